// A point set's listed fields (core/FieldList.hpp) into and out of a checkpoint, each array
// named prefix + the field's name, so that what a package keeps across a resume is written
// once, in its field list. A missing array or one of another length is an input error naming
// the array.
#pragma once

#include "core/Error.hpp"
#include "core/FieldList.hpp"
#include "io/Checkpoint.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::io {

template <class Set, std::size_t N>
void putFields(CheckpointState& s, std::string_view prefix, const Set& set,
               const std::array<Field<Set>, N>& fields) {
    for (const auto& f : fields) {
        s.doubles[std::string(prefix) + std::string(f.name)] = set.*f.member;
    }
}

/// The array `name` of `arrays` (a checkpoint's doubles or ints) into `into`, which must
/// have its length already.
template <class T>
void takeArrayFrom(const std::map<std::string, std::vector<T>>& arrays, const std::string& name,
                   std::vector<T>& into) {
    auto it = arrays.find(name);
    if (it == arrays.end() || it->second.size() != into.size()) {
        throw InputError("<checkpoint>", "/" + name, "missing or wrong size",
                         "a checkpoint written by this version of hvi-run");
    }
    into = it->second;
}

inline void takeArray(const CheckpointState& s, const std::string& name,
                      std::vector<double>& into) {
    takeArrayFrom(s.doubles, name, into);
}

inline void takeArray(const CheckpointState& s, const std::string& name,
                      std::vector<int32_t>& into) {
    takeArrayFrom(s.ints, name, into);
}

template <class Set, std::size_t N>
void takeFields(const CheckpointState& s, std::string_view prefix, Set& set,
                const std::array<Field<Set>, N>& fields) {
    for (const auto& f : fields) {
        takeArray(s, std::string(prefix) + std::string(f.name), set.*f.member);
    }
}

/// Byte flags (alive, in contact) travel as int32 arrays.
inline void putFlags(CheckpointState& s, const std::string& name,
                     const std::vector<uint8_t>& flags) {
    s.ints[name] = std::vector<int32_t>(flags.begin(), flags.end());
}

inline void takeFlags(const CheckpointState& s, const std::string& name,
                      std::vector<uint8_t>& into) {
    auto it = s.ints.find(name);
    if (it == s.ints.end() || it->second.size() != into.size()) {
        throw InputError("<checkpoint>", "/" + name, "missing or wrong size",
                         "a checkpoint written by this version of hvi-run");
    }
    for (std::size_t i = 0; i < into.size(); ++i) {
        into[i] = static_cast<uint8_t>(it->second[i]);
    }
}

/// A time step kept in `extra` [us]; +inf (nothing to limit) goes through JSON as null.
inline double timeStepOf(const CheckpointState& s, const char* key) {
    const auto& v = s.extra.at(key);
    return v.is_number() ? v.get<double>() : std::numeric_limits<double>::infinity();
}

} // namespace hvi::io
