#include "solver/PackageLoop.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

namespace hvi::solver {

PackageLoop::Vote PackageLoop::smallestVote() const {
    Vote vote{nullptr, std::numeric_limits<double>::infinity()};
    for (const Package* p : m_packages) {
        const double dt = p->stableTimeStep();
        if (!vote.limiter || dt < vote.dt) {
            vote = {p, dt};
        }
    }
    return vote;
}

void PackageLoop::runPhase(void (Package::*phase)(double), double dt) {
    using WallClock = std::chrono::steady_clock;
    for (Package* p : m_packages) {
        const auto t0 = WallClock::now();
        (p->*phase)(dt);
        p->book(std::chrono::duration<double>(WallClock::now() - t0).count());
    }
}

void PackageLoop::step(double dt) {
    runPhase(&Package::kick, dt);
    runPhase(&Package::constrain, dt);
    runPhase(&Package::drift, dt);
    runPhase(&Package::evaluate, dt);
    runPhase(&Package::kickAgain, dt);
    runPhase(&Package::finish, dt);
}

void PackageLoop::prepare(double dtKnown, double cfl) {
    double smallest = std::numeric_limits<double>::infinity();
    for (Package* p : m_packages) {
        p->prepare(dtKnown > 0.0 ? dtKnown : cfl * smallest);
        smallest = std::min(smallest, p->stableTimeStep());
    }
}

void PackageLoop::save(io::CheckpointState& state) const {
    for (const Package* p : m_packages) {
        p->save(state);
    }
}

void PackageLoop::restore(const io::CheckpointState& state) {
    for (Package* p : m_packages) {
        p->restore(state);
    }
}

} // namespace hvi::solver
