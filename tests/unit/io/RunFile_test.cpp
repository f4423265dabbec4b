// The run file: a small synthetic run written and read back. Values are compared bitwise
// (this is I/O: nothing may change a bit), every dataset must carry Units and Description,
// the XDMF sidecar may only reference datasets that exist, and a failed or interrupted run
// leaves what docs/conventions.md promises.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "io/RunFileReader.hpp"
#include "io/RunFileView.hpp"
#include "io/RunFileWriter.hpp"
#include "io/RunFileXdmf.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

using namespace hvi::io;
using hvi::InputError;
using hvi::RuntimeFailure;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// ---- synthetic data -----------------------------------------------------------------------

/// A value for item i of field f in snapshot `seed`: distinct everywhere, with awkward doubles
/// (negative zero, subnormal, huge, non-terminating binary fractions) among them.
template <class T>
T syntheticValue(int seed, int field, std::size_t i) {
    if constexpr (std::is_same_v<T, double>) {
        switch (i % 7) {
        case 0:
            return -0.0;
        case 1:
            return std::numeric_limits<double>::denorm_min() * (seed + field + 1);
        case 2:
            return 1.0e300 * (seed + 1) / (field + 3);
        default:
            return (seed + 1.0) / 3.0 + field / 7.0 - static_cast<double>(i) / 11.0;
        }
    } else if constexpr (std::is_same_v<T, std::uint8_t>) {
        return static_cast<std::uint8_t>((i + static_cast<std::size_t>(seed)) % 2);
    } else {
        return static_cast<T>(seed * 1000 + field * 100 - static_cast<int>(i));
    }
}

/// Fills every field of a record (optional ones only if `withOptional`) with n items.
template <class Fields>
Fields synthetic(std::size_t n, int seed, bool withOptional) {
    Fields fields;
    int field = 0;
    forEachField(fields, [&](const FieldSpec& spec, auto& values) {
        using T = typename std::remove_cvref_t<decltype(values)>::value_type;
        ++field;
        if (spec.presence == Presence::Optional && !withOptional) {
            return;
        }
        values.resize(n * static_cast<std::size_t>(spec.components));
        for (std::size_t i = 0; i < values.size(); ++i) {
            values[i] = syntheticValue<T>(seed, field, i);
        }
    });
    return fields;
}

/// A 3 x 2 node grid with 2 quads; connectivity must point at real nodes.
FeFields syntheticMesh(int seed) {
    FeFields fe;
    fe.nodes = synthetic<FeNodeFieldsOf<VectorOf>>(6, seed, true);
    fe.elements = synthetic<FeElementFieldsOf<VectorOf>>(2, seed, true);
    fe.elements.connectivity = {0, 1, 4, 3, 1, 2, 5, 4};
    return fe;
}

std::vector<HistoryRow> syntheticHistory(std::size_t rows) {
    std::vector<HistoryRow> history(rows);
    for (std::size_t k = 0; k < rows; ++k) {
        int field = 0;
        forEachField(history[k], [&](const FieldSpec&, auto& value) {
            using T = std::remove_cvref_t<decltype(value)>;
            value = syntheticValue<T>(7, ++field, k);
        });
    }
    return history;
}

/// Every field's raw bytes by dataset name: equal maps mean bitwise-equal records.
template <class Fields>
std::map<std::string, std::string> bytesOf(const Fields& fields) {
    std::map<std::string, std::string> bytes;
    forEachField(fields, [&](const FieldSpec& spec, const auto& values) {
        bytes[std::string(spec.name)] = std::string(reinterpret_cast<const char*>(values.data()),
                                                    values.size() * sizeof(values[0]));
    });
    return bytes;
}

HistoryColumns columnsOf(const std::vector<HistoryRow>& rows) {
    HistoryColumns columns;
    const auto& rowTable = FieldTable<HistoryRow>::entries;
    const auto& columnTable = FieldTable<HistoryColumns>::entries;
    for (std::size_t i = 0; i < rowTable.size(); ++i) {
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(rows.front().*member)>;
                auto& column =
                    columns.*std::get<std::vector<T> HistoryColumns::*>(columnTable[i].member);
                for (const auto& row : rows) {
                    column.push_back(row.*member);
                }
            },
            rowTable[i].member);
    }
    return columns;
}

