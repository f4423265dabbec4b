// The contact package of the time loop (solver/Package.hpp): it constrains the half-step
// velocities of particles and FE nodes before anything drifts (contact/KinematicContact.hpp),
// and a particle it pushes joins the evolving set (it may have been at rest until then).
//
// Units: mm, us, J.
#pragma once

#include "contact/KinematicContact.hpp"
#include "solver/FePackage.hpp"
#include "solver/Package.hpp"
#include "solver/ParticleState.hpp"

#include <vector>

namespace hvi::solver {

class ContactPackage final : public Package {
public:
    ContactPackage(contact::ContactOptions options, std::vector<contact::ContactBody> bodies,
                   ParticleState& points, FePackage& fe);

    const char* name() const override { return "contact"; }
    double stableTimeStep() const override { return m_contact.stableTimeStep(); }
    void constrain(double dt) override;
    /// Its vote for the first step, for a step of `dtGuess`.
    void prepare(double dtGuess) override;
    void save(io::CheckpointState& state) const override;
    void restore(const io::CheckpointState& state) override;

    contact::KinematicContact& contact() { return m_contact; }
    const contact::KinematicContact& contact() const { return m_contact; }

private:
    contact::KinematicContact m_contact;
    ParticleState& m_points;
    FePackage& m_fe;
};

} // namespace hvi::solver
