// Thesis step 2 (mass-equivalent Whipple, mass splits, initial standoff); see ThesisSizing.hpp.
#include "ble/ThesisSizing.hpp"

#include "ble/ArgumentChecks.hpp"
#include "ble/RootFinding.hpp"
#include "core/Error.hpp"

#include <string>

namespace hvi::ble {

namespace {

void checkPanel(const FoamPanelSpec& p) {
    detail::requireNonNegative("front facesheet [cm]", p.frontFacesheetCm);
    detail::requireNonNegative("rear facesheet [cm]", p.rearFacesheetCm);
    detail::requireNonNegative("relative density [%]", p.relativeDensityPercent);
    detail::requirePositive("foam material density [g/cm^3]", p.foamMaterialDensityGCm3);
    detail::requirePositive("plate density [g/cm^3]", p.plateDensityGCm3);
    detail::requirePositive("plate yield [ksi]", p.plateYieldKsi);
}

WhippleShield evenWhipple(const FoamPanelSpec& p, double standoffCm) {
    const double half = 0.5 * equivalentTotalPlateCm(p, standoffCm);
    return {half, p.plateDensityGCm3, half, p.plateYieldKsi, standoffCm};
}

void judge(MassSplit& split, const FoamPanelSpec& p, double standoffCm, const Threat& threat,
           NnoShatterConstants constants) {
    const WhippleShield shield{split.bumperCm, p.plateDensityGCm3, split.rearWallCm,
                               p.plateYieldKsi, standoffCm};
    split.performance = whippleNnoCriticalDiameter(shield, threat, constants);
    split.perforated = threat.diameterCm > split.performance.criticalDiameterCm;
}

} // namespace

double equivalentSolidFoamCm(const FoamPanelSpec& panel, double coreThicknessCm) {
    checkPanel(panel);
    detail::requireNonNegative("core thickness [cm]", coreThicknessCm);
    // Same areal mass: rho_foam_material (rho%/100) S = rho_plate t_solid. With one alloy
    // throughout (the thesis) this is the thesis' t = (rho%/100) S.
    return panel.relativeDensityPercent / 100.0 * coreThicknessCm * panel.foamMaterialDensityGCm3 /
           panel.plateDensityGCm3;
}

double equivalentTotalPlateCm(const FoamPanelSpec& panel, double coreThicknessCm) {
    return panel.frontFacesheetCm + panel.rearFacesheetCm +
           equivalentSolidFoamCm(panel, coreThicknessCm);
}

const char* massSplitName(MassSplitModel model) {
    switch (model) {
    case MassSplitModel::Even:
        return "even";
    case MassSplitModel::RearWallFormula:
        return "rear_wall_formula";
    case MassSplitModel::BumperFormula:
        return "bumper_formula";
    }
    return "unknown";
}

ThesisSizingResult thesisMassSplits(const FoamPanelSpec& panel, const Threat& threat,
                                    const ThesisSizingOptions& options) {
    checkPanel(panel);
    detail::requirePositive("core thickness [cm]", panel.coreThicknessCm);
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    const double s = panel.coreThicknessCm;

    ThesisSizingResult result;
    result.solidFoamCm = equivalentSolidFoamCm(panel, s);
    result.totalPlateCm = equivalentTotalPlateCm(panel, s);
    const double total = result.totalPlateCm;

    const WhippleDesign design =
        designWhipple(threat, {panel.plateDensityGCm3, panel.plateYieldKsi, s}, options.convention);

    MassSplit& even = result.splits[0];
    even.model = MassSplitModel::Even;
    even.bumperCm = even.rearWallCm = 0.5 * total;

    MassSplit& rear = result.splits[1];
    rear.model = MassSplitModel::RearWallFormula;
    rear.rearWallCm = design.rearWallCm;
    rear.bumperCm = total - design.rearWallCm;
    rear.designWarnings = design.warnings;

    MassSplit& bumper = result.splits[2];
    bumper.model = MassSplitModel::BumperFormula;
    bumper.bumperCm = design.bumperCm;
    bumper.rearWallCm = total - design.bumperCm;
    for (const auto& w : design.warnings) {
        // The yield-ratio convention concerns the rear-wall equation only.
        if (w.code != "thesis_inverted_yield_ratio") {
            bumper.designWarnings.push_back(w);
        }
    }

    // A plate the formula wants >= the whole mass leaves the other plate with nothing.
    if (rear.rearWallCm >= total) {
        rear.feasible = false;
        rear.infeasibleReason =
            "rear-wall formula asks for t_w = " + std::to_string(rear.rearWallCm) +
            " cm >= total plate " + std::to_string(total) + " cm";
        rear.bumperCm = 0.0;
    }
    if (bumper.bumperCm >= total) {
        bumper.feasible = false;
        bumper.infeasibleReason =
            "bumper formula asks for t_b = " + std::to_string(bumper.bumperCm) +
            " cm >= total plate " + std::to_string(total) + " cm";
        bumper.rearWallCm = 0.0;
    }
    for (auto& split : result.splits) {
        if (split.feasible) {
            judge(split, panel, s, threat, options.shatterConstants);
        }
    }
    return result;
}

InitialStandoffResult thesisInitialStandoff(const FoamPanelSpec& panel, const Threat& threat,
                                            double standoffMinCm, double standoffMaxCm,
                                            const ThesisSizingOptions& options) {
    checkPanel(panel);
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    detail::requirePositive("minimum standoff [cm]", standoffMinCm);
    if (!(standoffMaxCm > standoffMinCm)) {
        throw std::invalid_argument("hvi::ble: standoff envelope needs S_max > S_min (got " +
                                    std::to_string(standoffMinCm) + ", " +
                                    std::to_string(standoffMaxCm) + ")");
    }
    const auto dcAt = [&](double s) {
        return whippleNnoCriticalDiameter(evenWhipple(panel, s), threat, options.shatterConstants)
            .criticalDiameterCm;
    };
    const double d = threat.diameterCm;

    InitialStandoffResult result;
    const auto finish = [&](double s) {
        const WhippleShield shield = evenWhipple(panel, s);
        const CriticalDiameterResult r =
            whippleNnoCriticalDiameter(shield, threat, options.shatterConstants);
        result.standoffCm = s;
        result.plateCm = shield.bumperCm;
        result.criticalDiameterCm = r.criticalDiameterCm;
        result.warnings = r.warnings;
    };

    // d_c grows with S (a longer standoff spreads the debris cloud, and the equal-mass plates
    // thicken with the core), so checking the ends decides whether a root exists.
    if (dcAt(standoffMaxCm) < d) {
        result.status = InitialStandoffStatus::NoSolutionInEnvelope;
        finish(standoffMaxCm);
        result.message = "no solution: no standoff up to the envelope (S_max = " +
                         std::to_string(standoffMaxCm) + " cm) stops the threat";
        return result;
    }
    if (dcAt(standoffMinCm) >= d) {
        result.status = InitialStandoffStatus::StoppedAtEnvelopeMinimum;
        finish(standoffMinCm);
        result.message =
            "the smallest standoff of the envelope (S_min = " + std::to_string(standoffMinCm) +
            " cm) already stops the threat";
        return result;
    }
    // 1e-9 cm is far below any manufacturing tolerance and well above round-off at S ~ 1-100 cm.
    const RootResult root =
        brentRoot([&](double s) { return dcAt(s) - d; }, standoffMinCm, standoffMaxCm, 1e-9);
    if (!root.bracketed || !root.converged) {
        throw RuntimeFailure("hvi::ble: initial standoff root finder did not converge");
    }
    result.status = InitialStandoffStatus::Solved;
    result.iterations = root.iterations;
    finish(root.x);
    result.message = "S_initial = " + std::to_string(root.x) + " cm";
    return result;
}

} // namespace hvi::ble
