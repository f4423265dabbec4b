// The thresholds hvi-assess judges material by, in one place (docs/metrics.md explains each).
//
// Three judgements of an item (SPH particle or FE element) of a target body matter:
//   failed   -- it can no longer carry load: deleted or eroded (Alive = 0), Johnson-Cook
//               damage D >= failedDamage, or density below failedDensityRatio * the body's
//               reference density (the solver's minimum-density cut-off: no stress there);
//   in place -- alive, density at least intactDensityRatio * reference, and still near where
//               it started: |z - z0| <= axial window (plate material, failed or not, not
//               debris);
//   intact   -- in place and not failed.
// The defaults are the values documented in docs/metrics.md; the verdict echoes the values
// it used under /criteria.
#pragma once

#include <nlohmann/json.hpp>

namespace hvi::assess {

struct Criteria {
    /// D >= this is failed (the Johnson-Cook damage saturates at 1).
    double failedDamage = 1.0;
    /// rho < this * rho_ref is failed. A negative value means "the scene's
    /// sph.min_density_ratio" (the solver's own cut-off, 0.5 by default).
    double failedDensityRatio = -1.0;
    /// rho >= this * rho_ref is needed to count as plate material in place.
    double intactDensityRatio = 0.8;
    /// Material in place stays within this many plate thicknesses (and at least two particle
    /// spacings) of its initial z.
    double axialWindowThicknesses = 1.0;
    /// A radial bin of the bumper is closed when the mass in place there is at least this
    /// fraction of the bin's original mass (material spans the plate's thickness, on average).
    double holeSpanFraction = 0.5;
    /// Bins of the bumper within this many bin widths of its outer edge are not used (the
    /// free edge or the domain boundary is not the hole).
    int holeEdgeBins = 2;
    /// Material beyond the rear wall's rear surface counts as a perforation only when at least
    /// this many items crossed (one or two SPH particles slipping between the wall's particles
    /// is a known SPH leakage artefact, not a perforation).
    int minCrossingItems = 3;
    /// Failed items closer than this many particle spacings are connected (1.5 links the 8
    /// lattice neighbours, diagonal ones at sqrt(2) spacings).
    double linkSpacings = 1.5;
    /// Sound rear-wall items closer than this many spacings *at their current positions* are
    /// joined (failed ones and eroded-element particles only within linkSpacings): the wall
    /// is the joined set holding most of its material, and a scab is detached once nothing
    /// joins it. 3 keeps lattice neighbours joined up to 100 % stretch (a diagonal pair at
    /// sqrt(2) spacings stretched twice is 2.83 apart), so a thinning bulge or a bent petal
    /// is not cut from the wall.
    double joinSpacings = 3.0;
    /// A perforation lying wholly within this many spacings of the axis is flagged as confined
    /// to the axis (axisymmetric runs). 3: the particle columns within one kernel support
    /// (2 h = 2.6 spacings at the default h = 1.3 spacings) of the axis, whose SPH sums reach
    /// the axis ghosts, rounded up to whole columns.
    double axisBandSpacings = 3.0;
    /// The rear wall bulges (or is dented at its front) when its material in place has moved
    /// this many spacings off its initial face: one spacing is the smallest displacement the
    /// discretisation resolves.
    double bulgeSpacings = 1.0;
    /// Material slower than this is at rest [km/s]. A negative value means "the scene's
    /// run.stop_debris_speed_km_s" (the source study's 0.1 km/s by default, section 5.4), the
    /// speed the solver's stop rules use too.
    double restSpeedKmS = -1.0;
    /// The leading edge of the debris cloud has this fraction of the debris mass ahead of it
    /// (ignores a few stray particles ahead of the cloud).
    double leadingEdgeMassFraction = 1.0e-3;
    /// The leading-edge speed is the mass-weighted axial speed of this front fraction of the
    /// debris mass.
    double frontMassFraction = 0.01;

    nlohmann::json toJson() const;
};

} // namespace hvi::assess