const std::string kScene = R"({"geometry": "axisymmetric", "bodies": [{"name": "bumper"}]})";
const std::string kMaterials = R"({"al6061t6": {"eos": "mie_gruneisen", "rho0_g_cm3": 2.703}})";

json provenance() {
    return {{"tool", "hvi-run"},
            {"threads", 2},
            {"input_file", "scene.json"},
            {"resolved_input", json::parse(kScene)}};
}

/// The standard synthetic run: snapshot 0 hydro only (no optional fields), snapshot 1 with
/// strength fields, snapshot 2 with more particles and a finite-element mesh.
struct SyntheticRun {
    std::vector<ParticleFields> particles{synthetic<ParticleFields>(5, 0, false),
                                          synthetic<ParticleFields>(5, 1, true),
                                          synthetic<ParticleFields>(7, 2, true)};
    FeFields mesh = syntheticMesh(2);
    std::vector<double> times{0.0, 0.25, 1.0 / 3.0};
    std::vector<long> steps{0, 40, 97};
    std::vector<HistoryRow> history = syntheticHistory(10);

    /// Writes the run to `path`; the writer is finished with `facts` unless `finishIt` is
    /// false (then the caller gets it back open).
    void writeTo(RunFileWriter& writer) const {
        for (std::size_t k = 0; k < 3; ++k) {
            const ParticleFieldsView view = viewOf(particles[k]);
            const FeFieldsView meshView = viewOf(mesh);
            EXPECT_EQ(writer.writeSnapshot(times[k], steps[k], view, k == 2 ? &meshView : nullptr),
                      static_cast<int>(k));
            // Half the history before the flush, half after: exercises extending the columns.
            for (std::size_t r = k * 4; r < std::min<std::size_t>(history.size(), k * 4 + 4); ++r) {
                writer.appendHistory(history[r]);
            }
            if (k == 1) {
                writer.flush();
            }
        }
    }
};

json runFacts() {
    return {{"wall_time_s", 12.5},
            {"threads", 2},
            {"stop_reason", "end_time"},
            {"steps", 97},
            {"converged", true},
            {"version", "0.1.0"},
            {"limits", {{"end_time_us", 1.0}}}};
}

fs::path freshPath(const std::string& name) {
    const fs::path path = hvi::test::tempPath(name);
    fs::remove(path);
    fs::remove(xdmfPathFor(path));
    return path;
}

fs::path writeStandardRun(const std::string& name) {
    const fs::path path = freshPath(name);
    SyntheticRun run;
    RunFileWriter writer(path, kScene, kMaterials, provenance());
    run.writeTo(writer);
    writer.finish(runFacts());
    return path;
}

/// Runs `fn` and returns the InputError it throws (fails the test if it throws nothing).
template <class Fn>
hvi::InputIssue inputIssueOf(Fn&& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        EXPECT_EQ(e.issues().size(), 1u);
        return e.issues().front();
    }
    ADD_FAILURE() << "no InputError thrown";
    return {};
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Every dataset path in an HDF5 file.
std::vector<std::string> datasetPaths(const fs::path& path) {
    std::vector<std::string> paths;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(file, 0);
    auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
        if (info->type == H5O_TYPE_DATASET) {
            static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
        }
        return 0;
    };
    H5Ovisit(file, H5_INDEX_NAME, H5_ITER_INC, visit, &paths);
    H5Fclose(file);
    return paths;
}

std::string stringAttribute(hid_t object, const char* name) {
    if (H5Aexists(object, name) <= 0) {
        return "";
    }
    const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attr);
    std::string value;
    if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) {
        char* text = nullptr;
        const hid_t mem = H5Tcopy(H5T_C_S1);
        H5Tset_size(mem, H5T_VARIABLE);
        H5Tset_cset(mem, H5T_CSET_UTF8);
        if (H5Aread(attr, mem, &text) >= 0 && text != nullptr) {
            value = text;
            H5free_memory(text);
        }
        H5Tclose(mem);
    }
    H5Tclose(type);
    H5Aclose(attr);
    return value;
}

void deleteObject(const fs::path& path, const std::string& object) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, object.c_str(), H5P_DEFAULT), 0) << object;
    H5Fclose(file);
}

} // namespace

