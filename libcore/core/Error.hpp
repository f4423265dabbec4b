// The error types every tool maps to an exit code (see docs/conventions.md, "Exit codes").
//
// InputError carries what a user needs to fix a file: the file, a JSON pointer into it,
// what is wrong and what was expected. Tools print it as one line:
//   tool: FILE: /json/pointer: what is wrong (what was expected)
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace hvi {

/// Exit codes shared by all tools.
enum class ExitCode : int {
    Ok = 0,
    CheckFailed = 1,  ///< ran correctly, but a requested check did not pass (hvi-assess --expect)
    BadInput = 2,     ///< usage error, unreadable or invalid input file, non-physical value
    RuntimeFailure = 3, ///< the computation failed (no root, blow-up, I/O error while writing)
    Interrupted = 4,  ///< stopped by a signal; a checkpoint may have been written
};

/// One problem in one input file, located by JSON pointer.
struct InputIssue {
    std::string file;     ///< as the user named it ("-" for stdin, "<flags>" for options)
    std::string pointer;  ///< JSON pointer ("" for the whole document)
    std::string problem;  ///< what is wrong, e.g. "must be > 0, got -1"
    std::string expected; ///< what was expected, e.g. "projectile diameter [mm], > 0"

    /// FILE: /pointer: problem (expected)
    std::string format() const;
};

/// Bad input: one or more issues, all reported together.
class InputError : public std::runtime_error {
public:
    explicit InputError(std::vector<InputIssue> issues);
    InputError(std::string file, std::string pointer, std::string problem,
               std::string expected = "");
    const std::vector<InputIssue>& issues() const { return m_issues; }

private:
    std::vector<InputIssue> m_issues;
};

/// A computation that cannot produce a result (no root in the bracket, non-finite state).
class RuntimeFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The run stopped on a signal; what it leaves behind (checkpoint, partial file) is said
/// before this is thrown.
class Interrupted : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace hvi
