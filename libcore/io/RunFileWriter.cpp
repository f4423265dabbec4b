#include "io/RunFileWriter.hpp"

#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "io/AtomicOutput.hpp"
#include "io/Hdf5.hpp"
#include "io/JsonText.hpp"
#include "io/RunFileView.hpp"
#include "io/RunFileXdmf.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

namespace hvi::io {

namespace fs = std::filesystem;
using h5::checked;
using h5::Handle;

fs::path xdmfPathFor(const fs::path& runFile) {
    fs::path xmf = runFile;
    xmf.replace_extension(".xmf");
    return xmf;
}

namespace {

std::string snapshotName(int index) {
    char buffer[16];
    std::snprintf(buffer, sizeof(buffer), "%06d", index);
    return buffer;
}

/// The attributes every dataset carries (SWIFT's set, minus cosmology).
void writeFieldAttributes(hid_t dataset, const FieldSpec& spec) {
    h5::writeAttribute(dataset, "Units", std::string(spec.units));
    h5::writeAttribute(dataset, "Description", std::string(spec.description));
    h5::writeAttribute(dataset, "CgsConversionFactor", cgsConversionFactor(spec.dimensions));
    h5::writeAttribute(dataset, "U_L exponent", static_cast<double>(spec.dimensions.length));
    h5::writeAttribute(dataset, "U_M exponent", static_cast<double>(spec.dimensions.mass));
    h5::writeAttribute(dataset, "U_t exponent", static_cast<double>(spec.dimensions.time));
}

void writeTextDataset(hid_t file, const std::string& name, const std::string& text,
                      const std::string& description) {
    Handle dataset = h5::writeStringDataset(file, name, text);
    h5::writeAttribute(dataset.get(), "Units", "-");
    h5::writeAttribute(dataset.get(), "Description", description);
}

/// Throws unless every field of `fields` holds count * components values (optional fields may
/// be empty instead).
template <class Fields>
void checkSizes(const Fields& fields, std::size_t count, const std::string& kind) {
    forEachField(fields, [&](const FieldSpec& spec, const auto& values) {
        const std::size_t expected = count * static_cast<std::size_t>(spec.components);
        if (values.size() == expected || (values.empty() && spec.presence == Presence::Optional)) {
            return;
        }
        throw RuntimeFailure("run file: " + kind + " field " + std::string(spec.name) + " has " +
                             std::to_string(values.size()) + " values, expected " +
                             std::to_string(expected) + " (" + std::to_string(count) + " x " +
                             std::to_string(spec.components) + ")");
    });
}

/// Writes `count` items of the field `spec` describes, with its attributes.
Handle writeField(hid_t group, const FieldSpec& spec, std::size_t count, const void* data,
                  int gzipLevel) {
    std::vector<hsize_t> dims{static_cast<hsize_t>(count)};
    if (spec.components > 1) {
        dims.push_back(static_cast<hsize_t>(spec.components));
    }
    Handle dataset = h5::writeArrayDataset(group, std::string(spec.name), h5::fileTypeOf(spec.type),
                                           h5::memTypeOf(spec.type), dims, data, gzipLevel);
    writeFieldAttributes(dataset.get(), spec);
    return dataset;
}

/// Writes one dataset per present field of `fields` into `group`.
template <class Fields>
void writeRecord(hid_t group, const Fields& fields, std::size_t count, int gzipLevel) {
    forEachField(fields, [&](const FieldSpec& spec, const auto& values) {
        if (values.empty() && spec.presence == Presence::Optional) {
            return; // the scene has no such physics
        }
        writeField(group, spec, count, values.data(), gzipLevel);
    });
}

/// Writes a snapshot's view block (RunFileView.hpp) under `view`; returns what it holds.
ViewBlockLayout writeViewBlock(hid_t view, const ViewBlock& block, int gzipLevel) {
    ViewBlockLayout layout;
    layout.pointCount = block.pointCount;
    layout.cellCount = block.cellCount;
    Handle group = h5::createGroup(view, std::string(viewBlockName(block.kind)));
    h5::writeAttribute(group.get(), "PointCount", static_cast<long>(block.pointCount));
    h5::writeAttribute(group.get(), "CellCount", static_cast<long>(block.cellCount));
    if (block.cellCount == 0) {
        return layout; // HDF5 takes zero-sized datasets, XDMF readers do not: none written
    }
    writeField(group.get(), viewPointsSpec(), block.pointCount, block.points.data(), gzipLevel);
    writeField(group.get(), viewCellsSpec(block.kind), block.cellCount, block.cells.data(),
               gzipLevel);
    for (const ViewArray& array : block.arrays) {
        const bool cell = array.spec->centre == ViewCentre::Cell;
        const void* data = array.spec->field.type == ElementType::Float32
                               ? static_cast<const void*>(array.real.data())
                               : static_cast<const void*>(array.integer.data());
        Handle dataset = writeField(group.get(), array.spec->field,
                                    cell ? block.cellCount : block.pointCount, data, gzipLevel);
        h5::writeAttribute(dataset.get(), "Center", cell ? "Cell" : "Node");
        layout.arrays.emplace_back(array.spec->field.name);
    }
    return layout;
}

} // namespace

struct RunFileWriter::Impl {
    Impl(fs::path finalPath, RunFileWriterOptions opts)
        : output(std::move(finalPath)), options(opts) {}
    ~Impl() {
        h5::ErrorSilencer quiet;
        historyColumns.clear();
        file.reset();
        // `output` (declared first, destroyed last) then removes an uncommitted temporary.
    }

