#include "io/Hdf5.hpp"

#include "core/Error.hpp"
#include "io/JsonText.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace hvi::io::h5 {

bool Handle::reset() {
    if (m_id < 0) {
        return true;
    }
    herr_t status = 0;
    switch (H5Iget_type(m_id)) {
    case H5I_FILE:
        status = H5Fclose(m_id);
        break;
    case H5I_GROUP:
        status = H5Gclose(m_id);
        break;
    case H5I_DATASET:
        status = H5Dclose(m_id);
        break;
    case H5I_ATTR:
        status = H5Aclose(m_id);
        break;
    case H5I_DATATYPE:
        status = H5Tclose(m_id);
        break;
    case H5I_DATASPACE:
        status = H5Sclose(m_id);
        break;
    case H5I_GENPROP_LST:
        status = H5Pclose(m_id);
        break;
    default:
        status = -1; // not a live identifier: nothing we can close
        break;
    }
    m_id = H5I_INVALID_HID;
    return status >= 0;
}

ErrorSilencer::ErrorSilencer() {
    H5Eget_auto2(H5E_DEFAULT, &m_func, &m_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

ErrorSilencer::~ErrorSilencer() {
    H5Eset_auto2(H5E_DEFAULT, m_func, m_data);
}

namespace {

herr_t collectInnermost(unsigned /*n*/, const H5E_error2_t* err, void* clientData) {
    // Walking downward, the last entry visited is the innermost (most specific) one.
    if (err != nullptr && err->desc != nullptr) {
        *static_cast<std::string*>(clientData) = err->desc;
    }
    return 0;
}

} // namespace

std::string lastErrorMessage() {
    std::string message;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collectInnermost, &message);
    // The library's own texts can hold line breaks (a write failure quotes ctime()); the
    // tools' errors are one line.
    std::replace(message.begin(), message.end(), '\n', ' ');
    return message;
}

void skipCleanupAtExit() {
    H5dont_atexit();
}

void failWrite(const std::string& what) {
    const std::string detail = lastErrorMessage();
    throw RuntimeFailure(detail.empty() ? what : what + ": " + detail);
}

hid_t fileTypeOf(ElementType type) {
    switch (type) {
    case ElementType::Float64:
        return H5T_IEEE_F64LE;
    case ElementType::Int32:
        return H5T_STD_I32LE;
    case ElementType::UInt8:
        return H5T_STD_U8LE;
    case ElementType::Int64:
        return H5T_STD_I64LE;
    case ElementType::Float32:
        return H5T_IEEE_F32LE;
    }
    return H5T_IEEE_F64LE;
}

hid_t memTypeOf(ElementType type) {
    switch (type) {
    case ElementType::Float64:
        return H5T_NATIVE_DOUBLE;
    case ElementType::Int32:
        return H5T_NATIVE_INT32;
    case ElementType::UInt8:
        return H5T_NATIVE_UINT8;
    case ElementType::Int64:
        return H5T_NATIVE_INT64;
    case ElementType::Float32:
        return H5T_NATIVE_FLOAT;
    }
    return H5T_NATIVE_DOUBLE;
}

std::string libraryVersion() {
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

// ---- writing ------------------------------------------------------------------------------

Handle checked(hid_t id, const std::string& what) {
    if (id < 0) {
        failWrite(what);
    }
    return Handle(id);
}

void checked(herr_t status, const std::string& what) {
    if (status < 0) {
        failWrite(what);
    }
}

Handle createGroup(hid_t location, const std::string& name) {
    return checked(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   "cannot create HDF5 group " + name);
}

namespace {

Handle utf8StringType() {
    Handle type = checked(H5Tcopy(H5T_C_S1), "cannot create HDF5 string type");
    checked(H5Tset_size(type.get(), H5T_VARIABLE), "cannot create HDF5 string type");
    checked(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot create HDF5 string type");
    return type;
}

void writeScalarAttribute(hid_t object, const std::string& name, hid_t fileType, hid_t memType,
                          const void* value) {
    const std::string what = "cannot write HDF5 attribute " + name;
    Handle space = checked(H5Screate(H5S_SCALAR), what);
    if (H5Aexists(object, name.c_str()) > 0) {
        checked(H5Adelete(object, name.c_str()), what);
    }
    Handle attr = checked(
        H5Acreate2(object, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT), what);
    checked(H5Awrite(attr.get(), memType, value), what);
}

Handle boolEnumType() {
    Handle type = checked(H5Tenum_create(H5T_NATIVE_INT8), "cannot create HDF5 bool type");
    const std::int8_t no = 0;
    const std::int8_t yes = 1;
    checked(H5Tenum_insert(type.get(), "FALSE", &no), "cannot create HDF5 bool type");
    checked(H5Tenum_insert(type.get(), "TRUE", &yes), "cannot create HDF5 bool type");
    return type;
}

} // namespace

void writeAttribute(hid_t object, const std::string& name, const std::string& value) {
    Handle type = utf8StringType();
    const char* text = value.c_str();
    writeScalarAttribute(object, name, type.get(), type.get(), &text);
}

void writeAttribute(hid_t object, const std::string& name, const char* value) {
    writeAttribute(object, name, std::string(value));
}

void writeAttribute(hid_t object, const std::string& name, double value) {
    writeScalarAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void writeAttribute(hid_t object, const std::string& name, long value) {
    writeScalarAttribute(object, name, H5T_STD_I64LE, H5T_NATIVE_LONG, &value);
}

void writeAttribute(hid_t object, const std::string& name, int value) {
    writeAttribute(object, name, static_cast<long>(value));
}

void writeBoolAttribute(hid_t object, const std::string& name, bool value) {
    Handle type = boolEnumType();
    const std::int8_t raw = value ? 1 : 0;
    writeScalarAttribute(object, name, type.get(), type.get(), &raw);
}

void writeJsonAttribute(hid_t object, const std::string& name, const nlohmann::json& value) {
    if (value.is_null()) {
        return;
    }
    if (value.is_string()) {
        writeAttribute(object, name, value.get<std::string>());
    } else if (value.is_boolean()) {
        writeBoolAttribute(object, name, value.get<bool>());
    } else if (value.is_number_integer()) {
        writeAttribute(object, name, value.get<long>());
    } else if (value.is_number()) {
        writeAttribute(object, name, value.get<double>());
    } else {
        // Invalid UTF-8 in a string must not make the end of a run fail: replace it.
        writeAttribute(object, name, jsonText(value));
    }
}

Handle writeStringDataset(hid_t location, const std::string& name, const std::string& text) {
    const std::string what = "cannot write HDF5 dataset " + name;
    Handle type = utf8StringType();
    Handle space = checked(H5Screate(H5S_SCALAR), what);
    Handle dataset = checked(H5Dcreate2(location, name.c_str(), type.get(), space.get(),
                                        H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             what);
    const char* data = text.c_str();
    checked(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &data), what);
    return dataset;
}

Handle writeArrayDataset(hid_t location, const std::string& name, hid_t fileType, hid_t memType,
                         const std::vector<hsize_t>& dims, const void* data, int gzipLevel) {
    const std::string what = "cannot write HDF5 dataset " + name;
    Handle space =
        checked(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), what);
    hsize_t count = 1;
    for (hsize_t d : dims) {
        count *= d;
    }
    Handle dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), what);
    if (gzipLevel > 0 && count > 0) {
        // Chunks of at most 64 Ki rows: large enough to compress well, small enough to read
        // one snapshot field without inflating much more than it.
        std::vector<hsize_t> chunk = dims;
        chunk[0] = std::min<hsize_t>(chunk[0], hsize_t{1} << 16);
        checked(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()), what);
        checked(H5Pset_shuffle(dcpl.get()), what);
        checked(H5Pset_deflate(dcpl.get(), static_cast<unsigned>(gzipLevel)), what);
    }
    Handle dataset = checked(H5Dcreate2(location, name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                        dcpl.get(), H5P_DEFAULT),
                             what);
    if (count > 0) {
        checked(H5Dwrite(dataset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
    }
    return dataset;
}

// ---- reading ------------------------------------------------------------------------------

bool pathExists(hid_t file, const std::string& path) {
    // H5Lexists fails (rather than returning false) when an intermediate group is missing,
    // so walk the path one component at a time.
    std::string prefix;
    std::size_t start = 1;
    while (start <= path.size()) {
        std::size_t end = path.find('/', start);
        if (end == std::string::npos) {
            end = path.size();
        }
        if (end > start) {
            prefix += "/" + path.substr(start, end - start);
            if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) {
                return false;
            }
        }
        start = end + 1;
    }
    return H5Oexists_by_name(file, path.c_str(), H5P_DEFAULT) > 0;
}

Handle openObject(hid_t file, const std::string& fileLabel, const std::string& path,
                  const std::string& expected) {
    if (!pathExists(file, path)) {
        throw InputError(fileLabel, path, "missing", expected);
    }
    const hid_t id = H5Oopen(file, path.c_str(), H5P_DEFAULT);
    if (id < 0) {
        throw InputError(fileLabel, path, "cannot be opened (damaged file?)", expected);
    }
    return Handle(id);
}

std::vector<hsize_t> datasetDims(hid_t dataset) {
    Handle space(H5Dget_space(dataset));
    if (!space.valid()) {
        return {};
    }
    const int rank = H5Sget_simple_extent_ndims(space.get());
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    if (rank > 0) {
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    }
    return dims;
}

void readArrayDataset(hid_t dataset, hid_t memType, void* out, const std::string& fileLabel,
                      const std::string& path) {
    Handle space(H5Dget_space(dataset));
    if (!space.valid()) {
        throw InputError(fileLabel, path, "cannot be read (damaged file?)");
    }
    if (H5Sget_simple_extent_npoints(space.get()) == 0) {
        return;
    }
    if (H5Dread(dataset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0) {
        const std::string detail = lastErrorMessage();
        throw InputError(fileLabel, path, "cannot be read" + (detail.empty() ? "" : ": " + detail),
                         "a complete, undamaged run file");
    }
}

namespace {

/// Reads a scalar string from a dataset (isAttribute false) or attribute.
std::optional<std::string> readScalarString(hid_t object, bool isAttribute) {
    Handle type(isAttribute ? H5Aget_type(object) : H5Dget_type(object));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) {
        return std::nullopt;
    }
    Handle space(isAttribute ? H5Aget_space(object) : H5Dget_space(object));
    if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1) {
        return std::nullopt;
    }
    auto read = [&](hid_t memType, void* buffer) {
        return isAttribute ? H5Aread(object, memType, buffer)
                           : H5Dread(object, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer);
    };
    Handle memType(H5Tcopy(H5T_C_S1));
    if (H5Tis_variable_str(type.get()) > 0) {
        H5Tset_size(memType.get(), H5T_VARIABLE);
        H5Tset_cset(memType.get(), H5Tget_cset(type.get()));
        char* text = nullptr;
        if (read(memType.get(), &text) < 0) {
            return std::nullopt;
        }
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    const std::size_t size = H5Tget_size(type.get());
    H5Tset_size(memType.get(), size);
    H5Tset_cset(memType.get(), H5Tget_cset(type.get()));
    H5Tset_strpad(memType.get(), H5T_STR_NULLPAD);
    std::string value(size, '\0');
    if (read(memType.get(), value.data()) < 0) {
        return std::nullopt;
    }
    value.resize(std::min(value.find('\0'), value.size()));
    return value;
}

} // namespace

std::string readStringDataset(hid_t file, const std::string& fileLabel, const std::string& path) {
    Handle dataset = openObject(file, fileLabel, path, "a JSON text dataset");
    if (H5Iget_type(dataset.get()) != H5I_DATASET) {
        throw InputError(fileLabel, path, "is not a dataset", "a JSON text dataset");
    }
    auto text = readScalarString(dataset.get(), false);
    if (!text) {
        throw InputError(fileLabel, path, "cannot be read as a string", "a JSON text dataset");
    }
    return *text;
}

namespace {

std::optional<nlohmann::json> attributeToJson(hid_t attr) {
    Handle type(H5Aget_type(attr));
    Handle space(H5Aget_space(attr));
    if (!type.valid() || !space.valid()) {
        return std::nullopt;
    }
    const hssize_t count = H5Sget_simple_extent_npoints(space.get());
    const bool scalar = H5Sget_simple_extent_type(space.get()) == H5S_SCALAR;
    switch (H5Tget_class(type.get())) {
    case H5T_STRING: {
        auto text = readScalarString(attr, true);
        return text ? std::optional<nlohmann::json>(*text) : std::nullopt;
    }
    case H5T_FLOAT: {
        std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(count, 0)));
        if (!values.empty() && H5Aread(attr, H5T_NATIVE_DOUBLE, values.data()) < 0) {
            return std::nullopt;
        }
        return scalar && values.size() == 1 ? nlohmann::json(values[0]) : nlohmann::json(values);
    }
    case H5T_INTEGER: {
        std::vector<long> values(static_cast<std::size_t>(std::max<hssize_t>(count, 0)));
        if (!values.empty() && H5Aread(attr, H5T_NATIVE_LONG, values.data()) < 0) {
            return std::nullopt;
        }
        return scalar && values.size() == 1 ? nlohmann::json(values[0]) : nlohmann::json(values);
    }
    case H5T_ENUM: {
        if (count != 1) {
            return std::nullopt;
        }
        Handle nativeType(H5Tget_native_type(type.get(), H5T_DIR_DEFAULT));
        std::vector<unsigned char> raw(H5Tget_size(nativeType.get()));
        if (H5Aread(attr, nativeType.get(), raw.data()) < 0) {
            return std::nullopt;
        }
        char name[16] = {};
        if (H5Tenum_nameof(nativeType.get(), raw.data(), name, sizeof(name)) < 0) {
            return std::nullopt;
        }
        const std::string label = name;
        if (label == "TRUE" || label == "FALSE") {
            return nlohmann::json(label == "TRUE");
        }
        return nlohmann::json(label);
    }
    default:
        return std::nullopt;
    }
}

} // namespace

