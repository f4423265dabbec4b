#include "io/RunFileReader.hpp"

#include "io/Hdf5.hpp"
#include "io/JsonText.hpp"
#include "io/RunFileView.hpp"
#include "io/RunFileWriter.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace hvi::io {

namespace fs = std::filesystem;
using h5::Handle;

namespace {

constexpr const char* kExpectRunFile = "an HDF5 run file written by hvi-run";

bool isSnapshotName(const std::string& name) {
    return name.size() == 6 && std::all_of(name.begin(), name.end(), [](char c) {
               return std::isdigit(static_cast<unsigned char>(c)) != 0;
           });
}

std::string shapeText(const std::vector<hsize_t>& dims) {
    std::string text = "(";
    for (std::size_t i = 0; i < dims.size(); ++i) {
        text += (i > 0 ? ", " : "") + std::to_string(dims[i]);
    }
    return text + ")";
}

} // namespace

struct RunFileReader::Impl {
    fs::path path;
    std::string label; // the file as the user named it, for error lines
    Handle file;
    std::vector<SnapshotInfo> snapshots;

    /// A required attribute of the object at `objectPath`.
    nlohmann::json requiredAttribute(hid_t object, const std::string& objectPath,
                                     const std::string& name, const std::string& expected) const {
        auto value = h5::readAttribute(object, name, label, objectPath);
        if (!value) {
            throw InputError(label, objectPath + "@" + name, "missing", expected);
        }
        return *value;
    }

    template <class Fields>
    Fields readRecord(const std::string& group, std::size_t count, const std::string& kind) const {
        Fields out;
        forEachField(out, [&](const FieldSpec& spec, auto& values) {
            const std::string where = group + "/" + std::string(spec.name);
            const std::string expected =
                kind + " field, " + std::to_string(count) +
                (spec.components > 1 ? " x " + std::to_string(spec.components) : std::string()) +
                " values [" + std::string(spec.units) + "]";
            if (!h5::pathExists(file.get(), where)) {
                if (spec.presence == Presence::Optional) {
                    return; // the run had no such physics
                }
                throw InputError(label, where, "missing", expected);
            }
            Handle dataset = h5::openObject(file.get(), label, where, expected);
            if (H5Iget_type(dataset.get()) != H5I_DATASET) {
                throw InputError(label, where, "is not a dataset", expected);
            }
            std::vector<hsize_t> want{static_cast<hsize_t>(count)};
            if (spec.components > 1) {
                want.push_back(static_cast<hsize_t>(spec.components));
            }
            const auto dims = h5::datasetDims(dataset.get());
            if (dims != want) {
                throw InputError(label, where, "has shape " + shapeText(dims), expected);
            }
            values.resize(count * static_cast<std::size_t>(spec.components));
            h5::readArrayDataset(dataset.get(), h5::memTypeOf(spec.type), values.data(), label,
                                 where);
        });
        return out;
    }

    /// What a snapshot's view block holds; empty for a file of format 1, which has no view.
    ViewBlockLayout viewBlockLayout(const std::string& snapshot, ViewBlockKind kind) const {
        ViewBlockLayout layout;
        const std::string group = snapshot + "/View/" + std::string(viewBlockName(kind));
        if (!h5::pathExists(file.get(), group)) {
            return layout;
        }
        Handle handle = h5::openObject(file.get(), label, group, "a view block");
        for (const char* name : {"PointCount", "CellCount"}) {
            const auto value = h5::readAttribute(handle.get(), name, label, group);
            if (!value || !value->is_number_integer() || value->get<long>() < 0) {
                throw InputError(label, group + "/@" + name,
                                 value ? "is " + jsonText(*value) : std::string("missing"),
                                 "a count >= 0");
            }
            (std::string(name) == "PointCount" ? layout.pointCount : layout.cellCount) =
                value->get<std::size_t>();
        }
        for (const auto& spec : viewArraySpecs(kind)) {
            if (h5::pathExists(file.get(), group + "/" + std::string(spec.field.name))) {
                layout.arrays.emplace_back(spec.field.name);
            }
        }
        return layout;
    }
};

