// Contact step 2 (contact/KinematicContact.hpp): the constraints of a step, in slave order,
// from the candidates of step 1.
//
// A constraint holds the contact normal n, the inverse effective mass along it
// (1/m_s + sum_k w_k^2 / m_k over the master's nodes k with their footprint shares w_k, the
// radial part dropped for nodes held on the axis; 1/m_s + 1/m_j against a particle j), and
// the approach the step may still make: the gap g - R over dt, which closes it and no more.
// A slave slightly inside (R - g below kRecoverableOverlap of its spacing, left by an
// impulse the passes did not fully balance) separates at kOverlapRecovery (R - g)/dt, so
// overlaps never build up; a deeper one (a surface just exposed by erosion) is only kept
// from growing, since pushing it out would throw the slave. A particle presses on its
// footprint (contact/Footprint.hpp), a node on a point.
//
// Units: mm, us, mg (km/s).
#pragma once

#include "contact/ContactPoints.hpp"
#include "contact/ContactSearch.hpp"
#include "contact/Footprint.hpp"

#include <cstdint>
#include <vector>

namespace hvi::contact {

/// Share of a small overlap removed per step, and the largest overlap (fraction of the
/// slave body's spacing) treated so.
constexpr double kOverlapRecovery = 0.2;
constexpr double kRecoverableOverlap = 0.02;

struct Constraint {
    std::size_t slave = 0; ///< index into the slave list
    Slave sl{};            ///< its state (pointers into the arrays)
    int32_t target = 0;    ///< segment, or -1 - particle index
    std::size_t j = 0;     ///< master particle
    /// Master nodes and their shares (ConstraintSet::footNodes), and the master segments'
    /// shares of the heat (footSegments), from these offsets on.
    std::size_t nodeFirst = 0, nodeCount = 0, segmentFirst = 0, segmentCount = 0;
    double nz = 0.0, nr = 0.0;
    double invSum = 0.0;         ///< inverse effective mass along n [1/mg]
    double allowed = 0.0;        ///< the approach the step may make [km/s]
    double impulse = 0.0;        ///< accumulated over the passes, >= 0 [mg km/s]
    double approachBefore = 0.0; ///< relative normal velocity before the impulses
    bool kicked = false;
};

struct ConstraintSet {
    std::vector<Constraint> list;
    std::vector<Share> footNodes, footSegments;
};

/// The constraints of the candidates `found` for a step dt [us].
ConstraintSet buildConstraints(const ContactPoints& points,
                               const std::vector<SlaveContacts>& found, double dt);

} // namespace hvi::contact
