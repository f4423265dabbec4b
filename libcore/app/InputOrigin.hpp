// Where each value of a tool's input came from: the input file, or a command-line flag
// ("<flags>", see FlagOverlay). Errors are raised against the document as a whole and then
// relabelled here, so that every error line names the place the user has to edit.
//
// It also translates the keys of a library's messages into the tool's JSON layout: the
// geometry reductions report problems at their own keys (FoamCoreSpec "standoff_mm"), which
// the tool's file holds elsewhere ("/panel/core_thickness_mm").
#pragma once

#include "core/Error.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace hvi::app {

/// A library key and where the tool's document holds it.
struct KeyLocation {
    std::string libraryKey; ///< e.g. "standoff_mm"
    std::string pointer;    ///< e.g. "/panel/core_thickness_mm"
};

class InputOrigin {
public:
    InputOrigin() = default;
    /// `file`: the input file as the user named it ("<flags>" when there is none).
    InputOrigin(std::string file, std::set<std::string> flagPointers);

    const std::string& file() const { return m_file; }
    /// "<flags>" when a flag set the value at `pointer`, else the file.
    const std::string& labelOf(const std::string& pointer) const;

    /// The issues of `error` with their file label set by labelOf(pointer).
    InputError relabel(const InputError& error) const;
    /// As relabel(), after mapping issues located at "/" + libraryKey to the tool's pointer
    /// and replacing the library's key names in the texts by the tool's key names.
    InputError relabel(const InputError& error, const std::vector<KeyLocation>& keys) const;

private:
    std::string m_file;
    std::set<std::string> m_flagPointers;
};

} // namespace hvi::app
