// The deletion rule: a point leaves the run when it outruns every initial speed by the scene's
// runaway factor (sph.runaway_speed_factor: a numerical jet, not debris) or leaves the domain
// box (scene domain, or the bodies' extent with room behind for the debris). Particles and the
// FE nodes no element holds any more ("free nodes") obey the same rule; the ledger books what
// they carried. A non-finite state is a failure of the run, not a deletion.
//
// Units: mm, km/s.
#pragma once

#include "fe/FeMesh.hpp"
#include "scene/Scene.hpp"
#include "solver/Ledger.hpp"
#include "sph/ParticleSet.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace hvi::solver {

struct DeletionRule {
    double runawaySpeed = 0.0;                 ///< [km/s]; +inf when nothing moves at the start
    double zMin = 0.0, zMax = 0.0, rMax = 0.0; ///< the domain box [mm]

    /// From the scene: the runaway factor times the fastest initial speed; the domain box,
    /// by default from 2 projectile lengths in front of the bodies to 5 mm behind them.
    static DeletionRule of(const scene::Scene& scene);

    /// Why a point at (z, r) moving with |v|^2 = v2 [km^2/s^2] must go, if it must.
    std::optional<DeletionReason> reason(double z, double r, double v2) const {
        if (v2 > runawaySpeed * runawaySpeed) {
            return DeletionReason::Runaway;
        }
        if (z < zMin || z > zMax || std::fabs(r) > rMax) {
            return DeletionReason::OutOfDomain;
        }
        return std::nullopt;
    }
};

/// What the deletion pass needs to name a point whose state stopped being finite.
struct RunClock {
    double time = 0.0; ///< [us]
    long step = 0;
};

/// Deletes the particles the rule removes among `items` (all particles when null), books
/// them in the ledger and returns how many went. Throws RuntimeFailure on a non-finite state.
std::size_t deleteParticles(sph::ParticleSet& ps, const std::vector<int32_t>* items,
                            const DeletionRule& rule, const scene::Scene& scene, RunClock clock,
                            Ledger& ledger);

/// The same for the free nodes (nodes of no alive element); every alive node is checked for
/// a finite state.
void deleteFreeNodes(fe::NodeSet& nodes, const DeletionRule& rule, const scene::Scene& scene,
                     RunClock clock, Ledger& ledger);

} // namespace hvi::solver