    AtomicOutput output;
    RunFileWriterOptions options;
    Handle file;
    std::vector<Handle> historyColumns; // table order
    hsize_t historyRowsWritten = 0;
    std::vector<HistoryRow> pendingHistory;
    std::vector<SnapshotLayout> layout;
    bool open = true;

    void writeCode(const nlohmann::json& provenance);
    void writeUnits();
    void createHistory();
    void writePendingHistory();
};

void RunFileWriter::Impl::writeCode(const nlohmann::json& provenance) {
    Handle code = h5::createGroup(file.get(), "Code");
    nlohmann::json attrs = nlohmann::json::object();
    if (provenance.is_object()) {
        for (const auto& [key, value] : provenance.items()) {
            if (value.is_primitive()) { // nested blocks (resolved input) live in /provenance
                attrs[key] = value;
            }
        }
    }
    const nlohmann::json defaults = {{"version", build::kVersion},
                                     {"git", build::kGitDescribe},
                                     {"compiler", build::kCompiler},
                                     {"build_type", build::kBuildType}};
    for (const auto& [key, value] : defaults.items()) {
        if (!attrs.contains(key)) {
            attrs[key] = value;
        }
    }
    attrs["hdf5_version"] = h5::libraryVersion(); // the library actually linked
    for (const auto& [key, value] : attrs.items()) {
        h5::writeJsonAttribute(code.get(), key, value);
    }
}

void RunFileWriter::Impl::writeUnits() {
    Handle units = h5::createGroup(file.get(), "Units");
    h5::writeAttribute(units.get(), "Description",
                       "Unit system of every dataset: mm, mg, us (so velocity km/s, density "
                       "g/cm3, pressure GPa, energy J, specific energy MJ/kg)");
    h5::writeAttribute(units.get(), "length", "mm");
    h5::writeAttribute(units.get(), "mass", "mg");
    h5::writeAttribute(units.get(), "time", "us");
    h5::writeAttribute(units.get(), "velocity", "km/s");
    h5::writeAttribute(units.get(), "density", "g/cm3");
    h5::writeAttribute(units.get(), "pressure", "GPa");
    h5::writeAttribute(units.get(), "energy", "J");
    h5::writeAttribute(units.get(), "specific_energy", "MJ/kg");
    // SWIFT's names, so tools that know SWIFT snapshots convert without being told.
    h5::writeAttribute(units.get(), "Unit length in cgs (U_L)", cgsConversionFactor(kLength));
    h5::writeAttribute(units.get(), "Unit mass in cgs (U_M)", cgsConversionFactor(kMass));
    h5::writeAttribute(units.get(), "Unit time in cgs (U_t)", cgsConversionFactor(kTime));
    h5::writeAttribute(units.get(), "Unit current in cgs (U_I)", 1.0);
    h5::writeAttribute(units.get(), "Unit temperature in cgs (U_T)", 1.0);
}

void RunFileWriter::Impl::createHistory() {
    Handle history = h5::createGroup(file.get(), "history");
    h5::writeAttribute(history.get(), "Description",
                       "Time history: one value per row appended by the solver, all columns "
                       "the same length");
    for (const auto& binding : FieldTable<HistoryRow>::entries) {
        const FieldSpec& spec = binding.spec;
        const std::string name(spec.name);
        const std::string what = "cannot create history column " + name;
        const hsize_t initial = 0;
        const hsize_t unlimited = H5S_UNLIMITED;
        // 1024 rows x 8 bytes per chunk: one chunk per ~1000 steps, negligible overhead.
        const hsize_t chunk = 1024;
        Handle space = checked(H5Screate_simple(1, &initial, &unlimited), what);
        Handle dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), what);
        checked(H5Pset_chunk(dcpl.get(), 1, &chunk), what);
        Handle dataset = checked(H5Dcreate2(history.get(), name.c_str(), h5::fileTypeOf(spec.type),
                                            space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                                 what);
        writeFieldAttributes(dataset.get(), spec);
        historyColumns.push_back(std::move(dataset));
    }
}

