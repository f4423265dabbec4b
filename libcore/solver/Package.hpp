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
#include "solver/Profile.hpp"

#include <limits>

namespace hvi::solver {

class Package {
public:
    virtual ~Package() = default;

    /// Its name in the time-step limiter and the benchmark ("sph", "fe", "contact").
    virtual const char* name() const = 0;
    /// The largest stable step before the Courant factor [us]; +inf when it sets no limit.
    virtual double stableTimeStep() const { return std::numeric_limits<double>::infinity(); }

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
    void resetTimes() { m_times = PhaseTimes{}; }

protected:
    void bookSection(std::string_view name, double seconds) { m_times.bookSection(name, seconds); }

private:
    PhaseTimes m_times;
};

} // namespace hvi::solver
