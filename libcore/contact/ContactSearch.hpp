// Contact step 1 (contact/KinematicContact.hpp): for every slave, the master segments (and,
// for a free node, the master particles) it approaches and may reach within the step, and
// its time-step vote.
//
// A slave at signed distance g from a segment of another body (a particle may meet its own
// body's surface: one made of an eroded element stays outside the rest of its body), with
// g > -l/2 (l: the master body's element size) and projection in [0, 1], approaching at
// normal speed v_n > 0, votes dt <= (c/2) / v_n (c: the search cell) so no approach
// outruns the search, and is a candidate when g - R < v_n dt. Found in parallel, one slave
// per task, each slave's candidates in the grid's cell order: the result does not depend on
// the thread count.
//
// Units: mm, us, km/s.
#pragma once

#include "contact/ContactPoints.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace hvi::contact {

/// The most candidates kept per slave (the first found, in the grid's order).
constexpr int kMaxContactsPerSlave = 4;

/// One slave's candidate contacts of this step.
struct SlaveContacts {
    int count = 0;
    std::array<int32_t, kMaxContactsPerSlave> target{}; ///< segment, or -1 - particle index
    double dt = std::numeric_limits<double>::infinity(); ///< the slave's time-step vote [us]
};

/// Candidates of every slave (indexed as ContactPoints' slaves) for a step dt, with a
/// search cell of cellSize [mm].
std::vector<SlaveContacts> findCandidates(const ContactPoints& points, double dt,
                                          double cellSize);

} // namespace hvi::contact
