// Refusing NaN and infinities in numeric flags, for every tool at once.
//
// CLI11 reads "nan", "inf" and "1e400" (as inf) into a double without complaint, and its
// range checks let NaN through (every comparison with NaN is false), so a tool that tests
// `value > 0` to see whether a flag was given took `--resolution-mm nan` for "not given" and
// ran at the scene's spacing. The Tool skeleton watches every floating-point option of every
// tool here, before any of the tool's own checks see the value.
#pragma once

#include "core/Error.hpp"

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

namespace hvi::tool {

class FiniteFlags {
public:
    /// Watches every floating-point option of `app`: CLI11's FLOAT, and NUM as the tools
    /// name their number flags. Call after the options are declared, before parsing.
    void watch(CLI::App& app);
    /// A flag that sets a value of the input document is reported at that JSON pointer
    /// (naming the flag in the text), as the document's own errors are.
    void setPointer(const CLI::Option* option, const std::string& pointer);
    /// One issue per non-finite value parsed so far, labelled "<flags>".
    const std::vector<InputIssue>& issues() const { return m_issues; }

private:
    void record(const CLI::Option& option, const std::string& value);

    std::map<const CLI::Option*, std::string> m_pointers;
    std::vector<InputIssue> m_issues;
};

} // namespace hvi::tool
