// Thin HDF5 (C API, 1.10) plumbing shared by the run file and the checkpoint: an owning
// handle, scoped silencing of the library's own error printing, and typed helpers that turn
// HDF5 failures into the project's errors.
//
// Two error policies, one per direction:
//  - writing: a failure is a RuntimeFailure (exit code 3) carrying the innermost HDF5
//    message (e.g. "No space left on device");
//  - reading: a missing or unreadable object is an InputError whose pointer is the HDF5
//    path ("/snapshots/000003/Density"), so a tool prints
//    `hvi-assess: run.h5: /snapshots/000003/Density: missing (...)`.
//
// Not thread-safe (the serial HDF5 library is not): call from one thread, outside OpenMP
// parallel regions.
#pragma once

#include "io/OutputFields.hpp"

#include <hdf5.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace hvi::io::h5 {

/// Owns one HDF5 identifier (file, group, dataset, attribute, datatype, dataspace, property
/// list) and closes it with the matching H5*close.
class Handle {
public:
    Handle() = default;
    explicit Handle(hid_t id) : m_id(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : m_id(other.release()) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            m_id = other.release();
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    hid_t get() const { return m_id; }
    bool valid() const { return m_id >= 0; }
    hid_t release() {
        const hid_t id = m_id;
        m_id = H5I_INVALID_HID;
        return id;
    }
    /// Closes the identifier; returns false when HDF5 reports an error while closing (for a
    /// file this is where buffered data reaches the disk, so callers that care check it).
    bool reset();

private:
    hid_t m_id = H5I_INVALID_HID;
};

/// While alive, HDF5 does not print its error stack to stderr (we report errors ourselves).
class ErrorSilencer {
public:
    ErrorSilencer();
    ~ErrorSilencer();
    ErrorSilencer(const ErrorSilencer&) = delete;
    ErrorSilencer& operator=(const ErrorSilencer&) = delete;

private:
    H5E_auto2_t m_func = nullptr;
    void* m_data = nullptr;
};

/// The innermost message on the current HDF5 error stack ("" when empty).
std::string lastErrorMessage();

/// Keeps the HDF5 library from closing what is still open when the process exits. After a
/// failed write (disk full) a file the library could not close stays in its tables, and its
/// exit-time clean-up (H5_term_library) then crashes: exit 139 instead of the tool's 3. The
/// tools close every file they open on every path (RAII handles), so nothing is lost; the
/// kernel reclaims the rest. Must be called before the first HDF5 call: Tool::run does.
void skipCleanupAtExit();

/// Throws RuntimeFailure("what: <innermost HDF5 message>").
[[noreturn]] void failWrite(const std::string& what);

/// The HDF5 file type (explicit little-endian) and native memory type of an element type.
hid_t fileTypeOf(ElementType type);
hid_t memTypeOf(ElementType type);

/// "1.10.8": the version of the HDF5 library linked in.
std::string libraryVersion();

// ---- writing (errors: RuntimeFailure) ---------------------------------------------------

/// Checks an id returned by an HDF5 call; throws via failWrite when negative.
Handle checked(hid_t id, const std::string& what);
/// Checks a status returned by an HDF5 call; throws via failWrite when negative.
void checked(herr_t status, const std::string& what);

Handle createGroup(hid_t location, const std::string& name);

void writeAttribute(hid_t object, const std::string& name, const std::string& value);
void writeAttribute(hid_t object, const std::string& name, const char* value);
void writeAttribute(hid_t object, const std::string& name, double value);
void writeAttribute(hid_t object, const std::string& name, long value);
void writeAttribute(hid_t object, const std::string& name, int value);
/// Booleans are stored as an int8 enum {FALSE=0, TRUE=1}, the convention h5py reads as bool.
void writeBoolAttribute(hid_t object, const std::string& name, bool value);
/// A JSON scalar becomes a typed attribute (string, int64, double, bool); null is skipped;
/// arrays and objects are stored as their JSON text (a string attribute).
void writeJsonAttribute(hid_t object, const std::string& name, const nlohmann::json& value);

/// A scalar variable-length UTF-8 string dataset (used for JSON documents).
Handle writeStringDataset(hid_t location, const std::string& name, const std::string& text);

/// A dataset of `dims` (1-D or 2-D) elements of `memType` stored as `fileType`. Zero-sized
/// datasets are allowed (nothing is written). `gzipLevel` > 0 chunks and compresses.
Handle writeArrayDataset(hid_t location, const std::string& name, hid_t fileType, hid_t memType,
                         const std::vector<hsize_t>& dims, const void* data, int gzipLevel = 0);

// ---- reading (errors: InputError naming `file` and the HDF5 path) ------------------------

/// True when every component of the absolute `path` exists and resolves to an object.
bool pathExists(hid_t file, const std::string& path);

/// Opens the object at `path` (group or dataset); InputError "missing" when absent.
Handle openObject(hid_t file, const std::string& fileLabel, const std::string& path,
                  const std::string& expected);

/// The extent of a dataset (empty for a scalar dataspace).
std::vector<hsize_t> datasetDims(hid_t dataset);

/// Reads a whole numeric dataset into `out` (converted to `memType`, sized by the caller to
/// the dataset's element count); InputError naming `path` when HDF5 cannot read it.
void readArrayDataset(hid_t dataset, hid_t memType, void* out, const std::string& fileLabel,
                      const std::string& path);

/// Reads a scalar string dataset (variable or fixed length).
std::string readStringDataset(hid_t file, const std::string& fileLabel, const std::string& path);

/// One attribute as JSON (string, number, bool, or an array of numbers); nullopt if absent.
std::optional<nlohmann::json> readAttribute(hid_t object, const std::string& name,
                                            const std::string& fileLabel,
                                            const std::string& objectPath);

/// Every attribute of an object as a flat JSON object.
nlohmann::json readAllAttributes(hid_t object, const std::string& fileLabel,
                                 const std::string& objectPath);

/// The names of the links directly inside a group, in name order.
std::vector<std::string> childNames(hid_t group, const std::string& fileLabel,
                                    const std::string& groupPath);

} // namespace hvi::io::h5