void RunFileWriter::Impl::writePendingHistory() {
    if (pendingHistory.empty()) {
        return;
    }
    const auto& entries = FieldTable<HistoryRow>::entries;
    const hsize_t added = pendingHistory.size();
    const hsize_t total = historyRowsWritten + added;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const hid_t dataset = historyColumns[i].get();
        const std::string what = "cannot write history column " + std::string(entries[i].spec.name);
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(pendingHistory.front().*member)>;
                std::vector<T> column;
                column.reserve(pendingHistory.size());
                for (const auto& row : pendingHistory) {
                    column.push_back(row.*member);
                }
                checked(H5Dset_extent(dataset, &total), what);
                Handle fileSpace = checked(H5Dget_space(dataset), what);
                checked(H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, &historyRowsWritten,
                                            nullptr, &added, nullptr),
                        what);
                Handle memSpace = checked(H5Screate_simple(1, &added, nullptr), what);
                checked(H5Dwrite(dataset, h5::memTypeOf(entries[i].spec.type), memSpace.get(),
                                 fileSpace.get(), H5P_DEFAULT, column.data()),
                        what);
            },
            entries[i].member);
    }
    historyRowsWritten = total;
    pendingHistory.clear();
}

RunFileWriter::RunFileWriter(fs::path finalPath, const std::string& sceneJson,
                             const std::string& materialsJson, const nlohmann::json& provenance,
                             RunFileWriterOptions options)
    : m_impl(std::make_unique<Impl>(std::move(finalPath), options)) {
    h5::ErrorSilencer quiet;
    Impl& im = *m_impl;
    if (im.output.isStdout()) {
        throw RuntimeFailure("a run file cannot be written to standard output; name a file");
    }
    if (xdmfPathFor(im.output.finalPath()) == im.output.finalPath()) {
        throw RuntimeFailure("run file " + im.output.finalPath().string() +
                             ": name it NAME.h5 (NAME.xmf is its XDMF sidecar)");
    }
    const std::string what = "cannot create run file " + im.output.tempPath().string();
    if (options.gzipLevel < 0 || options.gzipLevel > 9) {
        throw RuntimeFailure(what + ": gzip level must be 0-9, got " +
                             std::to_string(options.gzipLevel));
    }
    if (options.gzipLevel > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) {
        throw RuntimeFailure(what + ": this HDF5 library has no gzip (deflate) filter");
    }
    Handle fapl = checked(H5Pcreate(H5P_FILE_ACCESS), what);
    // Strong close: closing the file closes everything in it, so the rename never races an
    // object left open. File format of HDF5 1.8, exactly: attributes of any size (the
    // default, older format limits an object's attributes to 64 KiB) and indexed groups for
    // many snapshots, while every HDF5 reader since 2008 (h5py, ParaView, VisIt) reads it;
    // not 1.10's, whose chunk indexes 1.8-based tools cannot read.
    checked(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), what);
    checked(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), what);
    im.file = checked(
        H5Fcreate(im.output.tempPath().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), what);
    const hid_t file = im.file.get();
    h5::writeAttribute(file, "Format", "hvi-run");
    h5::writeAttribute(file, "FormatVersion", kRunFileFormatVersion);
    h5::writeAttribute(file, "Description",
                       "Run file of the hvi-run hydrocode (2D axisymmetric SPH + Lagrange FE). "
                       "See /Units for the unit system; every dataset has Units and "
                       "Description attributes.");
    writeTextDataset(file, "scene", sceneJson, "The scene the run computed (JSON text)");
    writeTextDataset(file, "materials", materialsJson,
                     "The material models and parameters the run used (JSON text)");
    writeTextDataset(file, "provenance",
                     provenance.is_null() ? std::string("{}") : jsonText(provenance, 2),
                     "Provenance of the run: tool, version, input file, resolved input "
                     "(JSON text)");
    im.writeCode(provenance);
    im.writeUnits();
    Handle snapshots = h5::createGroup(file, "snapshots");
    h5::writeAttribute(snapshots.get(), "Description",
                       "Snapshots NNNNNN in time order, numbered from 000000; particle fields "
                       "in each group, finite-element fields under Nodes/ and Elements/");
    im.createHistory();
}

