// Open-cell foam core -> flat solid layers for the 2D axisymmetric hydrocode.
//
// Source: the thesis "Modelling of Hypervelocity Impact on Foam-Core Sandwich Panel with
// Enhanced Capability for Orbital Debris Protection" (University of Manitoba), §4.2 and §5.4,
// eqs 26, 30, 31. Eqs 26 and 31 are used as quoted in shared/validation/thesis_cases.json
// ("notes", with the layer counts the thesis used) and shared/reference/ble-equations.md §9;
// the text of eq 30 is not in this project's references, so the pore count below follows the
// notes ("effective PPI = half the real PPI, pores rounded up, layers = pores - 1").
// Why the reduction exists: a 3D foam mesh costs
// weeks of hydrocode time, while a 2D axisymmetric stack of plates costs minutes. A fragment
// crossing the core meets only about half of the ligament planes on its way (thesis: ~49 %),
// so the stack uses an *effective* PPI = ppi_factor × PPI (default 0.5).
//
// The reduction, lengths in mm, z along the shot line:
//   t_solid = (relative_density_percent / 100) · S                       (eq 26)
//   x       = PPI_eff · S[in]            pores across the core, exact
//   pores   = ceil(x), where x within 1e-9 of an integer counts as that integer
//             (rounding *up*: rounding the 10 PPI, 0.5 in panel's 2.5 pores down to 2 gave
//             a single 0.889 mm layer and the wrong verdict in the thesis; the 1e-9 guard
//             keeps 20 PPI_eff × 2 in from becoming 41 pores through floating-point noise)
//   n       = pores − 1 layers, spacing p = S / pores
//
// Layer positions — convention: CENTRE-SPACED. z is measured from the rear face of the front
// facesheet (z = 0) to the front face of the rear facesheet (z = S); layer k = 1..n has its
// mid-plane at z_k = k·p and spans z_k ± t/2. The gaps are therefore p − t between layers and
// p − t/2 between a facesheet and its neighbouring layer. The alternative (gap-equal: all n+1
// gaps equal to (S − n·t)/pores) was not chosen because
//   1. the mid-planes then sit on the pore lattice of period p that defines the pore count
//      (the facesheets being the lattice planes k = 0 and k = pores), which is what
//      "layers = pores − 1, evenly spaced" describes;
//   2. the positions do not depend on the thickness rule, so the Mass, Eq31 and Ligament
//      rules compare at identical positions and differ only in thickness;
//   3. the difference is small anyway (t/2 ≈ 0.2 mm on a 5 mm pitch for 10 PPI, 2 in).
//
// Layer thickness, by rule (FoamThicknessRule):
//   Mass     (default) t = t_solid / n: the foam mass spread exactly over the n layers.
//   Eq31     t = t_solid / x, the thesis eq 31 taken literally; it loses the fraction
//            1 − n/x of the foam mass (−10 % for 10 PPI, 2 in). Kept to reproduce the thesis.
//   Ligament t = a measured ligament thickness given by the caller; the implied mass error
//            (reduced / real − 1) is reported in massErrorRelative.
//
// Layer model (FoamLayerModel):
//   Disks    (default) every layer is a full disk 0 ≤ r ≤ domain radius R.
//   Segments the flat-segment variant of thesis §5.4.1, where a layer is made of flat
//            segments of finite radial extent instead of a full disk. The reference available
//            to this project gives no formula for it, so it is DEFINED HERE as follows:
//              - a layer is a periodic series of annuli ("segments") of radial length L
//                (segment_length_mm) separated by gaps; gap_fraction f = gap / period, so the
//                period is P = L / (1 − f) and the gap G = P − L;
//              - odd layers (1, 3, ...) start with solid at the axis: solid on [jP, jP + L];
//                even layers are shifted outwards by s·P (segment_stagger_fraction s, default
//                0.5), solid on [s·P + jP, s·P + jP + L] for j ≥ −1, clipped at r = 0, so that
//                with f ≤ 0.5 and s = 0.5 every line of flight parallel to the axis meets solid
//                in some layer (away from the domain edge), as in a real foam;
//              - the pattern is kept exactly periodic from the axis; only whole segments with
//                outer radius ≤ R are kept (a clipped sliver at the domain edge would be an
//                artefact far from the impact, and unresolvable);
//              - each segment of layer k has thickness t_k = t · R² / Σ(r_out² − r_in²), so
//                the layer keeps exactly the areal mass (over the disk of radius R) of the
//                full-disk layer of thickness t.
//            Positions along z are the same as for Disks (segments are centred on z_k).
//
// Areal masses are per unit panel area, in g/cm²: the real core is ρ·t_solid; the reduced
// core is ρ·Σ(volume of every layer body) / (π R²).
//
// Units: lengths mm, densities g/cm³, PPI per inch (converted once with hvi::units).
#pragma once