RunFileReader::RunFileReader(fs::path path) : m_impl(std::make_unique<Impl>()) {
    h5::ErrorSilencer quiet;
    Impl& im = *m_impl;
    im.path = std::move(path);
    im.label = im.path.string();
    std::error_code ec;
    if (!fs::is_regular_file(im.path, ec)) {
        throw InputError(im.label, "", fs::exists(im.path, ec) ? "is not a file" : "no such file",
                         kExpectRunFile);
    }
    if (H5Fis_hdf5(im.path.c_str()) <= 0) {
        throw InputError(im.label, "/", "not an HDF5 file", kExpectRunFile);
    }
    im.file = Handle(H5Fopen(im.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!im.file.valid()) {
        const std::string detail = h5::lastErrorMessage();
        throw InputError(im.label, "/",
                         "cannot be opened (truncated or damaged?)" +
                             (detail.empty() ? std::string() : ": " + detail),
                         kExpectRunFile);
    }
    const hid_t file = im.file.get();
    const auto format = h5::readAttribute(file, "Format", im.label, "/");
    if (!format || *format != "hvi-run") {
        throw InputError(im.label, "/@Format",
                         format ? "is " + jsonText(*format) : std::string("missing"),
                         "\"hvi-run\": " + std::string(kExpectRunFile));
    }
    const auto version = im.requiredAttribute(file, "/", "FormatVersion", "an integer");
    if (!version.is_number_integer() || version.get<long>() > kRunFileFormatVersion) {
        throw InputError(im.label, "/@FormatVersion", "is " + jsonText(version),
                         "a format version up to " + std::to_string(kRunFileFormatVersion) +
                             " (a newer hvi-run wrote this file)");
    }

    Handle snapshots = h5::openObject(file, im.label, "/snapshots", "the snapshots group");
    for (const auto& name : h5::childNames(snapshots.get(), im.label, "/snapshots")) {
        const std::string group = "/snapshots/" + name;
        if (!isSnapshotName(name)) {
            throw InputError(im.label, group, "unexpected object in /snapshots",
                             "snapshot groups named NNNNNN");
        }
        Handle g = h5::openObject(file, im.label, group, "a snapshot group");
        SnapshotInfo info;
        info.index = std::stoi(name);
        info.group = group;
        const auto time = im.requiredAttribute(g.get(), group, "Time", "snapshot time [us]");
        const auto step = im.requiredAttribute(g.get(), group, "Step", "step number");
        const auto count = im.requiredAttribute(g.get(), group, "ParticleCount", "an integer");
        if (!time.is_number() || !step.is_number_integer() || !count.is_number_integer() ||
            count.get<long>() < 0) {
            throw InputError(im.label, group, "has malformed Time/Step/ParticleCount attributes",
                             "Time [us] (number), Step and ParticleCount (integers >= 0)");
        }
        info.timeUs = time.get<double>();
        info.step = step.get<long>();
        info.particleCount = count.get<std::size_t>();
        info.hasFe = h5::pathExists(file, group + "/Elements");
        if (info.hasFe) {
            const auto nodes = im.requiredAttribute(g.get(), group, "NodeCount", "an integer");
            const auto elements =
                im.requiredAttribute(g.get(), group, "ElementCount", "an integer");
            if (!nodes.is_number_integer() || !elements.is_number_integer() ||
                nodes.get<long>() < 0 || elements.get<long>() < 0) {
                throw InputError(im.label, group, "has malformed NodeCount/ElementCount",
                                 "integers >= 0");
            }
            info.nodeCount = nodes.get<std::size_t>();
            info.elementCount = elements.get<std::size_t>();
        }
        im.snapshots.push_back(std::move(info));
    }
}

RunFileReader::~RunFileReader() {
    if (m_impl) {
        h5::ErrorSilencer quiet;
        m_impl->file.reset();
    }
}

RunFileReader::RunFileReader(RunFileReader&&) noexcept = default;
RunFileReader& RunFileReader::operator=(RunFileReader&&) noexcept = default;

const fs::path& RunFileReader::path() const {
    return m_impl->path;
}

const std::vector<SnapshotInfo>& RunFileReader::snapshots() const {
    return m_impl->snapshots;
}

Snapshot RunFileReader::readSnapshot(int index) const {
    h5::ErrorSilencer quiet;
    const Impl& im = *m_impl;
    auto it = std::find_if(im.snapshots.begin(), im.snapshots.end(),
                           [&](const SnapshotInfo& s) { return s.index == index; });
    if (it == im.snapshots.end()) {
        char name[16];
        std::snprintf(name, sizeof(name), "%06d", index);
        throw InputError(im.label, "/snapshots/" + std::string(name), "missing",
                         "one of the file's " + std::to_string(im.snapshots.size()) + " snapshots");
    }
    Snapshot snap;
    snap.info = *it;
    snap.particles = im.readRecord<ParticleFields>(it->group, it->particleCount, "particle");
    if (it->hasFe) {
        FeFields fe;
        fe.nodes =
            im.readRecord<FeNodeFieldsOf<VectorOf>>(it->group + "/Nodes", it->nodeCount, "node");
        fe.elements = im.readRecord<FeElementFieldsOf<VectorOf>>(it->group + "/Elements",
                                                                 it->elementCount, "element");
        snap.fe = std::move(fe);
    }
    return snap;
}

HistoryColumns RunFileReader::readHistory() const {
    h5::ErrorSilencer quiet;
    const Impl& im = *m_impl;
    HistoryColumns columns;
    std::optional<std::size_t> rows;
    std::string firstPath;
    forEachField(columns, [&](const FieldSpec& spec, auto& values) {
        const std::string path = "/history/" + std::string(spec.name);
        const std::string expected = "history column [" + std::string(spec.units) + "]";
        Handle dataset = h5::openObject(im.file.get(), im.label, path, expected);
        const auto dims = h5::datasetDims(dataset.get());
        if (dims.size() != 1) {
            throw InputError(im.label, path, "has shape " + shapeText(dims), "a 1-D " + expected);
        }
        const auto n = static_cast<std::size_t>(dims[0]);
        if (rows && *rows != n) {
            throw InputError(im.label, path, "has " + std::to_string(n) + " rows",
                             std::to_string(*rows) + " rows, as " + firstPath);
        }
        if (!rows) {
            rows = n;
            firstPath = path;
        }
        values.resize(n);
        h5::readArrayDataset(dataset.get(), h5::memTypeOf(spec.type), values.data(), im.label,
                             path);
    });
    return columns;
}

bool RunFileReader::hasRunFacts() const {
    h5::ErrorSilencer quiet;
    return h5::pathExists(m_impl->file.get(), "/run");
}

nlohmann::json RunFileReader::runFacts() const {
    h5::ErrorSilencer quiet;
    const Impl& im = *m_impl;
    Handle run = h5::openObject(im.file.get(), im.label, "/run",
                                "the run facts written when a run ends (a file without them "
                                "is from a run that was killed or is still running)");
    return h5::readAllAttributes(run.get(), im.label, "/run");
}

namespace {

nlohmann::json parseStored(const std::string& text, const std::string& label,
                           const std::string& path) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(label, path, "is not valid JSON (byte " + std::to_string(e.byte) + ")",
                         "JSON text");
    }
}

} // namespace

