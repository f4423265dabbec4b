// hvi-assess's rear-wall perforation rule (assess/RearWallPerforation.hpp) on the live state
// of a run: the stop rule "rear_wall_perforated" (solver/StopRules.hpp) stops a run only once
// the assessment of that very state finds the wall perforated. The stop rule's own detector
// (material of another body behind the wall's rear face where the wall has a hole) is cheap
// and runs every few steps; it only says when to ask this one. Without the confirmation a
// stray particle past a wall that holds stopped the run, and hvi-assess then found no
// perforation and could only call the NP provisional.
//
// Units: mm, us.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/ShieldLayout.hpp"
#include "fe/FeSolid.hpp"
#include "io/RunFileReader.hpp"
#include "scene/Scene.hpp"
#include "sph/ParticleSet.hpp"

namespace hvi::solver {

/// The state as hvi-assess reads it from a run file's snapshot.
io::Snapshot snapshotOf(double timeUs, long step, const sph::ParticleSet& ps,
                        const fe::FeSolid* fe);

class RearWallConfirmation {
public:
    /// `ps`, `fe`: the state at the start of the run (the material frame of the rule).
    RearWallConfirmation(const scene::Scene& scene, const sph::ParticleSet& ps,
                         const fe::FeSolid* fe);

    /// Whether the rule finds the rear wall perforated (false without a rear wall).
    bool perforated(double timeUs, long step, const sph::ParticleSet& ps,
                    const fe::FeSolid* fe) const;

private:
    io::Snapshot m_first;
    assess::ShieldLayout m_layout;
    assess::Criteria m_criteria; ///< hvi-assess's defaults
};

} // namespace hvi::solver