// ---- round trip ---------------------------------------------------------------------------

TEST(RunFile, SnapshotsRoundTripBitwise) {
    const SyntheticRun run;
    const fs::path path = writeStandardRun("roundtrip.h5");
    ASSERT_TRUE(fs::exists(path));

    const RunFileReader reader(path);
    ASSERT_EQ(reader.snapshots().size(), 3u);
    for (int k = 0; k < 3; ++k) {
        const auto& info = reader.snapshots()[static_cast<std::size_t>(k)];
        EXPECT_EQ(info.index, k);
        EXPECT_EQ(info.group, "/snapshots/00000" + std::to_string(k));
        EXPECT_EQ(
            std::memcmp(&info.timeUs, &run.times[static_cast<std::size_t>(k)], sizeof(double)), 0);
        EXPECT_EQ(info.step, run.steps[static_cast<std::size_t>(k)]);
        EXPECT_EQ(info.particleCount, run.particles[static_cast<std::size_t>(k)].z.size());
        EXPECT_EQ(info.hasFe, k == 2);

        const Snapshot snap = reader.readSnapshot(k);
        EXPECT_EQ(bytesOf(snap.particles), bytesOf(run.particles[static_cast<std::size_t>(k)]))
            << "snapshot " << k;
        ASSERT_EQ(snap.fe.has_value(), k == 2);
    }
    const Snapshot last = reader.readSnapshot(2);
    EXPECT_EQ(bytesOf(last.fe->nodes), bytesOf(run.mesh.nodes));
    EXPECT_EQ(bytesOf(last.fe->elements), bytesOf(run.mesh.elements));
    EXPECT_EQ(last.info.nodeCount, 6u);
    EXPECT_EQ(last.info.elementCount, 2u);
    // Snapshot 0 had no strength: its optional fields are absent, and read back empty.
    const Snapshot first = reader.readSnapshot(0);
    EXPECT_TRUE(first.particles.stressDeviator.empty());
    EXPECT_TRUE(first.particles.damage.empty());
}

TEST(RunFile, DatasetNamesHoldTheMembersTheyName) {
    // The round trip above would pass with two fields swapped consistently; read two
    // datasets with plain HDF5 calls to pin the name -> member binding.
    const SyntheticRun run;
    const fs::path path = writeStandardRun("names.h5");
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<double> vz(5);
    const hid_t dataset = H5Dopen2(file, "/snapshots/000001/Vz", H5P_DEFAULT);
    ASSERT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, vz.data()), 0);
    H5Dclose(dataset);
    EXPECT_EQ(std::memcmp(vz.data(), run.particles[1].vz.data(), 5 * sizeof(double)), 0);
    std::vector<std::int32_t> quads(8);
    const hid_t conn = H5Dopen2(file, "/snapshots/000002/Elements/Connectivity", H5P_DEFAULT);
    ASSERT_GE(H5Dread(conn, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, quads.data()), 0);
    hsize_t dims[2] = {0, 0};
    const hid_t space = H5Dget_space(conn);
    EXPECT_EQ(H5Sget_simple_extent_dims(space, dims, nullptr), 2);
    EXPECT_EQ(dims[0], 2u);
    EXPECT_EQ(dims[1], 4u);
    H5Sclose(space);
    H5Dclose(conn);
    H5Fclose(file);
    EXPECT_EQ(quads, run.mesh.elements.connectivity);
}

TEST(RunFile, HistoryRoundTripsBitwise) {
    const SyntheticRun run;
    const fs::path path = writeStandardRun("history.h5");
    const RunFileReader reader(path);
    const HistoryColumns columns = reader.readHistory();
    EXPECT_EQ(columns.timeUs.size(), run.history.size());
    EXPECT_EQ(bytesOf(columns), bytesOf(columnsOf(run.history)));
}

TEST(RunFile, ManyHistoryRowsAreWrittenInBatches) {
    // More rows than one in-memory batch: the writer must spill and keep appending.
    const fs::path path = freshPath("long_history.h5");
    const auto rows = syntheticHistory(RunFileWriter::kHistoryBatchRows * 2 + 17);
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        for (const auto& row : rows) {
            writer.appendHistory(row);
        }
        writer.finish({});
    }
    const RunFileReader reader(path);
    EXPECT_EQ(bytesOf(reader.readHistory()), bytesOf(columnsOf(rows)));
    EXPECT_EQ(reader.runFacts()["history_rows"], rows.size());
}