#include "geometry/GeometryWarning.hpp"
#include "geometry/InputChecks.hpp"
#include "scene/Defaults.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::geometry {

/// How thick each layer is (see the file comment). JSON: "mass", "eq31", "ligament".
enum class FoamThicknessRule { Mass, Eq31, Ligament };

/// Full disks, or the flat-segment variant (see the file comment). JSON: "disks", "segments".
enum class FoamLayerModel { Disks, Segments };

/// The foam core and the choices of the reduction. The comment of each field gives its JSON
/// key, which is also the key named in InputError pointers (prefix + "/" + key).
struct FoamCoreSpec {
    // Required (left at kMissing they are reported as missing).
    double standoffMm = kMissing;             ///< standoff_mm: core thickness S [mm], > 0
    double relativeDensityPercent = kMissing; ///< relative_density_percent: (0, 100) [%]
    double ppi = kMissing;                    ///< ppi: real pores per inch [1/in], > 0
    double materialDensityGCm3 = kMissing;    ///< material_density_g_cm3: solid ligament material
    double domainRadiusMm = kMissing;         ///< domain_radius_mm: outer radius of the layers

    // Optional.
    double ppiFactor = 0.5; ///< ppi_factor: PPI_eff / PPI, (0, 1]; 0.5 per thesis §4.2
    FoamThicknessRule rule = FoamThicknessRule::Mass; ///< thickness_rule
    double ligamentThicknessMm = kMissing;            ///< ligament_thickness_mm (Ligament only)
    FoamLayerModel model = FoamLayerModel::Disks;     ///< layer_model
    double segmentLengthMm = kMissing;                ///< segment_length_mm (Segments only)
    double segmentGapFraction = 0.5;                  ///< segment_gap_fraction, [0, 1)
    double segmentStaggerFraction = 0.5;              ///< segment_stagger_fraction, [0, 1)
    /// particle_spacing_mm: SPH resolution the warnings are judged against; default the
    /// thesis' calibrated 2D particle size (thesis_cases.json calibration).
    double particleSpacingMm = scene::kDefaultParticleSpacingMm;
};

/// One solid body of the reduced core: a full disk (inner radius 0) or one annular segment.
struct FoamLayer {
    int layerIndex;  ///< 1..layerCount, front to rear; segments of a layer share it
    double zFrontMm; ///< from the rear face of the front facesheet
    double zBackMm;  ///< zFrontMm + thicknessMm
    double thicknessMm;
    double innerRadiusMm; ///< 0 for a disk
    double outerRadiusMm; ///< the domain radius for a disk
};

/// The reduced core.
struct FoamLayerStack {
    std::vector<FoamLayer> layers; ///< by layer, then by radius
    int layerCount = 0;            ///< n = poreCount − 1
    int poreCount = 0;             ///< ceil(poresExact) with the 1e-9 guard
    double poresExact = 0.0;       ///< PPI_eff · S[in] before rounding
    double effectivePpi = 0.0;     ///< ppi_factor · PPI [1/in]
    double solidThicknessMm = 0.0; ///< t_solid, eq 26
    double layerSpacingMm = 0.0;   ///< p = S / poreCount, between layer mid-planes
    /// The rule's full-disk layer thickness t (segments are thicker, see the file comment).
    double layerThicknessMm = 0.0;
    double realArealMassGCm2 = 0.0;
    double reducedArealMassGCm2 = 0.0;
    double massErrorRelative = 0.0; ///< reduced / real − 1
    FoamThicknessRule rule = FoamThicknessRule::Mass;
    FoamLayerModel model = FoamLayerModel::Disks;
    std::vector<GeometryWarning> warnings;
};

/// Reduces a foam core to layers. Throws hvi::InputError listing every invalid input, each
/// located at pointerPrefix + "/" + key in `file`; also when the core is too thin to hold a
/// single layer (fewer than 2 pores).
FoamLayerStack buildFoamLayerStack(const FoamCoreSpec& spec, const std::string& file = "<input>",
                                   const std::string& pointerPrefix = "");

/// Pores across the core from the exact count x: ceil(x), except that x within 1e-9 of an
/// integer counts as that integer (20 PPI_eff × 2 in must give 40, not 41).
int roundUpPores(double poresExact);

std::string_view toString(FoamThicknessRule rule);
std::string_view toString(FoamLayerModel model);
/// "mass" | "eq31" | "ligament"; nothing for anything else.
std::optional<FoamThicknessRule> parseFoamThicknessRule(std::string_view text);
/// "disks" | "segments"; nothing for anything else.
std::optional<FoamLayerModel> parseFoamLayerModel(std::string_view text);

} // namespace hvi::geometry
