// A field of a structure-of-arrays point set, named once: its member and the name it has in
// checkpoints. Each point set lists its fields (sph/ParticleSet.hpp, fe/FeMesh.hpp) so that
// allocation, checkpoint, restore and the hand-over from an eroded element to its particle
// loop over one list, and adding a field touches that list only.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace hvi {

template <class Set, class T = double>
struct Field {
    std::string_view name; ///< checkpoint name (snake_case)
    std::vector<T> Set::*member;
};

/// True when two lists name the same fields in the same order (for lists that are copied
/// field by field from one point set to another).
template <class A, class B, std::size_t N>
constexpr bool sameNames(const std::array<Field<A>, N>& a, const std::array<Field<B>, N>& b) {
    for (std::size_t i = 0; i < N; ++i) {
        if (a[i].name != b[i].name) {
            return false;
        }
    }
    return true;
}

} // namespace hvi
