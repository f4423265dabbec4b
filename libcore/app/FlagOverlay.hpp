// Command-line flags that set values of a tool's input document, so that every value of a
// JSON input can also be given (or overridden) at a shell: `--ppi 40` writes 40 at /panel/ppi.
//
// The flags only parse; they do not range-check. Their values are written into the document
// and validated with it against the input schema, so a bad flag value gets the same one-line
// error as a bad file value, labelled "<flags>" instead of the file name
// (`foam2layers: <flags>: /panel/ppi: ... (foam pores per inch [1/in], > 0)`), and all
// problems of file and flags are reported together. The help text states unit and range.
#pragma once

#include <CLI/CLI.hpp>
#include <deque>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hvi::app {

/// The "file" name of values that came from command-line flags, in error lines.
inline constexpr const char* kFlagsLabel = "<flags>";

class FlagOverlay {
public:
    /// `flags` (CLI11 names, e.g. "--ppi") set the number at JSON `pointer`; `help` should
    /// give the unit and range. When given, the pointers in `erases` are removed from the
    /// document first (e.g. --facesheet-mm removes front_ and rear_facesheet_mm).
    CLI::Option* addNumber(CLI::App& app, const std::string& flags, const std::string& pointer,
                           const std::string& help, std::vector<std::string> erases = {});
    /// A string value; with `choices`, CLI11 rejects anything else (a usage error).
    CLI::Option* addString(CLI::App& app, const std::string& flags, const std::string& pointer,
                           const std::string& help, std::vector<std::string> choices = {});

    /// Whether a flag set the value at `pointer`.
    bool given(const std::string& pointer) const;
    /// The pointers the given flags set.
    std::set<std::string> givenPointers() const;
    /// The number flags and the pointers they set, for the tool's check of NaN and infinite
    /// flag values (tool::FiniteFlags), which then names the pointer.
    std::vector<std::pair<const CLI::Option*, std::string>> numberFlags() const;
    /// Writes the given values into `document`, creating the objects on the way. A value whose
    /// parent exists but is not an object is skipped (schema validation reports the parent).
    void applyTo(nlohmann::json& document) const;

private:
    struct Entry {
        std::string pointer;
        std::vector<std::string> erases;
        bool isNumber = true;
        double number = 0.0;
        std::string text;
        CLI::Option* option = nullptr;
    };
    std::deque<Entry> m_entries; // a deque: CLI11 keeps references to the values
};

} // namespace hvi::app
