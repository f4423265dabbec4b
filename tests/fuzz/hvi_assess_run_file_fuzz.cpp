// hvi-assess's input: a run file. Random bytes would mostly test the HDF5 library's own parser
// (a third party's code, outside the toolkit's reach), so this target is structure-aware: it
// makes one real run file at start-up (a small scene with an SPH projectile, an FE bumper and
// an SPH rear wall, run in-process by hvi-run), and each input is a program of edits on a copy
// of it: objects dropped, datasets cut short or given NaN, infinities, negative and huge
// values, string datasets (the stored scene and material JSON) and attributes replaced by
// other text or numbers, a snapshot group removed. hvi-assess then reads the edited file and
// judges it (the verdict, one field picture), as it would a damaged file in a sweep.
#include "FuzzSupport.hpp"
#include "app/HviAssessTool.hpp"
#include "app/HviRunTool.hpp"
#include "io/Hdf5.hpp"

#include <fuzzer/FuzzedDataProvider.h>
#include <hdf5.h>
#include <limits>

namespace {

using hvi::io::h5::Handle;

const char* const kScene = R"({
  "id": "fuzz-run-file", "geometry": "axisymmetric",
  "sph": {"particle_spacing_mm": 0.2},
  "run": {"end_time_us": 1.2},
  "output": {"snapshot_every_us": 0.4, "history_every_steps": 5},
  "domain": {"z_min_mm": -3, "z_max_mm": 6, "radius_mm": 4},
  "bodies": [
    {"name": "projectile", "role": "projectile", "material": "Al6061-T6",
     "shape": {"type": "sphere", "center_z_mm": -0.7, "radius_mm": 0.6},
     "velocity": {"z_km_s": 6.0}},
    {"name": "bumper", "role": "bumper", "material": "Al6061-T6", "discretization": "fe",
     "shape": {"type": "plate", "z_front_mm": 0.0, "thickness_mm": 0.4, "outer_radius_mm": 3.0}},
    {"name": "wall", "role": "rear_wall", "material": "Al6061-T6",
     "shape": {"type": "plate", "z_front_mm": 3.0, "thickness_mm": 0.8, "outer_radius_mm": 3.0}}
  ]
})";

struct Dataset {
    std::string path;
    bool isString = false;
};

struct Attribute {
    std::string object, name;
};

struct Template {
    std::string file;
    std::vector<std::string> groups;
    std::vector<Dataset> datasets;
    std::vector<Attribute> attributes;
};

herr_t collectAttribute(hid_t, const char* name, const H5A_info_t*, void* data) {
    auto* pair = static_cast<std::pair<Template*, std::string>*>(data);
    pair->first->attributes.push_back({pair->second, name});
    return 0;
}

herr_t collectObject(hid_t root, const char* name, const H5O_info_t* info, void* data) {
    auto* t = static_cast<Template*>(data);
    const std::string path = std::string(name) == "." ? "/" : "/" + std::string(name);
    if (info->type == H5O_TYPE_GROUP && path != "/") {
        t->groups.push_back(path);
    } else if (info->type == H5O_TYPE_DATASET) {
        Handle d(H5Dopen2(root, path.c_str(), H5P_DEFAULT));
        Handle type(H5Dget_type(d.get()));
        t->datasets.push_back({path, H5Tget_class(type.get()) == H5T_STRING});
    }
    Handle object(H5Oopen(root, path.c_str(), H5P_DEFAULT));
    std::pair<Template*, std::string> pair{t, path};
    H5Aiterate2(object.get(), H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collectAttribute, &pair);
    return 0;
}

