// Thesis step 2 (section 5.3, eqs 26-29): mass-equivalent Whipple, the three mass splits of
// Table V, and the initial standoff of eq 29, against the reference (ble-equations.md
// section 9) and the thesis' own Table V (thesis_cases.json, block ble_table_v).
#include "TestPaths.hpp"
#include "Tolerance.hpp"
#include "ble/ThesisSizing.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

using namespace hvi::ble;
using hvi::test::near;

namespace {

struct Shot {
    double diameterCm;
    double velocityKmS;
    double coreCm;
};

// Table IV of the thesis (also the foam block of thesis_cases.json).
const std::map<std::string, Shot> kShots{
    {"HITF04151", {0.36, 6.76, 5.08}},   {"HITF04161", {0.40, 6.89, 5.08}},
    {"HITF04152", {0.36, 6.79, 5.08}},   {"HITF04163", {0.40, 6.79, 5.08}},
    {"HITF03147-2", {0.11, 6.69, 1.27}}, {"HITF03147-3", {0.12, 6.83, 1.27}}};

// 0.254 mm Al 6061-T6 facesheets, 7 % relative density, everything 2.7 g/cm^3 and 40 ksi.
FoamPanelSpec thesisPanel(double coreCm, double yieldKsi = 40.0) {
    return {0.0254, 0.0254, coreCm, 7.0, 2.7, 2.7, yieldKsi};
}
Threat threatOf(const Shot& s) {
    return {s.diameterCm, 2.7, s.velocityKmS, 0.0};
}

// What reproduces the reference's script digits: inverted yield ratio in eq 27 (the thesis'
// Table V) and the printed C93 constants 1.248/1.071 in eq 3.
const ThesisSizingOptions kScript{YieldRatioConvention::ThesisInverted,
                                  NnoShatterConstants::Printed};

const MassSplit& split(const ThesisSizingResult& r, MassSplitModel m) {
    return r.splits[static_cast<std::size_t>(m)];
}

} // namespace

TEST(ThesisSizing, EquivalentPlateThickness) {
    // eq 26: 0.07 * 5.08 = 0.3556 cm of solid foam; + 2 * 0.0254 = 0.4064 cm (4.064 mm);
    // for S = 1.27 cm: 0.0889 + 0.0508 = 0.1397 cm (1.397 mm).
    EXPECT_TRUE(near("t_solid", equivalentSolidFoamCm(thesisPanel(5.08), 5.08), 0.3556, 0, 1e-12));
    EXPECT_TRUE(
        near("total 2 in", equivalentTotalPlateCm(thesisPanel(5.08), 5.08), 0.4064, 0, 1e-12));
    EXPECT_TRUE(
        near("total 0.5 in", equivalentTotalPlateCm(thesisPanel(1.27), 1.27), 0.1397, 0, 1e-12));
    // Mass, not volume, is conserved: a 2.8 g/cm^3 foam alloy behind 2.7 g/cm^3 plates.
    FoamPanelSpec mixed = thesisPanel(5.08);
    mixed.foamMaterialDensityGCm3 = 2.8;
    EXPECT_TRUE(
        near("t_solid mixed", equivalentSolidFoamCm(mixed, 5.08), 0.3556 * 2.8 / 2.7, 0, 1e-12));
}