TEST(RunFile, MetadataRoundTrips) {
    const fs::path path = writeStandardRun("metadata.h5");
    const RunFileReader reader(path);
    EXPECT_EQ(reader.sceneText(), kScene);
    EXPECT_EQ(reader.materialsText(), kMaterials);
    EXPECT_EQ(reader.scene()["bodies"][0]["name"], "bumper");
    EXPECT_EQ(reader.provenance(), provenance());

    const json facts = reader.runFacts();
    EXPECT_EQ(facts["status"], "complete");
    EXPECT_EQ(facts["wall_time_s"], 12.5);
    EXPECT_EQ(facts["threads"], 2);
    EXPECT_EQ(facts["stop_reason"], "end_time");
    EXPECT_EQ(facts["converged"], true);
    EXPECT_EQ(facts["snapshot_count"], 3);
    EXPECT_EQ(facts["history_rows"], 10);
    EXPECT_EQ(json::parse(facts["limits"].get<std::string>()), runFacts()["limits"]);

    const json code = reader.code();
    EXPECT_EQ(code["tool"], "hvi-run");
    EXPECT_EQ(code["threads"], 2);
    for (const char* key : {"version", "git", "compiler", "hdf5_version", "build_type"}) {
        ASSERT_TRUE(code.contains(key)) << key;
        EXPECT_FALSE(code[key].get<std::string>().empty()) << key;
    }
    EXPECT_FALSE(code.contains("resolved_input")); // nested blocks stay in /provenance

    const json units = reader.units();
    EXPECT_EQ(units["length"], "mm");
    EXPECT_EQ(units["mass"], "mg");
    EXPECT_EQ(units["time"], "us");
    EXPECT_EQ(units["Unit length in cgs (U_L)"], 0.1);
    EXPECT_EQ(units["Unit mass in cgs (U_M)"], 1e-3);
    EXPECT_EQ(units["Unit time in cgs (U_t)"], 1e-6);
}

TEST(RunFile, LargeRunFactsFit) {
    // The HDF5 1.6 object format caps an object's attributes at 64 KiB; the writer uses the
    // 1.8 format so a long stop reason or log excerpt cannot make finish() fail.
    const fs::path path = freshPath("large_facts.h5");
    const std::string longText(200000, 'x');
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        writer.finish({{"log_tail", longText}});
    }
    EXPECT_EQ(RunFileReader(path).runFacts()["log_tail"], longText);
}

TEST(RunFile, RewritingAReadSnapshotReproducesIt) {
    // The resume path: read a snapshot back and write it into a new run file.
    const fs::path first = writeStandardRun("resume_source.h5");
    const fs::path second = freshPath("resume_target.h5");
    const RunFileReader source(first);
    {
        RunFileWriter writer(second, source.sceneText(), source.materialsText(), provenance());
        for (const auto& info : source.snapshots()) {
            const Snapshot snap = source.readSnapshot(info.index);
            const FeFieldsView mesh = snap.fe ? viewOf(*snap.fe) : FeFieldsView{};
            writer.writeSnapshot(info.timeUs, info.step, viewOf(snap.particles),
                                 snap.fe ? &mesh : nullptr);
        }
        writer.finish({});
    }
    const RunFileReader copy(second);
    ASSERT_EQ(copy.snapshots().size(), 3u);
    for (int k = 0; k < 3; ++k) {
        const Snapshot a = source.readSnapshot(k);
        const Snapshot b = copy.readSnapshot(k);
        EXPECT_EQ(bytesOf(a.particles), bytesOf(b.particles));
        ASSERT_EQ(a.fe.has_value(), b.fe.has_value());
        if (a.fe) {
            EXPECT_EQ(bytesOf(a.fe->elements), bytesOf(b.fe->elements));
        }
    }
}