/// The real run file every input edits, made once.
const Template& runFileTemplate() {
    static const Template t = [] {
        using namespace hvi::fuzz;
        Template out;
        const auto scene = scratch() / "template-scene.json";
        std::ofstream(scene) << kScene;
        out.file = (scratch() / "template.h5").string();
        hvi::app::HviRunTool run;
        std::string said;
        if (runCaptured(run, {"hvi-run", scene.string(), "-o", out.file, "-q", "--threads", "1"},
                        &said) != 0) {
            std::fprintf(stderr, "fuzz: the template run failed: %s\n", said.c_str());
            std::abort();
        }
        Handle file(H5Fopen(out.file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
        H5Ovisit2(file.get(), H5_INDEX_NAME, H5_ITER_NATIVE, collectObject, &out, H5O_INFO_BASIC);
        return out;
    }();
    return t;
}

double specialValue(FuzzedDataProvider& in) {
    constexpr double values[] = {std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity(),
                                 -1.0,
                                 0.0,
                                 1e300,
                                 -1e300,
                                 1e9,
                                 2147483648.0,
                                 0.5};
    return values[in.ConsumeIntegralInRange<std::size_t>(0, std::size(values) - 1)];
}

/// Replaces the numeric dataset at `path` by its values cut to `keep` rows along the first
/// dimension, with `poison` values set to special ones; the file type stays the same.
void rewriteNumbers(hid_t file, const std::string& path, FuzzedDataProvider& in, bool cut) {
    Handle d(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
    Handle type(H5Dget_type(d.get()));
    Handle space(H5Dget_space(d.get()));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 1 || rank > 4) {
        return;
    }
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    hsize_t rowSize = 1;
    for (int k = 1; k < rank; ++k) {
        rowSize *= dims[static_cast<std::size_t>(k)];
    }
    std::vector<double> values(dims[0] * rowSize);
    if (!values.empty()) {
        H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
    if (cut) {
        dims[0] = in.ConsumeIntegralInRange<hsize_t>(0, dims[0]);
        values.resize(dims[0] * rowSize);
    }
    for (int k = in.ConsumeIntegralInRange(0, 4); k > 0 && !values.empty(); --k) {
        values[in.ConsumeIntegralInRange<std::size_t>(0, values.size() - 1)] = specialValue(in);
    }
    Handle fileType(H5Tcopy(type.get()));
    d = Handle();
    H5Ldelete(file, path.c_str(), H5P_DEFAULT);
    Handle newSpace(H5Screate_simple(rank, dims.data(), nullptr));
    Handle nd(H5Dcreate2(file, path.c_str(), fileType.get(), newSpace.get(), H5P_DEFAULT,
                         H5P_DEFAULT, H5P_DEFAULT));
    if (nd.get() >= 0 && !values.empty()) {
        H5Dwrite(nd.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
}

void editDataset(hid_t file, const Dataset& dataset, FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange(0, 15)) {
    case 1:
        H5Ldelete(file, dataset.path.c_str(), H5P_DEFAULT);
        break;
    case 2:
    case 3:
        if (dataset.isString) {
            const std::string text = in.ConsumeRandomLengthString(4096);
            H5Ldelete(file, dataset.path.c_str(), H5P_DEFAULT);
            hvi::io::h5::writeStringDataset(file, dataset.path, text);
        } else {
            rewriteNumbers(file, dataset.path, in, in.ConsumeBool());
        }
        break;
    default:
        break; // most datasets stay as they are, so one edit's effect is seen alone
    }
}

void editAttribute(hid_t file, const Attribute& attribute, FuzzedDataProvider& in) {
    const int op = in.ConsumeIntegralInRange(0, 15);
    if (op < 1 || op > 4) {
        return;
    }
    Handle object(H5Oopen(file, attribute.object.c_str(), H5P_DEFAULT));
    if (object.get() < 0) {
        return; // dropped with its group
    }
    H5Adelete(object.get(), attribute.name.c_str());
    if (op == 2) {
        hvi::io::h5::writeAttribute(object.get(), attribute.name, specialValue(in));
    } else if (op == 3) {
        hvi::io::h5::writeAttribute(object.get(), attribute.name, in.ConsumeRandomLengthString(64));
    } else if (op == 4) {
        hvi::io::h5::writeAttribute(object.get(), attribute.name, in.ConsumeIntegral<long>());
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    runFileTemplate();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    const Template& t = runFileTemplate();
    const auto run = scratch() / "run.h5";
    std::filesystem::copy_file(t.file, run, std::filesystem::copy_options::overwrite_existing);
    FuzzedDataProvider in(data, size);
    try { // an edit HDF5 refuses leaves the file as the edits before it made it
        hvi::io::h5::ErrorSilencer quiet;
        Handle file(H5Fopen(run.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        for (const auto& a : t.attributes) {
            editAttribute(file.get(), a, in);
        }
        for (const auto& d : t.datasets) {
            editDataset(file.get(), d, in);
        }
        for (const auto& g : t.groups) {
            if (in.ConsumeIntegralInRange(0, 31) == 1) {
                H5Ldelete(file.get(), g.c_str(), H5P_DEFAULT);
            }
        }
    } catch (const std::exception&) {
    }
    hvi::app::HviAssessTool assess;
    runCaptured(assess,
                {"hvi-assess", run.string(), "-q", "-o", (scratch() / "verdict.json").string(),
                 "--pictures", (scratch() / "pictures").string(), "--times-us", "0.8",
                 "--picture-width-px", "320", "--picture-height-px", "240"});
    return 0;
}