TEST(ThesisSizing, EvenSplitHitf04151Golden) {
    // Reference 9.5: even split 2.032 mm plates, HB09 4-25 at 40 ksi gives d_c = 3.322 mm.
    const Shot s = kShots.at("HITF04151");
    const auto printed = thesisMassSplits(thesisPanel(s.coreCm), threatOf(s), kScript);
    const MassSplit& even = split(printed, MassSplitModel::Even);
    EXPECT_TRUE(near("even t_b [mm]", even.bumperCm * 10.0, 2.032, 1e-9, 0.0));
    EXPECT_TRUE(near("even t_w [mm]", even.rearWallCm * 10.0, 2.032, 1e-9, 0.0));
    EXPECT_EQ(even.performance.regime, Regime::Shatter);
    // 0.0005 mm: the reference quotes 4 significant digits.
    EXPECT_TRUE(near("even d_c printed [mm]", even.performance.criticalDiameterCm * 10.0, 3.322,
                     0.0005, 0.0));
    EXPECT_TRUE(even.perforated); // 3.6 > 3.322: P (the thesis prints NP, see TableV test)
    // With the continuous constants (default) d_c = 3.3208 mm: 0.0009 mm below the printed
    // form, the 1.071 vs 1.07069 rounding weighted by (V_n/4 - 0.75) = 0.94.
    const auto continuous = thesisMassSplits(thesisPanel(s.coreCm), threatOf(s));
    EXPECT_TRUE(near("even d_c continuous [mm]",
                     split(continuous, MassSplitModel::Even).performance.criticalDiameterCm * 10.0,
                     3.3208, 0.00005, 0.0));
}

TEST(ThesisSizing, TableVGolden) {
    // All 18 Table V thicknesses within 0.005 mm with the ThesisInverted convention (the thesis
    // prints 2-3 decimals and takes BP = total - RW), the script's d_c (reference table 9.2,
    // 0.0005 mm = its last digit) and the verdicts.
    const std::map<std::string, std::array<double, 3>> scriptDcMm{
        {"HITF04151", {3.322, 2.407, 4.418}},   {"HITF04161", {3.362, 2.711, 4.402}},
        {"HITF04152", {3.331, 2.416, 4.436}},   {"HITF04163", {3.331, 2.672, 4.344}},
        {"HITF03147-2", {1.029, 0.739, 1.389}}, {"HITF03147-3", {1.039, 0.812, 1.391}}};
    std::ifstream in(hvi::test::sharedPath("validation/thesis_cases.json"));
    ASSERT_TRUE(in.good());
    const auto rows = nlohmann::json::parse(in).at("ble_table_v").at("rows");
    ASSERT_EQ(rows.size(), 6u);
    int thicknesses = 0;
    for (const auto& row : rows) {
        const std::string id = row.at("id");
        const Shot s = kShots.at(id);
        const auto r = thesisMassSplits(thesisPanel(s.coreCm), threatOf(s), kScript);
        const std::array<std::pair<const char*, MassSplitModel>, 3> models{
            {{"even", MassSplitModel::Even},
             {"rear_wall_formula", MassSplitModel::RearWallFormula},
             {"bumper_formula", MassSplitModel::BumperFormula}}};
        for (std::size_t k = 0; k < models.size(); ++k) {
            const auto& [key, model] = models[k];
            const auto& thesis = row.at(key);
            const MassSplit& m = split(r, model);
            const std::string what = id + " " + key;
            ASSERT_TRUE(m.feasible) << what;
            EXPECT_TRUE(near(what + " bp [mm]", m.bumperCm * 10.0, thesis.at("bp"), 0.005, 0.0));
            EXPECT_TRUE(near(what + " rw [mm]", m.rearWallCm * 10.0, thesis.at("rw"), 0.005, 0.0));
            thicknesses += 2;
            EXPECT_TRUE(near(what + " d_c [mm]", m.performance.criticalDiameterCm * 10.0,
                             scriptDcMm.at(id)[k], 0.0005, 0.0));

            std::string expected = thesis.at("pnp");
            if (expected == "P*") {
                expected = "P"; // "P, computed d_c very close to d"
            }
            if (model == MassSplitModel::Even && (id == "HITF04151" || id == "HITF03147-2")) {
                // The thesis prints NP here, but no consistent yield stress reproduces it:
                // at 40 ksi d_c = 3.322 < 3.6 mm and 1.029 < 1.1 mm, so P. HITF04151 (6.76 km/s,
                // NP) and HITF04152 (6.79 km/s, P) have the same geometry and d, and d_c rises
                // with V in the shatter band, so no single sigma gives NP for one and P for the
                // other (reference 9.3). We assert what the equations give.
                EXPECT_EQ(expected, "NP") << what;
                EXPECT_TRUE(m.perforated) << what << ": computed verdict is P";
            } else {
                EXPECT_EQ(m.perforated ? "P" : "NP", expected) << what;
            }
        }
        // The printed-vs-continuous constant choice moves d_c by < 0.002 mm: no verdict flips.
        const auto cont = thesisMassSplits(
            thesisPanel(s.coreCm), threatOf(s),
            {YieldRatioConvention::ThesisInverted, NnoShatterConstants::Continuous});
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_EQ(cont.splits[k].perforated, r.splits[k].perforated) << id;
        }
    }
    EXPECT_EQ(thicknesses, 36); // 18 (bp, rw) pairs
}

