// A short fingerprint of a byte string: the 64-bit FNV-1a hash (Fowler, Noll, Vo; the
// parameters of the IETF draft "The FNV Non-Cryptographic Hash Algorithm") as 16 hex digits.
// For telling whether two texts are the same (a checkpoint and the scene that resumes it),
// not for security.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace hvi::core {

inline std::string fingerprint(std::string_view bytes) {
    std::uint64_t hash = 14695981039346656037ULL; // offset basis
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 1099511628211ULL; // FNV prime
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

} // namespace hvi::core
