// Bumper hole diameter: THE validation metric of the source study (measured 6.7 mm for a
// 3.125 mm Al sphere at 6.847 km/s on a 0.8 mm Al plate).
//
// Definition (docs/metrics.md, "Bumper hole diameter"). The bumper's initial radial extent is
// cut into rings ("bins") one particle spacing wide, aligned with the particle lattice. For
// each bin, the *in-place fraction* is the mass of bumper material still in place
// (MaterialState.hpp: alive, density >= 0.8 rho_ref, within one plate thickness of its
// initial z; failed or not) whose current radius falls in the bin, divided by the bin's
// original mass. A bin is closed when that fraction is >= 0.5: on average plate material
// still spans the plate's thickness there. The hole radius r_h is where the fraction crosses
// 0.5 beyond the outermost open bin (linear interpolation between that bin's centre and the
// next), so that every bin beyond r_h is closed; the diameter is 2 r_h (0 when no bin is
// open). Bins within two widths of the bumper's outer edge are ignored (free edge, domain
// boundary).
//
// This is the clear hole, as measured on a recovered plate or on the material plots of the
// source study: the torn, rolled lip is plate even where the failure model has failed it.
// The same construction with *intact* material only (in place and not failed) gives the
// diameter of the failed zone around the hole, reported beside it.
//
// Why this is robust for SPH: loose debris is excluded because it has moved away or expanded;
// petals and a thickened lip count as plate; and a fraction threshold on ring mass does not
// depend on where single particles sit within a bin, so the result moves by less than a
// spacing when the resolution changes. Mass is the whole-ring mass in axisymmetric runs, so
// the fraction is an areal-density ratio.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <optional>
#include <vector>

namespace hvi::assess {

/// One hole edge found from a fraction profile.
struct HoleEdge {
    double diameterMm = 0.0;
    bool reachesEdge = false; ///< open up to the last usable bin: the hole may be larger
};

struct BumperHole {
    double diameterMm = 0.0; ///< the clear hole (material in place)
    bool reachesEdge = false;
    double failedZoneDiameterMm = 0.0; ///< the same with intact material only
    double binWidthMm = 0.0;
    std::vector<double> binCentreMm;
    std::vector<double> inPlaceFraction, intactFraction;
};

/// The bumper hole in one snapshot; nullopt when the scene has no bumper body.
std::optional<BumperHole> bumperHole(const MaterialItems& items, const ShieldLayout& layout,
                                     const Criteria& criteria);

/// The hole edge of a fraction profile over bins of width `binWidth` starting at `rMin`
/// (exposed for tests).
HoleEdge holeEdge(const std::vector<double>& fraction, double rMin, double binWidth,
                  const Criteria& criteria);

} // namespace hvi::assess