TEST(ThesisSizing, HandbookConventionGivesThickerRearWall) {
    // With HB09's (70/s)^0.5 the rear-wall split of HITF04151 has t_w = 2.143 mm (reference
    // section 9.3, script section A), not the thesis' 1.22 mm.
    const Shot s = kShots.at("HITF04151");
    const auto r = thesisMassSplits(thesisPanel(s.coreCm), threatOf(s));
    const MassSplit& rear = split(r, MassSplitModel::RearWallFormula);
    EXPECT_TRUE(near("HB09 t_w [mm]", rear.rearWallCm * 10.0, 2.143, 0.0005, 0.0));
    EXPECT_TRUE(near("HB09 t_b [mm]", rear.bumperCm * 10.0, 4.064 - 2.143, 0.0005, 0.0));
    EXPECT_TRUE(hasWarning(rear.designWarnings, "design_below_7km_s"));
    EXPECT_FALSE(hasWarning(rear.designWarnings, "thesis_inverted_yield_ratio"));
}

TEST(ThesisSizing, AlternativeVelocityOfHitf03147_2KeepsVerdicts) {
    // thesis_cases.json: Table IV gives 6.69 km/s, Table VII 6.89; the verdict must not flip.
    const Shot slow = kShots.at("HITF03147-2");
    Shot fast = slow;
    fast.velocityKmS = 6.89;
    const auto a = thesisMassSplits(thesisPanel(slow.coreCm), threatOf(slow), kScript);
    const auto b = thesisMassSplits(thesisPanel(fast.coreCm), threatOf(fast), kScript);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(a.splits[k].perforated, b.splits[k].perforated) << k;
    }
}

TEST(ThesisSizing, InfeasibleSplitIsReportedNotThrown) {
    // 1 % foam, 5 mm projectile at 7 km/s: total = 0.0508 + 0.0508 = 0.1016 cm, while the
    // bumper formula wants 0.25 * 0.5 = 0.125 cm and the rear-wall formula ~0.3 cm.
    FoamPanelSpec thin = thesisPanel(5.08);
    thin.relativeDensityPercent = 1.0;
    const Threat threat{0.5, 2.7, 7.0, 0.0};
    ThesisSizingResult r;
    ASSERT_NO_THROW(r = thesisMassSplits(thin, threat));
    EXPECT_TRUE(near("total", r.totalPlateCm, 0.1016, 0.0, 1e-12));
    const MassSplit& even = split(r, MassSplitModel::Even);
    const MassSplit& rear = split(r, MassSplitModel::RearWallFormula);
    const MassSplit& bumper = split(r, MassSplitModel::BumperFormula);
    EXPECT_TRUE(even.feasible);
    EXPECT_TRUE(even.perforated);
    EXPECT_FALSE(rear.feasible);
    EXPECT_FALSE(bumper.feasible);
    EXPECT_NE(rear.infeasibleReason.find("rear-wall formula"), std::string::npos);
    EXPECT_NE(bumper.infeasibleReason.find("bumper formula"), std::string::npos);
    EXPECT_TRUE(near("bumper formula t_b", bumper.bumperCm, 0.125, 0.0, 1e-12));
    EXPECT_GT(rear.rearWallCm, r.totalPlateCm);
    // Just feasible: d = 0.4 cm gives t_b = 0.1 < 0.1016.
    const auto ok = thesisMassSplits(thin, {0.4, 2.7, 7.0, 0.0});
    EXPECT_TRUE(split(ok, MassSplitModel::BumperFormula).feasible);
}