TEST(RunFile, CompressionIsOptionalAndLossless) {
    const SyntheticRun run;
    const fs::path path = freshPath("gzip.h5");
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance(), {.gzipLevel = 4});
        run.writeTo(writer);
        writer.finish({});
    }
    const RunFileReader reader(path);
    EXPECT_EQ(bytesOf(reader.readSnapshot(2).particles), bytesOf(run.particles[2]));
}

TEST(RunFile, MeshOnlySnapshotHasEmptyParticleFields) {
    const fs::path path = freshPath("mesh_only.h5");
    const FeFields mesh = syntheticMesh(3);
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        const FeFieldsView meshView = viewOf(mesh);
        writer.writeSnapshot(0.5, 3, ParticleFieldsView{}, &meshView);
        writer.finish({});
    }
    const RunFileReader reader(path);
    const Snapshot snap = reader.readSnapshot(0);
    EXPECT_EQ(snap.info.particleCount, 0u);
    EXPECT_TRUE(snap.particles.z.empty());
    ASSERT_TRUE(snap.fe.has_value());
    EXPECT_EQ(bytesOf(snap.fe->nodes), bytesOf(mesh.nodes));
    const std::string xmf = readText(xdmfPathFor(path));
    EXPECT_EQ(xmf.find("Particles"), std::string::npos) << "empty grid in the XDMF";
    EXPECT_NE(xmf.find("FiniteElements"), std::string::npos);
}

// ---- self-description ---------------------------------------------------------------------

TEST(RunFile, EveryDatasetHasUnitsAndDescription) {
    const fs::path path = writeStandardRun("attributes.h5");
    const auto paths = datasetPaths(path);
    EXPECT_GT(paths.size(), 40u); // 3 snapshots of particles, a mesh, 13 history columns
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    for (const auto& dataset : paths) {
        const hid_t id = H5Dopen2(file, dataset.c_str(), H5P_DEFAULT);
        ASSERT_GE(id, 0) << dataset;
        const std::string units = stringAttribute(id, "Units");
        EXPECT_FALSE(units.empty()) << dataset << " has no Units";
        EXPECT_FALSE(stringAttribute(id, "Description").empty())
            << dataset << " has no Description";
        // Table datasets carry exactly their table unit.
        const std::string name = dataset.substr(dataset.rfind('/') + 1);
        std::span<const FieldSpec> table = particleFieldSpecs();
        if (dataset.find("/View/") != std::string::npos) {
            const ViewBlockKind kind = dataset.find("/View/Particles/") != std::string::npos
                                           ? ViewBlockKind::Particles
                                           : ViewBlockKind::FiniteElements;
            const ViewArraySpec* view = findViewArraySpec(kind, name);
            const FieldSpec& spec = name == "Points"  ? viewPointsSpec()
                                    : name == "Cells" ? viewCellsSpec(kind)
                                    : view != nullptr ? view->field
                                                      : FieldSpec{};
            EXPECT_FALSE(spec.name.empty()) << dataset << " is not in the view table";
            EXPECT_EQ(units, spec.units) << dataset;
            H5Dclose(id);
            continue;
        }
        if (dataset.rfind("/history/", 0) == 0) {
            table = historyColumnSpecs();
        } else if (dataset.find("/Nodes/") != std::string::npos) {
            table = nodeFieldSpecs();
        } else if (dataset.find("/Elements/") != std::string::npos) {
            table = elementFieldSpecs();
        }
        if (dataset.rfind("/snapshots/", 0) == 0 || dataset.rfind("/history/", 0) == 0) {
            const FieldSpec* spec = findFieldSpec(table, name);
            ASSERT_NE(spec, nullptr) << dataset << " is not in the field table";
            EXPECT_EQ(units, spec->units) << dataset;
        }
        H5Dclose(id);
    }
    H5Fclose(file);
}

namespace {

struct XdmfReference {
    std::string dims;
    std::string numberType;
    std::string precision;
    std::string file;
    std::string path;
};

std::vector<XdmfReference> xdmfReferences(const std::string& xmf) {
    static const std::regex item(
        R"re(<DataItem Dimensions="([^"]+)" NumberType="([^"]+)" Precision="(\d)" Format="HDF">([^:<]+):([^<]+)</DataItem>)re");
    std::vector<XdmfReference> refs;
    for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), item); it != std::sregex_iterator();
         ++it) {
        refs.push_back({(*it)[1], (*it)[2], (*it)[3], (*it)[4], (*it)[5]});
    }
    return refs;
}