std::string RunFileReader::sceneText() const {
    h5::ErrorSilencer quiet;
    return h5::readStringDataset(m_impl->file.get(), m_impl->label, "/scene");
}

nlohmann::json RunFileReader::scene() const {
    return parseStored(sceneText(), m_impl->label, "/scene");
}

std::string RunFileReader::materialsText() const {
    h5::ErrorSilencer quiet;
    return h5::readStringDataset(m_impl->file.get(), m_impl->label, "/materials");
}

nlohmann::json RunFileReader::materials() const {
    return parseStored(materialsText(), m_impl->label, "/materials");
}

nlohmann::json RunFileReader::provenance() const {
    h5::ErrorSilencer quiet;
    return parseStored(h5::readStringDataset(m_impl->file.get(), m_impl->label, "/provenance"),
                       m_impl->label, "/provenance");
}

nlohmann::json RunFileReader::code() const {
    h5::ErrorSilencer quiet;
    Handle code = h5::openObject(m_impl->file.get(), m_impl->label, "/Code", "the /Code group");
    return h5::readAllAttributes(code.get(), m_impl->label, "/Code");
}

nlohmann::json RunFileReader::units() const {
    h5::ErrorSilencer quiet;
    Handle units = h5::openObject(m_impl->file.get(), m_impl->label, "/Units", "the /Units group");
    return h5::readAllAttributes(units.get(), m_impl->label, "/Units");
}

std::vector<SnapshotLayout> RunFileReader::layout() const {
    h5::ErrorSilencer quiet;
    std::vector<SnapshotLayout> result;
    for (const auto& info : m_impl->snapshots) {
        SnapshotLayout snap;
        snap.group = info.group;
        snap.timeUs = info.timeUs;
        snap.step = info.step;
        snap.hasFe = info.hasFe;
        snap.particles = m_impl->viewBlockLayout(info.group, ViewBlockKind::Particles);
        if (info.hasFe) {
            snap.mesh = m_impl->viewBlockLayout(info.group, ViewBlockKind::FiniteElements);
        }
        result.push_back(std::move(snap));
    }
    return result;
}

} // namespace hvi::io
