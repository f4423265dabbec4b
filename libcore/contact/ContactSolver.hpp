// Contact step 3 (contact/KinematicContact.hpp): the normal impulses of a step's constraints,
// solved together.
//
// Resolving the constraints one after another in a single pass is not the simultaneous
// solution: a master node shared by two slaves takes its share of the first one resolved as
// if that slave were alone, and the second one's impulse on the same node comes on top, so
// the result follows the order. A uniform FE plate striking another (2 km/s, RZ) left the
// struck surface's nodes at 0.891 km/s on the axis down to 0.848 km/s at r = 0.28 mm one
// step after touching, and the axis element with 71 % more plastic strain than its
// neighbours (tests/verification/FeContact_test.cpp); solved together, 0.917 to 0.909 and
// +4 %. Projected Gauss-Seidel (the sequential-impulse method, Catto E. (2005), "Iterative
// dynamics with temporal coherence", GDC) repeats the passes, and each constraint may hand
// back part of the impulse it holds (its accumulated impulse stays >= 0: contact pushes,
// never pulls), so the passes converge to the simultaneous inelastic solution. They stop
// when no constraint changes its relative normal velocity by more than kPassTolerance, or
// after kMaxPasses; the order is fixed, so the result does not depend on the thread count.
//
// Units: mm, us, mg (km/s).
#pragma once

#include "contact/ContactConstraints.hpp"

namespace hvi::contact {

constexpr int kMaxPasses = 20;
constexpr double kPassTolerance = 1e-6; ///< [km/s]

/// The slave's normal velocity relative to its master (the footprint's weighted nodes, or
/// the master particle) [km/s]: negative when approaching.
double normalVelocity(const ContactPoints& points, const ConstraintSet& set,
                      const Constraint& con);

/// Sets each constraint's approachBefore, then its impulse by the passes, kicking the
/// slaves' and masters' velocities.
void solveImpulses(const ContactPoints& points, ConstraintSet& set);

} // namespace hvi::contact
