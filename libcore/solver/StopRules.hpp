// The stop rules of a run (source study section 5.4, with the rear-wall wait of issue #26):
// the end time and the step cap; the rear wall perforated (optional; as hvi-assess judges it,
// solver/RearWallConfirmation.hpp, once the detector below flags it); the debris slower than
// the stop speed; and no new body penetrated for a window while nothing advances, unless
// material still moves toward or in the rear wall faster than the stop speed.
//
// A body counts as penetrated when material of other bodies lies behind its initial rear face:
// one item for an SPH body; for an FE body (which bulges without breaking) as many items as
// hvi-assess asks of material crossing a rear wall (assess::Criteria::minCrossingItems), and
// only in a radial bin, one element wide, where the body has no meshed material left (a hole).
//
// Units: mm, us, km/s.
#pragma once

#include "fe/FeMesh.hpp"
#include "scene/Scene.hpp"
#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hvi::solver {

class StopRules {
public:
    /// `spacing[b]`: body b's particle spacing or element size [mm].
    StopRules(const scene::Scene& scene, std::vector<double> spacing);

    /// Penetration and progress with the state at `time` [us] (nodes null without FE bodies).
    void update(double time, const sph::ParticleSet& ps, const fe::NodeSet* nodes);
    /// The rule that fires at (time, step), if any ("end_time", "max_steps",
    /// "rear_wall_perforated", "debris_stopped", "no_new_penetration").
    std::optional<std::string> reason(double time, long step) const;

    const std::vector<uint8_t>& penetrated() const { return m_penetrated; }

    /// The rule stops on perforation and the detector finds the rear wall penetrated, but
    /// hvi-assess's rule has not confirmed it on the run's state yet
    /// (solver/RearWallConfirmation.hpp): "rear_wall_perforated" waits for the confirmation.
    bool awaitsRearWallConfirmation() const;
    void confirmRearWallPerforation() { m_rearWallConfirmed = true; }
    bool rearWallConfirmed() const { return m_rearWallConfirmed; }
    double lastProgressTime() const { return m_lastProgressTime; }

private:
    /// Whether body b has material of other bodies behind its rear face.
    bool penetratedNow(std::size_t b, const sph::ParticleSet& ps, const fe::NodeSet* nodes) const;
    /// An item of the rear wall moving faster than `speed` [km/s], or an item of another body
    /// in front of the wall's rear face, within its radial extent, moving toward it faster.
    bool rearWallActive(double speed, const sph::ParticleSet& ps, const fe::NodeSet* nodes) const;

    std::vector<scene::Body> m_bodies;
    scene::RunControls m_run;
    std::vector<double> m_spacing;
    double m_minSpacing = 0.0;

    std::vector<uint8_t> m_penetrated;
    double m_lastProgressTime = 0.0;
    double m_progressFront = -1e300;
    double m_progressCentre = -1e300; ///< furthest centre of mass of the moving material
    double m_debrisSpeed = 0.0;       ///< fastest forward speed of any alive point [km/s]
    /// The no-new-penetration rule waits while this holds (rearWallActive).
    bool m_rearWallActive = false;
    bool m_rearWallConfirmed = false;
};

} // namespace hvi::solver