/// The element names of `xml` must nest properly (a minimal well-formedness check).
::testing::AssertionResult tagsBalance(const std::string& xml) {
    std::vector<std::string> open;
    static const std::regex tag(R"(<(/?)([A-Za-z_][A-Za-z0-9_]*)[^>]*?(/?)>)");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator();
         ++it) {
        const std::string name = (*it)[2];
        if ((*it)[1] == "/") {
            if (open.empty() || open.back() != name) {
                return ::testing::AssertionFailure() << "unexpected </" << name << ">";
            }
            open.pop_back();
        } else if ((*it)[3] != "/") {
            open.push_back(name);
        }
    }
    if (!open.empty()) {
        return ::testing::AssertionFailure() << "<" << open.back() << "> not closed";
    }
    return ::testing::AssertionSuccess();
}

} // namespace

TEST(RunFile, XdmfReferencesOnlyExistingDatasets) {
    const SyntheticRun run;
    const fs::path path = writeStandardRun("xdmf.h5");
    const fs::path xmfPath = path.parent_path() / "xdmf.xmf";
    ASSERT_EQ(xdmfPathFor(path), xmfPath);
    ASSERT_TRUE(fs::exists(xmfPath));
    const std::string xmf = readText(xmfPath);
    EXPECT_TRUE(tagsBalance(xmf));
    EXPECT_NE(xmf.find("CollectionType=\"Temporal\""), std::string::npos);
    EXPECT_NE(xmf.find("GeometryType=\"XYZ\""), std::string::npos);
    EXPECT_EQ(xmf.find("GeometryType=\"X_Y\""), std::string::npos) << "Xdmf3 readers crash on it";
    EXPECT_NE(xmf.find("TopologyType=\"Polyvertex\""), std::string::npos);
    EXPECT_NE(xmf.find("TopologyType=\"Quadrilateral\""), std::string::npos);

    const auto refs = xdmfReferences(xmf);
    // Per block and time: Cells and Points, then every array of the view. The particles of
    // snapshot 0 have no strength fields (8 arrays), those of 1 and 2 have them (14: Damage,
    // PlasticStrain and four deviator components more); the mesh of snapshot 2 has 2 node
    // arrays and 8 element arrays.
    EXPECT_EQ(refs.size(), (2u + 8u) + (2u + 14u) + (2u + 14u) + (2u + 2u + 8u));
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    for (const auto& ref : refs) {
        EXPECT_EQ(ref.file, "xdmf.h5") << "the sidecar must name the file beside it";
        ASSERT_GT(H5Lexists(file, ref.path.c_str(), H5P_DEFAULT), 0) << ref.path;
        const hid_t dataset = H5Dopen2(file, ref.path.c_str(), H5P_DEFAULT);
        ASSERT_GE(dataset, 0) << ref.path;
        const hid_t space = H5Dget_space(dataset);
        hsize_t dims[2] = {0, 0};
        const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
        std::string shape = std::to_string(dims[0]);
        if (rank == 2) {
            shape += " " + std::to_string(dims[1]);
        }
        EXPECT_EQ(ref.dims, shape) << ref.path;
        const hid_t type = H5Dget_type(dataset);
        EXPECT_EQ(std::stoul(ref.precision), H5Tget_size(type)) << ref.path;
        EXPECT_EQ(ref.numberType == "Float", H5Tget_class(type) == H5T_FLOAT) << ref.path;
        H5Tclose(type);
        H5Sclose(space);
        H5Dclose(dataset);
    }
    H5Fclose(file);
    // One time entry per snapshot, with its time.
    static const std::regex timeTag(R"re(<Time Type="Single" Value="([^"]+)"/>)re");
    std::vector<double> times;
    for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), timeTag);
         it != std::sregex_iterator(); ++it) {
        times.push_back(std::stod((*it)[1]));
    }
    // The particle block at every snapshot, then the mesh block at the one with a mesh.
    std::vector<double> expected = run.times;
    expected.push_back(run.times[2]);
    EXPECT_EQ(times, expected);
}

