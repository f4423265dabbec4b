#include "io/Checkpoint.hpp"

#include "core/Error.hpp"
#include "io/AtomicOutput.hpp"
#include "io/Hdf5.hpp"
#include "io/JsonText.hpp"

namespace hvi::io {

namespace fs = std::filesystem;
using h5::checked;
using h5::Handle;

fs::path checkpointPathFor(const fs::path& runFile) {
    fs::path path = runFile;
    path.replace_extension(".ckpt.h5");
    return path;
}

namespace {

constexpr const char* kExpectCheckpoint = "an HDF5 checkpoint written by hvi-run";

void checkName(const std::string& name, const std::string& kind) {
    if (name.empty() || name == "." || name.find('/') != std::string::npos) {
        throw RuntimeFailure("checkpoint: " + kind + " array name \"" + name +
                             "\" is not allowed (non-empty, no '/')");
    }
}

template <class T>
void writeArrays(hid_t file, const std::string& groupName,
                 const std::map<std::string, std::vector<T>>& arrays, ElementType type) {
    Handle group = h5::createGroup(file, groupName);
    for (const auto& [name, values] : arrays) {
        const std::vector<hsize_t> dims{static_cast<hsize_t>(values.size())};
        Handle dataset = h5::writeArrayDataset(group.get(), name, h5::fileTypeOf(type),
                                               h5::memTypeOf(type), dims, values.data());
    }
}

template <class T>
std::map<std::string, std::vector<T>> readArrays(hid_t file, const std::string& label,
                                                 const std::string& groupPath, ElementType type) {
    std::map<std::string, std::vector<T>> arrays;
    Handle group = h5::openObject(file, label, groupPath, "the checkpoint's arrays");
    for (const auto& name : h5::childNames(group.get(), label, groupPath)) {
        const std::string path = groupPath + "/" + name;
        Handle dataset = h5::openObject(file, label, path, "a 1-D array");
        if (H5Iget_type(dataset.get()) != H5I_DATASET) {
            throw InputError(label, path, "is not a dataset", "a 1-D array");
        }
        const auto dims = h5::datasetDims(dataset.get());
        if (dims.size() != 1) {
            throw InputError(label, path, "is not 1-D", "a 1-D array");
        }
        std::vector<T> values(static_cast<std::size_t>(dims[0]));
        h5::readArrayDataset(dataset.get(), h5::memTypeOf(type), values.data(), label, path);
        arrays.emplace(name, std::move(values));
    }
    return arrays;
}

} // namespace

void writeCheckpoint(const fs::path& path, const CheckpointState& state) {
    for (const auto& entry : state.doubles) {
        checkName(entry.first, "double");
    }
    for (const auto& entry : state.ints) {
        checkName(entry.first, "int");
    }
    h5::ErrorSilencer quiet;
    AtomicOutput output(path);
    if (output.isStdout()) {
        throw RuntimeFailure("a checkpoint cannot be written to standard output");
    }
    {
        const std::string what = "cannot write checkpoint " + output.tempPath().string();
        Handle fapl = checked(H5Pcreate(H5P_FILE_ACCESS), what);
        checked(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), what);
        checked(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), what);
        Handle file = checked(
            H5Fcreate(output.tempPath().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), what);
        h5::writeAttribute(file.get(), "Format", "hvi-checkpoint");
        h5::writeAttribute(file.get(), "FormatVersion", kCheckpointFormatVersion);
        h5::writeAttribute(file.get(), "Time", state.timeUs);
        h5::writeAttribute(file.get(), "Step", state.step);
        writeArrays(file.get(), "doubles", state.doubles, ElementType::Float64);
        writeArrays(file.get(), "ints", state.ints, ElementType::Int32);
        h5::writeStringDataset(file.get(), "extra", jsonText(state.extra));
        if (!file.reset()) {
            h5::failWrite(what);
        }
    }
    output.commit();
}

CheckpointState readCheckpoint(const fs::path& path) {
    h5::ErrorSilencer quiet;
    const std::string label = path.string();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw InputError(label, "", fs::exists(path, ec) ? "is not a file" : "no such file",
                         kExpectCheckpoint);
    }
    if (H5Fis_hdf5(path.c_str()) <= 0) {
        throw InputError(label, "/", "not an HDF5 file", kExpectCheckpoint);
    }
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!file.valid()) {
        const std::string detail = h5::lastErrorMessage();
        throw InputError(label, "/",
                         "cannot be opened (truncated or damaged?)" +
                             (detail.empty() ? std::string() : ": " + detail),
                         kExpectCheckpoint);
    }
    auto attribute = [&](const std::string& name, const std::string& expected) {
        auto value = h5::readAttribute(file.get(), name, label, "/");
        if (!value) {
            throw InputError(label, "/@" + name, "missing", expected);
        }
        return *value;
    };
    const auto format = attribute("Format", kExpectCheckpoint);
    if (format != "hvi-checkpoint") {
        throw InputError(label, "/@Format", "is " + jsonText(format), "\"hvi-checkpoint\"");
    }
    const auto version = attribute("FormatVersion", "an integer");
    if (!version.is_number_integer() || version.get<long>() > kCheckpointFormatVersion) {
        throw InputError(label, "/@FormatVersion", "is " + jsonText(version),
                         "a format version up to " + std::to_string(kCheckpointFormatVersion));
    }
    const auto time = attribute("Time", "checkpoint time [us]");
    const auto step = attribute("Step", "step number");
    if (!time.is_number() || !step.is_number_integer()) {
        throw InputError(label, "/", "has malformed Time/Step attributes",
                         "Time [us] (number), Step (integer)");
    }
    CheckpointState state;
    state.timeUs = time.get<double>();
    state.step = step.get<long>();
    state.doubles = readArrays<double>(file.get(), label, "/doubles", ElementType::Float64);
    state.ints = readArrays<int32_t>(file.get(), label, "/ints", ElementType::Int32);
    const std::string extra = h5::readStringDataset(file.get(), label, "/extra");
    try {
        state.extra = nlohmann::json::parse(extra);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(label, "/extra", "is not valid JSON (byte " + std::to_string(e.byte) + ")",
                         "JSON text");
    }
    return state;
}

} // namespace hvi::io
