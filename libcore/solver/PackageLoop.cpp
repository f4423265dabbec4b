#include "solver/PackageLoop.hpp"

#include <algorithm>
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

void PackageLoop::runPhase(Phase which, void (Package::*phase)(double), double dt) {
    for (Package* p : m_packages) {
        const Stopwatch watch;
        (p->*phase)(dt);
        p->book(which, watch.seconds());
    }
}

void PackageLoop::step(double dt) {
    runPhase(Phase::Kick, &Package::kick, dt);
    runPhase(Phase::Constrain, &Package::constrain, dt);
    runPhase(Phase::Drift, &Package::drift, dt);
    runPhase(Phase::Evaluate, &Package::evaluate, dt);
    runPhase(Phase::KickAgain, &Package::kickAgain, dt);
    runPhase(Phase::Finish, &Package::finish, dt);
}

void PackageLoop::prepare(double dtKnown, double cfl) {
    double smallest = std::numeric_limits<double>::infinity();
    for (Package* p : m_packages) {
        const Stopwatch watch;
        p->prepare(dtKnown > 0.0 ? dtKnown : cfl * smallest);
        p->book(Phase::Prepare, watch.seconds());
        smallest = std::min(smallest, p->stableTimeStep());
    }
}

std::vector<std::pair<std::string, PhaseTimes>> PackageLoop::times() const {
    std::vector<std::pair<std::string, PhaseTimes>> out;
    for (const Package* p : m_packages) {
        out.emplace_back(p->name(), p->times());
    }
    return out;
}

void PackageLoop::countBinnedWork(double smallestVote) {
    for (Package* p : m_packages) {
        p->countBinnedWork(smallestVote);
    }
}

std::vector<std::pair<std::string, BinnedWork>> PackageLoop::binnedWork() const {
    std::vector<std::pair<std::string, BinnedWork>> out;
    for (const Package* p : m_packages) {
        if (p->binnedWork().evaluated() > 0.0) {
            out.emplace_back(p->name(), p->binnedWork());
        }
    }
    return out;
}

void PackageLoop::resetTimes() {
    for (Package* p : m_packages) {
        p->resetTimes();
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
