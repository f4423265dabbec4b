// One snapshot's material as a flat list of "items" that every metric reads the same way:
// the SPH particles first, then the finite-element quads (FE bodies are optional; a
// snapshot without a mesh simply has no element items).
//
// Each item has its current position and velocity, its reference (initial) position, mass,
// density, damage, body and whether it is still in the calculation. For an element these
// are its centroid (mean of its 4 nodes), the mean nodal velocity, and the share of its
// nodes' lumped masses (a node's mass split evenly among the elements using it).
//
// Reference positions are the item's position in the run's first snapshot: the solver keeps
// every particle's slot for the whole run (deleted particles keep their last state with
// Alive = 0), so particle i of any snapshot is particle i of the first. A particle made of
// an eroded element has, as its reference, the centroid of that element at the start. When the counts differ
// (a file not written that way), hasReference is false and the metrics fall back to the
// scene's geometry; the verdict says so.
//
// Units: mm, km/s, mg, g/cm3.
#pragma once

#include "assess/ShieldLayout.hpp"
#include "io/RunFileReader.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi::assess {

struct MaterialItems {
    double timeUs = 0.0;
    std::vector<double> z, r;   ///< current position [mm]
    std::vector<double> z0, r0; ///< position in the first snapshot [mm] (current if none)
    std::vector<double> vz, vr; ///< [km/s]
    std::vector<double> mass;   ///< [mg] (whole ring in axisymmetric runs)
    std::vector<double> density;
    std::vector<double> damage; ///< 0 where the run has no damage field
    std::vector<std::int32_t> body;
    std::vector<std::uint8_t> alive;
    std::size_t particleCount = 0; ///< items [0, particleCount) are particles, then elements
    bool hasReference = false;

    std::size_t size() const { return z.size(); }
    bool isElement(std::size_t i) const { return i >= particleCount; }
};

/// The items of `snapshot`, with reference positions from `first` (the run's first
/// snapshot; may be the same object). Unused particle slots (sph::isUnusedSlot) are left
/// out.
MaterialItems materialItems(const io::Snapshot& snapshot, const io::Snapshot& first);

} // namespace hvi::assess
