// Step 2 of the source study: size a Whipple shield of the same areal mass as a foam-core
// sandwich panel, split that mass three ways, judge each split with the NNO Whipple equation,
// and find the initial standoff at which the even split just stops the threat.
//
// Source: the thesis "Modelling of Hypervelocity Impact on Foam-Core Sandwich Panel with
// Enhanced Capability for Orbital Debris Protection" (University of Manitoba), section 5.3,
// eqs (26)-(29) and Tables IV-V; equations from HB09 4-21, 4-22, 4-25 (see WhippleDesign.hpp,
// WhippleNno.hpp). Reproduction notes: shared/reference/ble-equations.md section 9.
//
// Units: cm, g/cm^3, km/s, ksi, angle in degrees.
//
//   t_solid = (rho%/100) S rho_foam_material / rho_plate         (eq 26, mass-equivalent)
//   total   = t_front + t_rear + t_solid
//   even:       t_b = t_w = total/2
//   rear wall:  t_w from HB09 4-22 (eq 27), t_b = total - t_w
//   bumper:     t_b from HB09 4-21 (eq 28), t_w = total - t_b
//   verdict:    P (perforated) if d > d_c of the NNO equation, else NP.
// A split whose formula thickness is >= total (leaving nothing, or less, for the other plate)
// is reported infeasible, not thrown.
//
// Initial standoff (eq 29): the S at which the even split of the same-mass Whipple,
// t_b = t_w = total(S)/2, has d_c(S) = d. The thesis writes it as a fixed point
// S = F(t(S)); iterated literally it diverges (dF/dS at the root is -1.4 to -1.9 for the
// thesis cases, reference section 9.4), so it is solved here with Brent's method on the
// monotonic d_c(S) - d over the caller's standoff envelope [S_min, S_max].
//
// Options: the thesis' rear-wall column needs YieldRatioConvention::ThesisInverted (see
// WhippleDesign.hpp); the handbook convention is the default. The reference's d_c and
// S_initial digits were computed with the printed C93 constants, NnoShatterConstants::Printed
// (see WhippleNno.hpp); the continuous form is the default (S_initial differs by ~0.02 mm).
#pragma once

#include "ble/Types.hpp"
#include "ble/WhippleDesign.hpp"
#include "ble/WhippleNno.hpp"

#include <array>
#include <string>
#include <vector>

namespace hvi::ble {

struct ThesisSizingOptions {
    YieldRatioConvention convention = YieldRatioConvention::Handbook;       ///< rear-wall equation
    NnoShatterConstants shatterConstants = NnoShatterConstants::Continuous; ///< NNO d_c
};

/// The foam panel whose mass the equivalent Whipple shield carries.
struct FoamPanelSpec {
    double frontFacesheetCm = 0.0;        ///< [cm]
    double rearFacesheetCm = 0.0;         ///< [cm]
    double coreThicknessCm = 0.0;         ///< S [cm] (ignored by thesisInitialStandoff)
    double relativeDensityPercent = 7.0;  ///< foam density / solid density [%]
    double foamMaterialDensityGCm3 = 2.7; ///< solid density of the foam's material [g/cm^3]
    double plateDensityGCm3 = 2.7;        ///< facesheets and Whipple plates [g/cm^3]
    double plateYieldKsi = 40.0;          ///< Whipple rear-wall yield [ksi]
};

/// eq 26: thickness [cm] of plate material with the foam core's areal mass.
double equivalentSolidFoamCm(const FoamPanelSpec& panel, double coreThicknessCm);

/// Front + rear facesheet + equivalent solid foam [cm].
double equivalentTotalPlateCm(const FoamPanelSpec& panel, double coreThicknessCm);

enum class MassSplitModel { Even, RearWallFormula, BumperFormula };

/// Stable names for output files: "even", "rear_wall_formula", "bumper_formula".
const char* massSplitName(MassSplitModel model);

struct MassSplit {
    MassSplitModel model = MassSplitModel::Even;
    bool feasible = true;
    std::string infeasibleReason; ///< empty when feasible
    /// t_b and t_w [cm]. When infeasible, the plate the formula sized keeps the formula's
    /// value (so the caller can report it) and the other plate is 0.
    double bumperCm = 0.0;
    double rearWallCm = 0.0;
    CriticalDiameterResult performance;          ///< NNO d_c; meaningful only when feasible
    bool perforated = false;                     ///< d > d_c (P); meaningful only when feasible
    std::vector<ValidityWarning> designWarnings; ///< from the design equation used, if any
};

struct ThesisSizingResult {
    double solidFoamCm = 0.0;        ///< eq 26
    double totalPlateCm = 0.0;       ///< facesheets + solid foam
    std::array<MassSplit, 3> splits; ///< Even, RearWallFormula, BumperFormula, in that order
};

/// The three mass splits of the Whipple shield equivalent to `panel` at its core thickness.
/// threat.diameterCm must be > 0.
ThesisSizingResult thesisMassSplits(const FoamPanelSpec& panel, const Threat& threat,
                                    const ThesisSizingOptions& options = {});

enum class InitialStandoffStatus {
    Solved,                   ///< d_c(S) = d inside the envelope
    NoSolutionInEnvelope,     ///< d_c(S_max) < d: no standoff up to S_max stops the threat
    StoppedAtEnvelopeMinimum, ///< d_c(S_min) >= d: even S_min stops it; standoffCm = S_min
};

struct InitialStandoffResult {
    InitialStandoffStatus status = InitialStandoffStatus::Solved;
    double standoffCm = 0.0;               ///< S_initial (or S_min / S_max, see status)
    double plateCm = 0.0;                  ///< t_b = t_w at standoffCm [cm]
    double criticalDiameterCm = 0.0;       ///< d_c at standoffCm
    int iterations = 0;                    ///< root-finder evaluations
    std::string message;                   ///< one line for the user
    std::vector<ValidityWarning> warnings; ///< NNO warnings at standoffCm
};

/// eq 29: initial standoff of the even-split equivalent Whipple, searched over
/// [standoffMinCm, standoffMaxCm] (options.convention is not used). A status, not an exception,
/// reports "no solution". Throws hvi::RuntimeFailure only if the root finder fails to converge (not
/// expected).
InitialStandoffResult thesisInitialStandoff(const FoamPanelSpec& panel, const Threat& threat,
                                            double standoffMinCm, double standoffMaxCm,
                                            const ThesisSizingOptions& options = {});

} // namespace hvi::ble
