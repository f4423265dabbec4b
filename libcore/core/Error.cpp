#include "core/Error.hpp"

namespace hvi {

std::string InputIssue::format() const {
    std::string line = file + ": " + (pointer.empty() ? std::string("/") : pointer) + ": " + problem;
    if (!expected.empty()) {
        line += " (" + expected + ")";
    }
    return line;
}

namespace {
std::string joinIssues(const std::vector<InputIssue>& issues) {
    std::string text;
    for (const auto& issue : issues) {
        if (!text.empty()) {
            text += "\n";
        }
        text += issue.format();
    }
    return text;
}
} // namespace

InputError::InputError(std::vector<InputIssue> issues)
    : std::runtime_error(joinIssues(issues)), m_issues(std::move(issues)) {}

InputError::InputError(std::string file, std::string pointer, std::string problem,
                       std::string expected)
    : InputError(std::vector<InputIssue>{
          {std::move(file), std::move(pointer), std::move(problem), std::move(expected)}}) {}

} // namespace hvi
