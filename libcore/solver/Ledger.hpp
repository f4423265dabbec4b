// The conservation ledger: what the run started with, what the deletion rules and erosion
// took out of it, and the totals at any instant, so that the energy error
// (E + E_deleted - E0) / E0 measures the integrator and not the bookkeeping.
//
// Units: J (planar scenes: J/mm), mg, mg km/s.
#pragma once

#include "contact/KinematicContact.hpp"
#include "fe/FeSolid.hpp"
#include "sph/ParticleSet.hpp"

#include <cstddef>

namespace hvi::solver {

/// Conservation ledger at one instant.
struct Totals {
    double kinetic = 0.0;       ///< particles and nodes [J] (planar: J/mm)
    double internal = 0.0;      ///< particles and alive elements [J]
    double deletedEnergy = 0.0; ///< deleted particles and free nodes, eroded elements [J]
    double mass = 0.0;          ///< alive mass (particles and nodes) [mg]
    double deletedMass = 0.0;   ///< [mg]
    double momentumZ = 0.0;     ///< alive z-momentum [mg km/s]
    double deletedMomentumZ = 0.0;
    std::size_t alive = 0, deleted = 0, active = 0; ///< particles
    std::size_t erodedElements = 0;
};

/// Why a point left the run (solver/DeletionRule.hpp).
enum class DeletionReason { Runaway, OutOfDomain };

class Ledger {
public:
    /// The ledger's own account, as a checkpoint keeps it. The eroded elements' energy and
    /// the free nodes' heat are kept by the FE and contact packages.
    struct Account {
        double initialEnergy = 0.0;
        double deletedEnergy = 0.0;    ///< deleted particles and free nodes [J]
        double deletedMass = 0.0;      ///< [mg]
        double deletedMomentumZ = 0.0; ///< [mg km/s]
        std::size_t runaway = 0, outOfDomain = 0;
    };

    void setInitialEnergy(double energy) { m_account.initialEnergy = energy; }
    /// Books a deleted point: its mass [mg], axial velocity [km/s] and specific energy
    /// (kinetic and internal) [MJ/kg].
    void remove(double mass, double vz, double specificEnergy, DeletionReason reason) {
        m_account.deletedEnergy += mass * specificEnergy;
        m_account.deletedMass += mass;
        m_account.deletedMomentumZ += mass * vz;
        ++(reason == DeletionReason::Runaway ? m_account.runaway : m_account.outOfDomain);
    }

    const Account& account() const { return m_account; }
    void restore(const Account& account) { m_account = account; }

    /// The totals of the particles, the FE nodes and elements (null without FE bodies), with
    /// `active` the particle count of the last evaluation.
    Totals totals(const sph::ParticleSet& particles, const fe::FeSolid* fe,
                  const contact::KinematicContact* contact, std::size_t active) const;
    /// (E + E_deleted - E0) / |E0| for totals of this ledger (E0 = 0: the absolute error).
    double energyError(const Totals& t) const;

private:
    Account m_account;
};

} // namespace hvi::solver