std::optional<nlohmann::json> readAttribute(hid_t object, const std::string& name,
                                            const std::string& fileLabel,
                                            const std::string& objectPath) {
    if (H5Aexists(object, name.c_str()) <= 0) {
        return std::nullopt;
    }
    Handle attr(H5Aopen(object, name.c_str(), H5P_DEFAULT));
    auto value = attr.valid() ? attributeToJson(attr.get()) : std::nullopt;
    if (!value) {
        throw InputError(fileLabel, objectPath + "@" + name, "attribute cannot be read",
                         "a string, number or boolean attribute");
    }
    return value;
}

namespace {

struct AttributeWalk {
    std::vector<std::string> names;
};

herr_t collectAttributeName(hid_t /*object*/, const char* name, const H5A_info_t* /*info*/,
                            void* data) {
    static_cast<AttributeWalk*>(data)->names.emplace_back(name);
    return 0;
}

herr_t collectLinkName(hid_t /*group*/, const char* name, const H5L_info_t* /*info*/, void* data) {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
}

} // namespace

nlohmann::json readAllAttributes(hid_t object, const std::string& fileLabel,
                                 const std::string& objectPath) {
    nlohmann::json result = nlohmann::json::object();
    AttributeWalk walk;
    hsize_t index = 0;
    if (H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &index, collectAttributeName, &walk) < 0) {
        throw InputError(fileLabel, objectPath, "attributes cannot be listed (damaged file?)");
    }
    for (const auto& name : walk.names) {
        result[name] = *readAttribute(object, name, fileLabel, objectPath);
    }
    return result;
}

std::vector<std::string> childNames(hid_t group, const std::string& fileLabel,
                                    const std::string& groupPath) {
    std::vector<std::string> names;
    hsize_t index = 0;
    if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &index, collectLinkName, &names) < 0) {
        throw InputError(fileLabel, groupPath, "cannot be listed (damaged file?)");
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace hvi::io::h5