TEST(ThesisSizing, InitialStandoffMatchesReference) {
    // Reference 9.4 (script section E): S_initial [mm] at 40 and 57 ksi and the plate
    // thickness at the root; computed there with the printed C93 constants. 0.005 mm: the
    // table's last digit.
    struct Row {
        const char* id;
        double s40;
        double plate40;
        double s57;
    };
    const Row rows[] = {{"HITF04151", 55.46, 2.195, 48.81},   {"HITF04161", 61.34, 2.401, 54.01},
                        {"HITF04152", 55.29, 2.189, 48.65},   {"HITF04163", 61.97, 2.423, 54.59},
                        {"HITF03147-2", 13.87, 0.739, 11.88}, {"HITF03147-3", 15.33, 0.791, 13.17}};
    for (const Row& row : rows) {
        const Shot s = kShots.at(row.id);
        const auto r40 = thesisInitialStandoff(thesisPanel(0.0), threatOf(s), 0.5, 20.0, kScript);
        ASSERT_EQ(r40.status, InitialStandoffStatus::Solved) << row.id;
        EXPECT_TRUE(near(std::string(row.id) + " S_initial 40 ksi [mm]", r40.standoffCm * 10.0,
                         row.s40, 0.005, 0.0));
        EXPECT_TRUE(near(std::string(row.id) + " plate [mm]", r40.plateCm * 10.0, row.plate40,
                         0.0005, 0.0));
        // At the root d_c = d (1e-9 cm bracket tolerance on S moves d_c by far less).
        EXPECT_TRUE(near("d_c at root", r40.criticalDiameterCm, s.diameterCm, 1e-9, 0.0));
        const auto r57 =
            thesisInitialStandoff(thesisPanel(0.0, 57.0), threatOf(s), 0.5, 20.0, kScript);
        EXPECT_TRUE(near(std::string(row.id) + " S_initial 57 ksi [mm]", r57.standoffCm * 10.0,
                         row.s57, 0.005, 0.0));
        // The continuous default lands 0.004-0.02 mm higher (1.071 vs 1.07069 moves d_c by
        // ~3e-4 relative, and S ~ d_c^3 in the hypervelocity term).
        const auto cont = thesisInitialStandoff(thesisPanel(0.0), threatOf(s), 0.5, 20.0);
        EXPECT_GT(cont.standoffCm, r40.standoffCm) << row.id;
        EXPECT_TRUE(near(std::string(row.id) + " S_initial continuous [mm]", cont.standoffCm * 10.0,
                         row.s40, 0.025, 0.0));
    }
}

TEST(ThesisSizing, InitialStandoffNoSolutionInEnvelope) {
    // HITF04151 needs S = 5.546 cm; an envelope ending at 4 cm cannot stop the threat.
    const Shot s = kShots.at("HITF04151");
    const auto r = thesisInitialStandoff(thesisPanel(0.0), threatOf(s), 1.0, 4.0);
    EXPECT_EQ(r.status, InitialStandoffStatus::NoSolutionInEnvelope);
    EXPECT_DOUBLE_EQ(r.standoffCm, 4.0);
    EXPECT_LT(r.criticalDiameterCm, s.diameterCm);
    EXPECT_NE(r.message.find("no solution"), std::string::npos);
}

TEST(ThesisSizing, InitialStandoffBelowEnvelope) {
    // An envelope starting at 6 cm is already past the 5.546 cm root.
    const Shot s = kShots.at("HITF04151");
    const auto r = thesisInitialStandoff(thesisPanel(0.0), threatOf(s), 6.0, 10.0);
    EXPECT_EQ(r.status, InitialStandoffStatus::StoppedAtEnvelopeMinimum);
    EXPECT_DOUBLE_EQ(r.standoffCm, 6.0);
    EXPECT_GE(r.criticalDiameterCm, s.diameterCm);
    EXPECT_THROW(thesisInitialStandoff(thesisPanel(0.0), threatOf(s), 6.0, 6.0),
                 std::invalid_argument);
}
