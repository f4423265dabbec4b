// The one interface every physics package of the time loop answers (in the spirit of
// Spheral's Physics and Laghos's operators): its time-step vote, its share of each phase of
// the kick-drift-kick step, what it derives from a state before the first step, and its state
// across a checkpoint. Simulation (solver/Simulation.hpp) holds the packages in a fixed order
// and runs every phase over all of them in that order; a package does nothing in a phase it
// has no part in.
//
// The phases of a step of length dt (Simulation.hpp gives the integrator):
//   kick       first half kick with the rates of the start of the step
//   constrain  constraints on the half-step velocities before anything drifts (contact)
//   drift      positions a full step, and the end-of-step prediction with the same rates
//   evaluate   rates at the predicted state
//   kickAgain  second half kick with those rates
//   finish     what follows the step: plasticity, pressures, clamps
// Calls per step: a few per package, none per particle, so the virtual dispatch is free.
//
// Units: us for times.
#pragma once

#include "io/Checkpoint.hpp"
#include "solver/BinnedWork.hpp"
#include "solver/Profile.hpp"

#include <limits>
#include <span>

namespace hvi::solver {

class Package {
public:
    virtual ~Package() = default;

    /// Its name in the time-step limiter and the benchmark ("sph", "fe", "contact").
    virtual const char* name() const = 0;
    /// The largest stable step before the Courant factor [us]; +inf when it sets no limit.
    virtual double stableTimeStep() const { return std::numeric_limits<double>::infinity(); }
    /// The stable step of each point its last evaluation evaluated [us] (+inf: no limit),
    /// whose smallest is stableTimeStep(); empty for a package with no points of its own.
    virtual std::span<const double> pointSteps() const { return {}; }

    virtual void kick(double /*dt*/) {}
    virtual void constrain(double /*dt*/) {}
    virtual void drift(double /*dt*/) {}
    virtual void evaluate(double /*dt*/) {}
    virtual void kickAgain(double /*dt*/) {}
    virtual void finish(double /*dt*/) {}

    /// Derives from the current state what the first step reads (pressures, rates, forces,
    /// its vote). `dtGuess`: the step the packages before it in the order allow [us].
    virtual void prepare(double /*dtGuess*/) {}

    /// Its state into a checkpoint, and back (after the simulation's clock and ledger).
    virtual void save(io::CheckpointState& /*state*/) const {}
    virtual void restore(const io::CheckpointState& /*state*/) {}

    /// Wall time spent in its phases so far [s]: the time loop books each phase, a package
    /// the sections inside them it wants to be seen (solver/Profile.hpp).
    double seconds() const { return m_times.total(); }
    const PhaseTimes& times() const { return m_times; }
    void book(Phase phase, double seconds) { m_times.book(phase, seconds); }
    void resetTimes() {
        m_times = PhaseTimes{};
        m_binned = BinnedWork{};
    }

    /// Counts the points of its last evaluation as time-step bins would step them against
    /// the step's smallest vote of all packages [us] (solver/BinnedWork.hpp).
    void countBinnedWork(double smallestVote) { m_binned.add(pointSteps(), smallestVote); }
    const BinnedWork& binnedWork() const { return m_binned; }

protected:
    void bookSection(std::string_view name, double seconds) { m_times.bookSection(name, seconds); }

private:
    PhaseTimes m_times;
    BinnedWork m_binned;
};

} // namespace hvi::solver