RunFileWriter::~RunFileWriter() = default;

int RunFileWriter::writeSnapshot(double timeUs, long step, const ParticleFieldsView& particles,
                                 const FeFieldsView* fe) {
    if (!isOpen()) {
        throw RuntimeFailure("run file " + finalPath().string() +
                             ": writeSnapshot after finish/abandon");
    }
    Impl& im = *m_impl;
    SnapshotLayout snap;
    const std::size_t particleCount = particles.z.size();
    std::size_t nodeCount = 0;
    std::size_t elementCount = 0;
    checkSizes(particles, particleCount, "particle");
    if (fe != nullptr) {
        snap.hasFe = true;
        nodeCount = fe->nodes.z.size();
        elementCount = fe->elements.connectivity.size() / 4;
        checkSizes(fe->nodes, nodeCount, "node");
        checkSizes(fe->elements, elementCount, "element");
        for (std::size_t i = 0; i < fe->elements.connectivity.size(); ++i) {
            const std::int32_t node = fe->elements.connectivity[i];
            if (node < 0 || static_cast<std::size_t>(node) >= nodeCount) {
                throw RuntimeFailure("run file: element " + std::to_string(i / 4) +
                                     " refers to node " + std::to_string(node) +
                                     ", but there are " + std::to_string(nodeCount) + " nodes");
            }
        }
    }

    h5::ErrorSilencer quiet;
    const int index = static_cast<int>(im.layout.size());
    snap.group = "/snapshots/" + snapshotName(index);
    snap.timeUs = timeUs;
    snap.step = step;
    Handle group = h5::createGroup(im.file.get(), snap.group);
    h5::writeAttribute(group.get(), "Time", timeUs);
    h5::writeAttribute(group.get(), "Step", step);
    h5::writeAttribute(group.get(), "ParticleCount", static_cast<long>(particleCount));
    writeRecord(group.get(), particles, particleCount, im.options.gzipLevel);
    if (fe != nullptr) {
        h5::writeAttribute(group.get(), "NodeCount", static_cast<long>(nodeCount));
        h5::writeAttribute(group.get(), "ElementCount", static_cast<long>(elementCount));
        Handle nodes = h5::createGroup(group.get(), "Nodes");
        writeRecord(nodes.get(), fe->nodes, nodeCount, im.options.gzipLevel);
        Handle elements = h5::createGroup(group.get(), "Elements");
        writeRecord(elements.get(), fe->elements, elementCount, im.options.gzipLevel);
    }
    Handle view = h5::createGroup(group.get(), "View");
    h5::writeAttribute(view.get(), "Description",
                       "What the XDMF sidecar shows: the alive particles and elements only, "
                       "the nodes of alive elements, every field in ParaView's shapes");
    snap.particles = writeViewBlock(view.get(), particleView(particles), im.options.gzipLevel);
    if (fe != nullptr) {
        snap.mesh = writeViewBlock(view.get(), meshView(*fe), im.options.gzipLevel);
    }
    view.reset();
    group.reset();
    im.layout.push_back(std::move(snap));
    if (im.options.flushEachSnapshot) {
        checked(H5Fflush(im.file.get(), H5F_SCOPE_GLOBAL), "cannot flush run file");
    }
    return index;
}