TEST(RunFile, ReaderRebuildsTheSameXdmf) {
    const fs::path path = writeStandardRun("relayout.h5");
    const RunFileReader reader(path);
    EXPECT_EQ(runFileXdmf(path.filename().string(), reader.layout()), readText(xdmfPathFor(path)));
}

// ---- atomicity, interruption, recovery ----------------------------------------------------

TEST(RunFile, WriterDestroyedWithoutFinishLeavesNoFile) {
    const SyntheticRun run;
    const fs::path path = freshPath("unfinished.h5");
    fs::path temp;
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        temp = writer.tempPath();
        run.writeTo(writer);
        EXPECT_TRUE(fs::exists(temp));
        EXPECT_FALSE(fs::exists(path));
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_FALSE(fs::exists(xdmfPathFor(path)));
}

TEST(RunFile, InconsistentViewIsRejectedBeforeWriting) {
    const fs::path path = freshPath("bad_view.h5");
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        ParticleFields fields = synthetic<ParticleFields>(4, 0, true);
        fields.density.pop_back();
        try {
            writer.writeSnapshot(0.0, 0, viewOf(fields));
            ADD_FAILURE() << "no RuntimeFailure";
        } catch (const RuntimeFailure& e) {
            EXPECT_NE(std::string(e.what()).find("Density has 3 values, expected 4"),
                      std::string::npos)
                << e.what();
        }
        EXPECT_EQ(writer.snapshotCount(), 0);

        ParticleFields missing = synthetic<ParticleFields>(4, 0, true);
        missing.alive.clear(); // required: may not be left out
        EXPECT_THROW(writer.writeSnapshot(0.0, 0, viewOf(missing)), RuntimeFailure);

        const ParticleFields good = synthetic<ParticleFields>(4, 0, true);
        FeFields mesh = syntheticMesh(0);
        mesh.elements.connectivity[5] = 6; // only nodes 0..5 exist
        const FeFieldsView meshView = viewOf(mesh);
        EXPECT_THROW(writer.writeSnapshot(0.0, 0, viewOf(good), &meshView), RuntimeFailure);
        EXPECT_EQ(writer.snapshotCount(), 0);
    } // the run "failed": nothing may remain
    EXPECT_FALSE(fs::exists(path));
}

TEST(RunFile, AbandonKeepsAPartialFile) {
    const SyntheticRun run;
    const fs::path path = freshPath("interrupted.h5");
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        run.writeTo(writer);
        writer.abandon({{"wall_time_s", 3.0}});
        EXPECT_FALSE(writer.isOpen());
        EXPECT_FALSE(fs::exists(writer.tempPath()));
        EXPECT_THROW(writer.finish({}), RuntimeFailure);
    }
    ASSERT_TRUE(fs::exists(path));
    EXPECT_TRUE(fs::exists(xdmfPathFor(path)));
    const RunFileReader reader(path);
    const json facts = reader.runFacts();
    EXPECT_EQ(facts["status"], "partial");
    EXPECT_EQ(facts["stop_reason"], "interrupted");
    EXPECT_EQ(facts["wall_time_s"], 3.0);
    EXPECT_EQ(reader.snapshots().size(), 3u);
    EXPECT_EQ(reader.readHistory().timeUs.size(), run.history.size());
}

TEST(RunFile, FlushedTemporaryOfAKilledRunIsReadable) {
    // SIGKILL leaves NAME.tmp.PID as of the last flush: copy it while the writer is still
    // open (the kill), then let the writer clean up as a failed run would.
    const SyntheticRun run;
    const fs::path path = freshPath("killed.h5");
    const fs::path rescued = freshPath("killed_rescued.h5");
    {
        RunFileWriter writer(path, kScene, kMaterials, provenance());
        run.writeTo(writer);
        writer.flush();
        fs::copy_file(writer.tempPath(), rescued, fs::copy_options::overwrite_existing);
    }
    const RunFileReader reader(rescued);
    EXPECT_EQ(reader.snapshots().size(), 3u);
    EXPECT_EQ(bytesOf(reader.readSnapshot(1).particles), bytesOf(run.particles[1]));
    EXPECT_EQ(bytesOf(reader.readHistory()), bytesOf(columnsOf(run.history)));
    EXPECT_FALSE(reader.hasRunFacts());
    const auto issue = inputIssueOf([&] { (void)reader.runFacts(); });
    EXPECT_EQ(issue.pointer, "/run");
    EXPECT_EQ(issue.problem, "missing");
}

