#include "app/FlagOverlay.hpp"

#include "core/Error.hpp"

namespace hvi::app {

using nlohmann::json;

CLI::Option* FlagOverlay::addNumber(CLI::App& app, const std::string& flags,
                                    const std::string& pointer, const std::string& help,
                                    std::vector<std::string> erases) {
    Entry& entry = m_entries.emplace_back();
    entry.pointer = pointer;
    entry.erases = std::move(erases);
    entry.isNumber = true;
    entry.option = app.add_option(flags, entry.number, help + " (sets " + pointer + ")");
    entry.option->type_name("NUM");
    return entry.option;
}

CLI::Option* FlagOverlay::addString(CLI::App& app, const std::string& flags,
                                    const std::string& pointer, const std::string& help,
                                    std::vector<std::string> choices) {
    Entry& entry = m_entries.emplace_back();
    entry.pointer = pointer;
    entry.isNumber = false;
    entry.option = app.add_option(flags, entry.text, help + " (sets " + pointer + ")");
    if (!choices.empty()) {
        entry.option->check(CLI::IsMember(choices));
    } else {
        entry.option->type_name("TEXT");
    }
    return entry.option;
}

bool FlagOverlay::given(const std::string& pointer) const {
    for (const auto& entry : m_entries) {
        if (entry.pointer == pointer && entry.option->count() > 0) {
            return true;
        }
    }
    return false;
}

std::set<std::string> FlagOverlay::givenPointers() const {
    std::set<std::string> pointers;
    for (const auto& entry : m_entries) {
        if (entry.option->count() > 0) {
            pointers.insert(entry.pointer);
        }
    }
    return pointers;
}

std::vector<std::pair<const CLI::Option*, std::string>> FlagOverlay::numberFlags() const {
    std::vector<std::pair<const CLI::Option*, std::string>> flags;
    for (const auto& entry : m_entries) {
        if (entry.isNumber) {
            flags.emplace_back(entry.option, entry.pointer);
        }
    }
    return flags;
}

namespace {

/// The object that should hold `pointer`'s last token, created as needed; nullptr when an
/// existing parent is not an object.
json* parentObject(json& document, const json::json_pointer& pointer) {
    json* node = &document;
    const json::json_pointer parent = pointer.parent_pointer();
    std::vector<std::string> tokens;
    for (json::json_pointer p = parent; !p.empty(); p = p.parent_pointer()) {
        tokens.insert(tokens.begin(), p.back());
    }
    for (const auto& token : tokens) {
        if (!node->is_object()) {
            return nullptr;
        }
        node = &(*node)[token];
        if (node->is_null()) {
            *node = json::object();
        }
    }
    return node->is_object() ? node : nullptr;
}

} // namespace

void FlagOverlay::applyTo(json& document) const {
    if (document.is_null()) {
        document = json::object();
    }
    for (const auto& entry : m_entries) {
        if (entry.option->count() == 0) {
            continue;
        }
        for (const auto& erase : entry.erases) {
            const json::json_pointer pointer(erase);
            if (json* parent = parentObject(document, pointer)) {
                parent->erase(pointer.back());
            }
        }
        const json::json_pointer pointer(entry.pointer);
        if (json* parent = parentObject(document, pointer)) {
            (*parent)[pointer.back()] = entry.isNumber ? json(entry.number) : json(entry.text);
        }
    }
}

} // namespace hvi::app