void RunFileWriter::appendHistory(const HistoryRow& row) {
    if (!isOpen()) {
        throw RuntimeFailure("run file " + finalPath().string() +
                             ": appendHistory after finish/abandon");
    }
    m_impl->pendingHistory.push_back(row);
    if (m_impl->pendingHistory.size() >= kHistoryBatchRows) {
        h5::ErrorSilencer quiet;
        m_impl->writePendingHistory();
    }
}

void RunFileWriter::flush() {
    if (!isOpen()) {
        return;
    }
    h5::ErrorSilencer quiet;
    m_impl->writePendingHistory();
    checked(H5Fflush(m_impl->file.get(), H5F_SCOPE_GLOBAL), "cannot flush run file");
}

void RunFileWriter::finish(const nlohmann::json& runFacts) {
    nlohmann::json facts = runFacts.is_null() ? nlohmann::json::object() : runFacts;
    if (!facts.is_object()) {
        throw RuntimeFailure("run file: run facts must be a JSON object");
    }
    if (!facts.contains("status")) {
        facts["status"] = "complete";
    }
    close(std::move(facts));
}

void RunFileWriter::abandon(const nlohmann::json& runFacts) {
    nlohmann::json facts = runFacts.is_null() ? nlohmann::json::object() : runFacts;
    if (!facts.is_object()) {
        throw RuntimeFailure("run file: run facts must be a JSON object");
    }
    facts["status"] = "partial";
    if (!facts.contains("stop_reason")) {
        facts["stop_reason"] = "interrupted";
    }
    close(std::move(facts));
}

void RunFileWriter::close(nlohmann::json facts) {
    if (!isOpen()) {
        throw RuntimeFailure("run file " + finalPath().string() + ": already finished");
    }
    Impl& im = *m_impl;
    h5::ErrorSilencer quiet;
    im.writePendingHistory();
    if (!facts.contains("snapshot_count")) {
        facts["snapshot_count"] = im.layout.size();
    }
    if (!facts.contains("history_rows")) {
        facts["history_rows"] = im.historyRowsWritten;
    }
    {
        Handle run = h5::createGroup(im.file.get(), "run");
        for (const auto& [key, value] : facts.items()) {
            h5::writeJsonAttribute(run.get(), key, value);
        }
    }
    im.historyColumns.clear();
    if (!im.file.reset()) {
        h5::failWrite("cannot close run file " + im.output.tempPath().string());
    }
    im.open = false;

    // The sidecar is written to its own temporary first, so a failure here (no space) still
    // leaves neither file; then both are renamed.
    AtomicOutput xmf(xdmfPathFor(finalPath()));
    {
        std::ofstream out(xmf.tempPath(), std::ios::binary);
        out << runFileXdmf(finalPath().filename().string(), im.layout);
        out.flush();
        if (!out) {
            throw RuntimeFailure("cannot write " + xmf.tempPath().string());
        }
    }
    im.output.commit();
    xmf.commit();
}

const fs::path& RunFileWriter::finalPath() const {
    return m_impl->output.finalPath();
}
const fs::path& RunFileWriter::tempPath() const {
    return m_impl->output.tempPath();
}
int RunFileWriter::snapshotCount() const {
    return static_cast<int>(m_impl->layout.size());
}
bool RunFileWriter::isOpen() const {
    return m_impl->open;
}

} // namespace hvi::io