// ---- bad files ----------------------------------------------------------------------------

TEST(RunFile, DeletedDatasetIsNamedByItsPath) {
    const fs::path path = writeStandardRun("damaged.h5");
    deleteObject(path, "/snapshots/000001/Density");
    deleteObject(path, "/history/Dt");
    const RunFileReader reader(path); // opening lists snapshots only
    EXPECT_NO_THROW((void)reader.readSnapshot(0));
    const auto issue = inputIssueOf([&] { (void)reader.readSnapshot(1); });
    EXPECT_EQ(issue.file, path.string());
    EXPECT_EQ(issue.pointer, "/snapshots/000001/Density");
    EXPECT_EQ(issue.problem, "missing");
    EXPECT_NE(issue.expected.find("g/cm3"), std::string::npos) << issue.format();
    EXPECT_EQ(inputIssueOf([&] { (void)reader.readHistory(); }).pointer, "/history/Dt");
    EXPECT_EQ(inputIssueOf([&] { (void)reader.readSnapshot(7); }).pointer, "/snapshots/000007");
}

TEST(RunFile, DeletedOptionalFieldReadsAsEmpty) {
    const fs::path path = writeStandardRun("no_damage.h5");
    deleteObject(path, "/snapshots/000001/Damage");
    const Snapshot snap = RunFileReader(path).readSnapshot(1);
    EXPECT_TRUE(snap.particles.damage.empty());
    EXPECT_EQ(snap.particles.plasticStrain.size(), 5u);
}

TEST(RunFile, DeletedMeshFieldIsNamed) {
    const fs::path path = writeStandardRun("no_connectivity.h5");
    deleteObject(path, "/snapshots/000002/Elements/Connectivity");
    EXPECT_EQ(inputIssueOf([&] { (void)RunFileReader(path).readSnapshot(2); }).pointer,
              "/snapshots/000002/Elements/Connectivity");
}

TEST(RunFile, NonHdf5FileIsAnInputError) {
    const fs::path path = hvi::test::tempPath("not_hdf5.h5");
    std::ofstream(path) << "{\"this\": \"is JSON, not HDF5\"}\n";
    const auto issue = inputIssueOf([&] { RunFileReader reader(path); });
    EXPECT_EQ(issue.file, path.string());
    EXPECT_EQ(issue.pointer, "/");
    EXPECT_EQ(issue.problem, "not an HDF5 file");

    const auto missing = inputIssueOf([&] { RunFileReader reader(freshPath("absent.h5")); });
    EXPECT_EQ(missing.problem, "no such file");
}

TEST(RunFile, TruncatedFileIsAnInputError) {
    const fs::path path = writeStandardRun("truncated.h5");
    fs::resize_file(path, fs::file_size(path) / 2);
    const auto issue = inputIssueOf([&] {
        RunFileReader reader(path);
        for (const auto& info : reader.snapshots()) {
            (void)reader.readSnapshot(info.index);
        }
    });
    EXPECT_EQ(issue.file, path.string());
    EXPECT_FALSE(issue.pointer.empty());
    EXPECT_NE(issue.problem.find("truncated"), std::string::npos) << issue.format();
}

TEST(RunFile, OtherHdf5FileIsNotARunFile) {
    const fs::path path = freshPath("other.h5");
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    H5Fclose(file);
    const auto issue = inputIssueOf([&] { RunFileReader reader(path); });
    EXPECT_EQ(issue.pointer, "/@Format");
    EXPECT_EQ(issue.problem, "missing");
}

TEST(RunFile, RunFileMayNotBeNamedLikeItsSidecar) {
    EXPECT_THROW(RunFileWriter(freshPath("run.xmf"), kScene, kMaterials, provenance()),
                 RuntimeFailure);
}

TEST(RunFile, MissingDirectoryIsARuntimeFailure) {
    EXPECT_THROW(
        RunFileWriter(hvi::test::tempPath("no/such/dir/run.h5"), kScene, kMaterials, provenance()),
        RuntimeFailure);
}
