// The packages of a time loop in their fixed order (solver/Package.hpp) and what is done to
// all of them at once: the time-step vote, the six phases of a kick-drift-kick step, the
// preparation before the first step, and checkpoint and restore. Simulation adds the clock,
// the deletion rule, the ledger and the stop rules around it.
//
// Units: us.
#pragma once

#include "io/Checkpoint.hpp"
#include "solver/Package.hpp"

#include <string>
#include <utility>
#include <vector>

namespace hvi::solver {

/// The time step grows by at most this factor from one step to the next: a sudden jump after
/// a quiet phase would skip the first steps of a new contact.
inline constexpr double kMaxDtGrowth = 1.25;

class PackageLoop {
public:
    /// Appends a package (not owned); phases run in the order of the calls.
    void add(Package& package) { m_packages.push_back(&package); }

    struct Vote {
        const Package* limiter = nullptr; ///< the first package with the smallest vote
        double dt = 0.0;                  ///< its vote [us] (+inf: nothing limits)
    };
    /// The smallest vote; a tie goes to the package added first.
    Vote smallestVote() const;

    /// One step of length dt: kick, constrain, drift, evaluate, kickAgain, finish, each over
    /// every package in order, booking each package's wall time.
    void step(double dt);

    /// Prepares every package in order. A package's first vote may depend on the step the
    /// ones before it allow (contact's on the SPH and FE steps): each is given `dtKnown` when
    /// positive, else cfl times the smallest vote of the packages before it.
    void prepare(double dtKnown, double cfl);

    /// Each package's wall time so far, by phase and section, in loop order.
    std::vector<std::pair<std::string, PhaseTimes>> times() const;
    /// Every package counts its last evaluation's points as time-step bins would step them
    /// against `smallestVote` [us]; and what each has counted so far, in loop order, for the
    /// packages with points of their own.
    void countBinnedWork(double smallestVote);
    std::vector<std::pair<std::string, BinnedWork>> binnedWork() const;
    void resetTimes();

    void save(io::CheckpointState& state) const;
    void restore(const io::CheckpointState& state);

private:
    void runPhase(Phase which, void (Package::*phase)(double), double dt);

    std::vector<Package*> m_packages;
};

} // namespace hvi::solver
