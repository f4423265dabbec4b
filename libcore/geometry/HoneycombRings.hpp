// Hexagonal honeycomb core -> concentric cylindrical rings for the 2D axisymmetric hydrocode.
//
// Source: the thesis (see FoamLayerStack.hpp) §4.1, after Cherniaev: the honeycomb core of
// height H becomes thin annuli of height H around the impact axis. Why: a 2D axisymmetric
// model cannot hold hexagons, and the walls that matter to the expanding debris cloud are
// those it meets going outwards; walls lying along the radial direction do little to it and
// are dropped. The reduced core therefore carries LESS mass than the real one: both areal
// masses and their ratio are reported so that a designer sees it.
//
// Tiling and frame. Regular hexagons, D = cell size across flats (flat-to-flat), side
// l = D/√3, cell area (√3/2)·D². x runs along W (normal to the ribbon walls), y along the
// ribbon direction L. Cell centres are D·(i + k/2, k·√3/2), i, k integers; the impact cell is
// (0, 0). The walls form three families by their unit normals: family 0, normal (1, 0): the
// ribbon walls, parallel to L; families 1 and 2, normals at 60° and 120°: the slanted walls.
//
// Double walls. In expanded honeycomb two foil sheets are bonded along the ribbon walls, so
// family 0 is double foil. ASSUMPTION: family-0 walls have the mean thickness (1 + φ)·t_f with
// φ = double_wall_fraction (default 1: every ribbon wall double, standard expanded core;
// 0: all walls single foil); families 1 and 2 have t_f.
//
// Real core density (thin-wall, first order in t/l). Per cell there are 3 walls (6 sides, each
// shared by 2 cells), one of each family, each of length l, so the solid area per cell is
// l·t_f·(3 + φ) and
//     ρ*/ρ_foil = l·t_f·(3 + φ) / ((√3/2)·D²) = (2/3)·(3 + φ)·t_f/D,
// i.e. (8/3)·t_f/D for φ = 1 and 2·t_f/D = (2/√3)·(t_f/l) for φ = 0. This is Gibson & Ashby,
// "Cellular Solids", 2nd ed. (Cambridge UP, 1997), ch. 4, relative density of a hexagonal
// honeycomb, ρ*/ρs = (t/l)(h/l + 2)/(2 cos θ (h/l + sin θ)), at h = l, θ = 30°, with the h-walls
// of thickness (1 + φ)t ((h/l + 2) becoming ((1 + φ)h/l + 2)). The O((t/l)²) correction for
// the wall overlap at the nodes is dropped: for t/D ≈ 0.005 it is below 0.3 %, and the rings
// are thin-wall volumes too. Real areal mass = ρ_foil · ρ*/ρ_foil · H.
//
// Ring radii. A ray from the impact point in a chosen direction is intersected with the
// tiling; every wall crossing at distance r becomes a ring of mid-radius r and thickness
// equal to the wall's thickness. The crossings are computed, not tabulated: the hexagonal
// tiling is the Voronoi diagram of the cell centres, so a point lies on a wall of family j
// exactly when its nearest cell centres include two that differ by one lattice step along
// that family's normal. Each family's walls lie on the lines n_j·x = m·D/2; the ray is
// intersected with every such line out to the domain radius and each intersection is kept
// if it passes that test. Hence any impact point (cell centre, on a wall, any offset) and
// any direction work.
//   Degenerate cases, by rule:
//   - a family parallel to the ray contributes no crossing (a ray running along a wall
//     does not cross it);
//   - a ray through a wall junction (node) crosses there once, with the mean thickness of
//     the walls that meet there and are not along the ray (the limit of rays passing just
//     either side of the node); atNode marks such rings;
//   - a wall through the impact point (crossing at r = 0) becomes an axial rod of radius
//     thickness/2, the only axisymmetric body a wall on the axis can map to.
//
// Direction rule (RingDirection), angles from +x (W):
//   Apothem (default), 0°: normal to the ribbon walls. From a cell centre the rings are at
//     D/2, 3D/2, 5D/2, ... all ribbon walls, thickness (1 + φ)t_f. Chosen as the default
//     because its first ring is the nearest wall of the impact cell (D/2, the inscribed
//     radius) and its series is the simplest; it was also the rule suggested when this
//     module was specified.
//   Vertex, 30°: towards a wall junction. From a cell centre the ray passes through nodes
//     only, at l, 2l, 4l, 5l, 7l, ... (running along a slanted wall between l and 2l),
//     thickness (t_f(1 + φ) + t_f)/2.
//   Custom: any angle (ring_angle_deg); 60° gives the apothem of a slanted-wall family.
//   No direction reproduces the isotropic mean crossing rate 4/(πD) ≈ 1.27/D (wall length
//   per area 2/D times 2/π): Apothem gives 1/D, Vertex 2/(√3·D) ≈ 1.15/D. Averaging the two
//   directions was not offered: their crossing series have different counts and no pairing.
//
// Rings are kept while their outer radius is ≤ the domain radius R. Reduced areal mass =
// ρ_foil · Σ π(r_out² − r_in²)·H / (π R²).
//
// Units: lengths mm, densities g/cm³, angles degrees in the inputs.
#pragma once

