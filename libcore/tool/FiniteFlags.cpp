#include "tool/FiniteFlags.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hvi::tool {

namespace {

bool isFloatingPoint(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    return type.rfind("FLOAT", 0) == 0 || type.rfind("NUM", 0) == 0;
}

/// Whether `text` is, as a whole, a number CLI11 would read as NaN or an infinity. Text that
/// is not a number is left to CLI11, which refuses it.
bool isNonFiniteNumber(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0' && !std::isfinite(value);
}

} // namespace

void FiniteFlags::watch(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        if (!isFloatingPoint(*option)) {
            continue;
        }
        // A transform runs before the option's checks, so CLI11's own range message for
        // "inf" ("not in range 0 to 1.8e308") does not come first. It records and lets the
        // value pass, so that several bad values are reported together (unless a range
        // check of one of them ends the parse first).
        option->transform(CLI::Validator(
                              [this, option](std::string& value) {
                                  if (isNonFiniteNumber(value)) {
                                      record(*option, value);
                                  }
                                  return std::string();
                              },
                              ""),
                          "finite");
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        watch(*sub);
    }
}

void FiniteFlags::setPointer(const CLI::Option* option, const std::string& pointer) {
    m_pointers[option] = pointer;
}

void FiniteFlags::record(const CLI::Option& option, const std::string& value) {
    const auto it = m_pointers.find(&option);
    InputIssue issue =
        it == m_pointers.end()
            ? InputIssue{"<flags>", option.get_name(), "is " + value + ", not a finite number",
                         "a finite number"}
            : InputIssue{"<flags>", it->second,
                         "is " + value + " (" + option.get_name() + "), not a finite number",
                         "a finite number"};
    const bool seen = std::any_of(m_issues.begin(), m_issues.end(), [&](const InputIssue& i) {
        return i.pointer == issue.pointer && i.problem == issue.problem;
    });
    if (!seen) {
        m_issues.push_back(std::move(issue));
    }
}

} // namespace hvi::tool
