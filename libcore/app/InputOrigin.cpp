#include "app/InputOrigin.hpp"

#include "app/FlagOverlay.hpp"

namespace hvi::app {

namespace {

const std::string kFlags = kFlagsLabel;

/// The last token of a JSON pointer ("/panel/core_thickness_mm" -> "core_thickness_mm").
std::string lastToken(const std::string& pointer) {
    const auto slash = pointer.rfind('/');
    return slash == std::string::npos ? pointer : pointer.substr(slash + 1);
}

bool isKeyChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// Replaces whole-word occurrences of `from` (snake_case keys) by `to`.
std::string replaceKey(const std::string& text, const std::string& from, const std::string& to) {
    if (from == to) {
        return text;
    }
    std::string out;
    std::size_t pos = 0;
    while (true) {
        const auto hit = text.find(from, pos);
        if (hit == std::string::npos) {
            out += text.substr(pos);
            return out;
        }
        const bool startOk = hit == 0 || !isKeyChar(text[hit - 1]);
        const bool endOk = hit + from.size() >= text.size() || !isKeyChar(text[hit + from.size()]);
        out += text.substr(pos, hit - pos);
        out += (startOk && endOk) ? to : from;
        pos = hit + from.size();
    }
}

} // namespace

InputOrigin::InputOrigin(std::string file, std::set<std::string> flagPointers)
    : m_file(std::move(file)), m_flagPointers(std::move(flagPointers)) {}

const std::string& InputOrigin::labelOf(const std::string& pointer) const {
    return m_flagPointers.count(pointer) ? kFlags : m_file;
}

InputError InputOrigin::relabel(const InputError& error) const {
    return relabel(error, {});
}

InputError InputOrigin::relabel(const InputError& error,
                                const std::vector<KeyLocation>& keys) const {
    std::vector<InputIssue> issues = error.issues();
    for (auto& issue : issues) {
        for (const auto& key : keys) {
            if (issue.pointer == "/" + key.libraryKey) {
                issue.pointer = key.pointer;
            }
        }
        for (const auto& key : keys) {
            const std::string toolKey = lastToken(key.pointer);
            issue.problem = replaceKey(issue.problem, key.libraryKey, toolKey);
            issue.expected = replaceKey(issue.expected, key.libraryKey, toolKey);
        }
        issue.file = labelOf(issue.pointer);
    }
    return InputError(std::move(issues));
}

} // namespace hvi::app