#include "geometry/GeometryWarning.hpp"
#include "geometry/InputChecks.hpp"
#include "scene/Defaults.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::geometry {

/// Direction of the ray whose wall crossings give the ring radii (see the file comment).
/// JSON: "apothem", "vertex", "custom".
enum class RingDirection { Apothem, Vertex, Custom };

/// Where the shot line meets the tiling. JSON: "cell_centre", "cell_wall", "offset".
enum class ImpactSite {
    CellCentre, ///< centre of cell (0, 0)
    CellWall,   ///< middle of the ribbon wall at x = D/2 (the one the Apothem ray meets)
    Offset,     ///< impact_offset_x_mm, impact_offset_y_mm from the centre of cell (0, 0)
};

/// The honeycomb core and the choices of the reduction. Each field's comment gives its JSON
/// key, which is also the key named in InputError pointers (prefix + "/" + key).
struct HoneycombCoreSpec {
    // Required (left at kMissing they are reported as missing).
    double coreThicknessMm = kMissing; ///< core_thickness_mm: height H [mm], > 0
    double cellSizeMm = kMissing;      ///< cell_size_mm: D across flats [mm], > 0
    double foilThicknessMm = kMissing; ///< foil_thickness_mm: t_f [mm], 0 < t_f < D/2
    double foilDensityGCm3 = kMissing; ///< foil_density_g_cm3 [g/cm^3], > 0
    double domainRadiusMm = kMissing;  ///< domain_radius_mm: outer radius of the model [mm]

    // Optional.
    double doubleWallFraction = 1.0;                  ///< double_wall_fraction: φ, [0, 1]
    ImpactSite impactSite = ImpactSite::CellCentre;   ///< impact_site
    double impactOffsetXMm = kMissing;                ///< impact_offset_x_mm (Offset only)
    double impactOffsetYMm = kMissing;                ///< impact_offset_y_mm (Offset only)
    RingDirection direction = RingDirection::Apothem; ///< ring_direction
    double ringAngleDeg = kMissing;                   ///< ring_angle_deg (Custom only), from +x
    /// particle_spacing_mm: SPH resolution the warnings are judged against; default the
    /// thesis' calibrated 2D particle size (thesis_cases.json calibration).
    double particleSpacingMm = scene::kDefaultParticleSpacingMm;
};

/// One ring: an annulus of height H around the impact axis.
struct HoneycombRing {
    double radiusMm;      ///< where the ray crosses the wall: the ring's mid-surface
    double innerRadiusMm; ///< radiusMm − thicknessMm/2, clipped at 0 (then an axial rod)
    double outerRadiusMm; ///< radiusMm + thicknessMm/2
    double thicknessMm;   ///< wall thickness at the crossing
    double zFrontMm;      ///< 0: the rear face of the front facesheet
    double zBackMm;       ///< H
    bool atNode;          ///< the ray crossed at a wall junction
};

/// The reduced core.
struct HoneycombRings {
    std::vector<HoneycombRing> rings; ///< by increasing radius
    RingDirection direction = RingDirection::Apothem;
    double angleDeg = 0.0;  ///< the ray direction used, from +x (W)
    double impactXMm = 0.0; ///< the impact point used, from the centre of cell (0, 0)
    double impactYMm = 0.0;
    double relativeDensity = 0.0;   ///< ρ*/ρ_foil = (2/3)(3 + φ) t_f/D
    double coreDensityGCm3 = 0.0;   ///< ρ_foil · relativeDensity
    double realArealMassGCm2 = 0.0; ///< coreDensity · H
    double reducedArealMassGCm2 = 0.0;
    double massRatio = 0.0; ///< reduced / real
    std::vector<GeometryWarning> warnings;
};

/// Reduces a honeycomb core to rings. Throws hvi::InputError listing every invalid input,
/// each located at pointerPrefix + "/" + key in `file`; also when no ring of positive radius
/// fits inside the domain radius.
HoneycombRings buildHoneycombRings(const HoneycombCoreSpec& spec,
                                   const std::string& file = "<input>",
                                   const std::string& pointerPrefix = "");

/// Relative density of the regular hexagonal core, (2/3)(3 + φ)·t_f/D (file comment).
double honeycombRelativeDensity(double cellSizeMm, double foilThicknessMm,
                                double doubleWallFraction);

std::string_view toString(RingDirection direction);
std::string_view toString(ImpactSite site);
/// "apothem" | "vertex" | "custom"; nothing for anything else.
std::optional<RingDirection> parseRingDirection(std::string_view text);
/// "cell_centre" | "cell_wall" | "offset"; nothing for anything else.
std::optional<ImpactSite> parseImpactSite(std::string_view text);

} // namespace hvi::geometry
