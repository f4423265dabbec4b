// The classic plate-impact spall test (issue #24, item 3): a 6061-T6 flyer strikes a plate
// three times its thickness in planar strain (FE on FE); the release waves from the flyer's back
// and the target's free surface meet in tension a flyer thickness inside the target. Its
// free-surface velocity rises to the impact speed, and when the spall plane opens it pulls
// back by du. Checked at 0.8, 1.2 and 2.0 GPa: the largest principal tension of unfailed
// material stays at the input spall strength and the centre spalls; at 1.2 and 2.0 GPa the
// pull-back du agrees with an independent one-dimensional solution of the same problem
// (tests/support/UniaxialStrain1D.hpp) converged on a grid ten times finer; at 1.2 GPa the
// acoustic estimate 0.5 rho0 c_L du returns the input within 10 % (the tolerance).
// At 2.0 GPa it does not, nor should it: the converged reference reads 1.47-1.51 GPa there,
// since the spall signal arrives while the release is still in its elastic part
// (docs/notebook/spall-and-damage.md, *Why the pull-back reads 2.0 GPa low*).
// The published 6061 series at 196, 288 and 490 m/s (end of the file) is run as well: the peak
// stresses against its gauges, the tension an unfailed plate reaches, and the input that
// reproduces its pull-back readings.
// Diagnostics: SPALL_H sets the element size, SPALL_NO_JC=1 removes Johnson-Cook failure,
// SPALL_PATCH merge-patches the spall block (e.g. '{"rate_exponent":0.12}'), and the disabled
// PublishedSeriesFeReadings prints the FE plate's readings of the series at SPALL_GPA.
#include "SceneRun.hpp"
#include "Tolerance.hpp"
#include "UniaxialStrain1D.hpp"
#include "material/MaterialLibrary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

constexpr double kFlyerMm = 0.5;
constexpr double kTargetMm = 1.5;
constexpr double kHalfWidthMm = 5.5; // edge release reaches the sampled band after 0.70 us
constexpr double kEndUs = 0.6;       // the pull-back and the re-acceleration are over by 0.5 us
constexpr double kElementMm = 0.025;
constexpr double kSpeedKmS = 1.0; // peak stress 8 GPa

/// Al 6061-T6 of the library with its spall strength replaced (or removed when <= 0).
json aluminiumWithSpall(double strengthGPa) {
    json entry = json::parse(material::MaterialLibrary::builtin().get("Al6061-T6").definitionJson);
    if (std::getenv("SPALL_NO_JC")) {
        entry.erase("failure");
    }
    if (strengthGPa > 0.0) {
        entry["spall"]["strength_GPa"] = strengthGPa;
    } else {
        entry.erase("spall");
    }
    if (const char* patch = std::getenv("SPALL_PATCH"); patch && entry.contains("spall")) {
        entry["spall"].merge_patch(json::parse(patch));
    }
    return entry;
}

json spallScene(double strengthGPa, double speedKmS) {
    auto body = [&](const char* name, double z0, double z1, double v) {
        json b = {{"name", name},
                  {"material", "AlSpall"},
                  {"discretization", "fe"},
                  {"strength", true},
                  {"shape",
                   {{"type", "rectangle"},
                    {"z_min_mm", z0},
                    {"z_max_mm", z1},
                    {"r_min_mm", 0.0},
                    {"r_max_mm", 2.0 * kHalfWidthMm}}}};
        if (v != 0.0) {
            b["velocity"] = {{"z_km_s", v}};
        }
        return b;
    };
    return {
        {"geometry", "planar"},
        {"materials", {{"AlSpall", aluminiumWithSpall(strengthGPa)}}},
        {"fe", {{"element_size_mm", test::envOr("SPALL_H", kElementMm)}}},
        {"run",
         {{"end_time_us", kEndUs},
          {"stop_debris_speed_km_s", 0.0},
          {"stop_no_new_penetration_us", 0.0}}},
        {"domain", {{"radius_mm", 50.0}}},
        {"bodies", {body("flyer", -kFlyerMm, 0.0, speedKmS), body("target", 0.0, kTargetMm, 0.0)}}};
}

struct PullBack {
    double peak = 0.0;              ///< free-surface velocity plateau [km/s]
    double minimum = 0.0;           ///< its minimum after the peak [km/s]
    std::size_t spalled = 0;        ///< target elements failed in the sampled centre band
    double maxTensionGPa = 0.0;     ///< largest principal stress of an unfailed target element
    double maxMeanTensionGPa = 0.0; ///< largest mean tension -P of an unfailed target element
    double peakStressGPa = 0.0;     ///< largest longitudinal compression of a target element
};

/// The free-surface record's peak and its minimum after the peak.
PullBack pullBackOf(const std::vector<double>& freeSurfaceVelocity) {
    const auto peakAt = std::max_element(freeSurfaceVelocity.begin(), freeSurfaceVelocity.end());
    PullBack out;
    out.peak = *peakAt;
    out.minimum = *std::min_element(peakAt, freeSurfaceVelocity.end());
    return out;
}

PullBack runSpall(double strengthGPa, double speedKmS = kSpeedKmS) {
    const auto doc = spallScene(strengthGPa, speedKmS);
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(doc["materials"], "<test>"));
    const fe::FeSolid& fe = *sim.finiteElements();
    // The target's free-surface nodes in the centre band, away from both lateral edges.
    std::vector<std::size_t> surface;
    for (std::size_t n = 0; n < fe.nodes().size(); ++n) {
        if (fe.nodes().body[n] == 1 && fe.nodes().z[n] > kTargetMm - 1e-9 &&
            std::fabs(fe.nodes().r[n] - kHalfWidthMm) < 1.0) {
            surface.push_back(n);
        }
    }
    EXPECT_GT(surface.size(), 50u);
    std::vector<double> history;
    PullBack out;
    test::runUntil(sim, kEndUs, [&](const solver::Simulation& s) {
        double sum = 0.0;
        for (std::size_t n : surface) {
            sum += s.finiteElements()->nodes().vz[n];
        }
        history.push_back(sum / static_cast<double>(surface.size()));
        const auto& el = s.finiteElements()->elements();
        for (std::size_t i = 0; i < el.size(); ++i) {
            if (el.body[i] == 1 && el.alive[i] && el.damage[i] < 1.0) {
                const material::StressDeviator dev{el.szz[i], el.srr[i], el.srz[i]};
                out.maxTensionGPa = std::max(out.maxTensionGPa, dev.maxPrincipal() - el.p[i]);
                out.maxMeanTensionGPa = std::max(out.maxMeanTensionGPa, -el.p[i]);
                out.peakStressGPa = std::max(out.peakStressGPa, el.p[i] - el.szz[i]);
            }
        }
    });
    const PullBack record = pullBackOf(history);
    out.peak = record.peak;
    out.minimum = record.minimum;
    const auto& el = fe.elements();
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (el.body[i] != 1 || el.damage[i] < 1.0) {
            continue;
        }
        out.spalled += std::fabs(test::elementCentroid(fe, i).r - kHalfWidthMm) < 1.0 ? 1 : 0;
    }
    return out;
}

/// 0.5 rho0 c_L du with the library's 6061-T6 constants (data/hydro_materials.json): the
/// longitudinal sound speed sqrt(c0^2 + 4G/(3 rho0)) = 6.408 km/s, at which the elastic front
/// of the spall signal returns to the free surface. With the bulk speed c0 = 5.24 km/s the same
/// du reads 18 % lower (the bias Romanchenko and Stepanov's correction removes).
double acousticSpallStrength(const PullBack& p) {
    const double rho0 = 2.703, cL = 6.408;
    return 0.5 * rho0 * cL * (p.peak - p.minimum);
}

PullBack expectSpall(double strengthGPa) {
    const PullBack p = runSpall(strengthGPa);
    std::printf("spall %.2f GPa: free surface peak %.4f km/s, pull-back to %.4f km/s -> "
                "0.5 rho0 c_L du = %.3f GPa; largest tension of unfailed material %.3f GPa; "
                "%zu elements failed in the centre band\n",
                strengthGPa, p.peak, p.minimum, acousticSpallStrength(p), p.maxTensionGPa,
                p.spalled);
    EXPECT_TRUE(test::near("free-surface peak [km/s]", p.peak, kSpeedKmS, 0.0, 0.03));
    EXPECT_GT(p.spalled, 0u) << "the centre band must spall";
    // The criterion holds the tension of unfailed material at the strength. A point is
    // checked at the start of the step after its stress changed, and across the steep tension
    // front one step moves it by up to about a tenth of the strength at this element size.
    EXPECT_LE(p.maxTensionGPa, 1.15 * strengthGPa);
    EXPECT_GE(p.maxTensionGPa, 0.95 * strengthGPa);
    return p;
}

/// The reference's material: the same library entry, read field by field.
test::UniaxialMaterial referenceMaterial(double strengthGPa) {
    const json entry = aluminiumWithSpall(strengthGPa);
    const json& eos = entry.at("eos");
    const json& jc = entry.at("strength");
    const json& th = entry.at("thermal");
    // The reference's Mie-Grueneisen form has b = 0 (as the library's 6061-T6).
    EXPECT_EQ(eos.at("b").get<double>(), 0.0) << "the 1D reference takes b = 0 only";
    constexpr double kMPaToGPa = 1e-3, kPerSToPerUs = 1e-6, kJToMJ = 1e-6;
    return {eos.at("reference_density_g_cm3"),
            eos.at("c0_km_s"),
            eos.at("s"),
            eos.at("gamma0"),
            entry.at("elastic").at("shear_modulus_GPa"),
            jc.at("A_MPa").get<double>() * kMPaToGPa,
            jc.at("B_MPa").get<double>() * kMPaToGPa,
            jc.at("n"),
            jc.at("C"),
            jc.at("m"),
            jc.at("reference_strain_rate_per_s").get<double>() * kPerSToPerUs,
            th.at("specific_heat_J_kgK").get<double>() * kJToMJ,
            th.at("room_temperature_K"),
            th.at("melt_temperature_K"),
            strengthGPa};
}

struct ReferenceRun {
    PullBack pullBack;
    double energyStart = 0.0, energyEnd = 0.0; ///< [J/mm^2]
};

ReferenceRun runReference(double strengthGPa, double cellMm, double speedKmS = kSpeedKmS) {
    test::UniaxialStrain1D ref(referenceMaterial(strengthGPa),
                               {kFlyerMm, kTargetMm, speedKmS, cellMm});
    ReferenceRun out;
    out.energyStart = ref.totalEnergy();
    std::vector<double> history;
    ref.run(kEndUs,
            [&](const test::UniaxialStrain1D& r) { history.push_back(r.freeSurfaceVelocity()); });
    out.pullBack = pullBackOf(history);
    out.pullBack.maxTensionGPa = ref.maxTensionGPa();
    out.energyEnd = ref.totalEnergy();
    return out;
}

/// The reference on a grid ten times finer than the FE mesh (converged there: see
/// ReferenceConverges).
constexpr double kReferenceCellMm = kElementMm / 10.0;

void expectPullBackAsReference(const PullBack& fe, double strengthGPa) {
    const PullBack ref = runReference(strengthGPa, kReferenceCellMm).pullBack;
    const double duFe = fe.peak - fe.minimum, duRef = ref.peak - ref.minimum;
    std::printf("spall %.2f GPa: pull-back du %.4f km/s (FE), %.4f km/s (1D reference) -> "
                "0.5 rho0 c_L du %.3f and %.3f GPa\n",
                strengthGPa, duFe, duRef, acousticSpallStrength(fe), acousticSpallStrength(ref));
    // 10 %: the FE record at 0.025 mm smears the spall signal's front over about three
    // elements (0.012 us at c_L) while the free surface decelerates at about 5 km/s/us before
    // it, which moves the minimum by up to 0.03 km/s; measured -1 % (2.0 GPa) and -8 %
    // (1.2 GPa), and +3 % at 2.0 GPa on 0.0125 mm elements. The reference has no Johnson-Cook
    // damage, which does not move the FE pull-back here (du 0.1680 and 0.1677 km/s at 2.0 GPa
    // with and without it).
    EXPECT_TRUE(test::near("pull-back du against the 1D reference [km/s]", duFe, duRef, 0.0, 0.10));
}

} // namespace

TEST(SpallPlate, PullBackReturnsTheSpallStrengthAt1p2GPa) {
    const PullBack p = expectSpall(1.2);
    EXPECT_TRUE(test::near("spall strength from the pull-back [GPa]", acousticSpallStrength(p), 1.2,
                           0.0, 0.10));
    expectPullBackAsReference(p, 1.2);
}

// At 2.0 GPa (the library's default) the acoustic estimate reads 27 % low, as the converged
// reference does; the FE record is checked against the reference instead. At 0.8 GPa the spall
// opens on the steep elastic front of the release and the reference's pull-back still moves by
// 20 % between grids of 0.01 and 0.00125 mm: only the criterion itself is checked there.
TEST(SpallPlate, TensionFollowsTheSpallStrength) {
    expectSpall(0.8);
    expectPullBackAsReference(expectSpall(2.0), 2.0);
}

// The reference itself: energy conserved, the criterion held, and the pull-back converged
// (halving its cell moves du by under 3 % at 1.2 and 2.0 GPa; measured 0.0 % and 2.6 %).
TEST(SpallPlate, ReferenceConverges) {
    for (double strength : {1.2, 2.0}) {
        const ReferenceRun fine = runReference(strength, kReferenceCellMm);
        const ReferenceRun finer = runReference(strength, 0.5 * kReferenceCellMm);
        const double du = fine.pullBack.peak - fine.pullBack.minimum;
        const double du2 = finer.pullBack.peak - finer.pullBack.minimum;
        std::printf("1D reference, spall %.2f GPa: du %.4f (%.5f mm), %.4f km/s (%.5f mm); "
                    "energy %.6f -> %.6f J/mm^2\n",
                    strength, du, kReferenceCellMm, du2, 0.5 * kReferenceCellMm, fine.energyStart,
                    fine.energyEnd);
        EXPECT_TRUE(test::near("reference du, halved cell [km/s]", du2, du, 0.0, 0.03));
        EXPECT_TRUE(test::near("reference peak [km/s]", fine.pullBack.peak, kSpeedKmS, 0.0, 0.03));
        EXPECT_LE(fine.pullBack.maxTensionGPa, strength * (1.0 + 1e-3));
        EXPECT_GE(fine.pullBack.maxTensionGPa, strength * 0.99);
        // The contact's inelastic first step and the staggered kinetic energy: measured 0.03 %.
        EXPECT_TRUE(
            test::near("reference energy [J/mm^2]", fine.energyEnd, fine.energyStart, 0.0, 0.005));
    }
}

// A published 6061 series against the model: plate impacts at 196, 288 and 490 m/s with
// manganin gauges in the target and VISAR on its free surface ("Determination of Hugoniot and
// strength properties of 6061 aluminium alloy under dynamic loading", read in its abstract:
// peak stresses 1.4, 2.2 and 3.8 GPa, spall strengths 0.81, 0.96 and 1.08 GPa from the
// free-surface records at 1.8e4-3.7e4 /s; the temper and the plates' thicknesses are not
// given there). The plates here keep this file's 0.5 mm flyer on 1.5 mm: the largest tension an
// unfailed plate reaches does not depend on them (1D reference at 196 m/s: 1.277-1.288 GPa for
// flyers of 0.5 to 3 mm on targets three or two times thicker).
namespace {

struct SeriesShot {
    double speedKmS, peakStressGPa, spallGPa;
};
constexpr SeriesShot kSeries[] = {{0.196, 1.4, 0.81}, {0.288, 2.2, 0.96}, {0.490, 3.8, 1.08}};

/// The experiment's reading of a free-surface record, 0.5 rho0 c0 du with the bulk sound speed
/// (the usual acoustic estimate; with c_L it reads 22 % higher).
double bulkSpallReading(const PullBack& p) {
    const test::UniaxialMaterial m = referenceMaterial(0.0);
    return 0.5 * m.rho0 * m.c0 * (p.peak - p.minimum);
}

} // namespace

// The plates without a spall criterion. The largest tension of the independent 1D reference
// at 196 m/s, 1.29 GPa, bounds the spall strength from above: the experiment spalled that plate,
// so no input above it reproduces the series, and at 288 m/s it stays below the library's
// 2.0 GPa as well. The FE plate's largest element values run above the reference's (measured
// +14 % to +17 % in tension, and the peak compression 9-19 % above the gauges' 1.4, 2.2 and
// 3.8 GPa): the ringing of the elastic precursor at the wave fronts, which this mesh leaves
// undamped (the reference has a linear viscosity); 25 % bounds it. The gauges are compared
// with the library's Hugoniot instead, at the free-surface peak's particle speed u (half the
// peak), with the deviator of the yield stress: rho0 (c0 + s u) u + 2A/3 reads 1.54, 2.23 and
// 3.81 GPa (+10 %, +1 %, +0.3 %); 12 %, since the single-wave Hugoniot leaves out the elastic
// precursor's two-wave structure, which weighs most at the lowest stress.
TEST(SpallPlate, PublishedSeriesBoundsTheStrength) {
    for (const SeriesShot& shot : kSeries) {
        const PullBack fe = runSpall(0.0, shot.speedKmS);
        const PullBack ref = runReference(0.0, kReferenceCellMm, shot.speedKmS).pullBack;
        const test::UniaxialMaterial m = referenceMaterial(0.0);
        const double u = 0.5 * fe.peak;
        const double hugoniotGPa = m.rho0 * (m.c0 + m.s * u) * u + 2.0 / 3.0 * m.aGPa;
        std::printf("%.0f m/s, no spall criterion: peak compression %.3f GPa, Hugoniot stress of "
                    "the free-surface peak %.3f GPa (gauges %.1f); largest tension %.3f GPa (FE), "
                    "%.3f GPa (1D reference)\n",
                    1e3 * shot.speedKmS, fe.peakStressGPa, hugoniotGPa, shot.peakStressGPa,
                    fe.maxTensionGPa, ref.maxTensionGPa);
        EXPECT_TRUE(test::near("Hugoniot stress of the free-surface peak against the gauges [GPa]",
                               hugoniotGPa, shot.peakStressGPa, 0.0, 0.12));
        EXPECT_TRUE(test::near("largest tension, FE against the 1D reference [GPa]",
                               fe.maxTensionGPa, ref.maxTensionGPa, 0.0, 0.25));
        if (shot.speedKmS < 0.2) {
            EXPECT_LT(ref.maxTensionGPa, 1.30);
        } else if (shot.speedKmS < 0.3) {
            EXPECT_LT(ref.maxTensionGPa, 2.0);
        }
    }
}

// Which spall strength reproduces the series' readings: on the 1D reference (which the FE
// plate follows within 10 %, PullBackReturnsTheSpallStrengthAt1p2GPa), the reading rises
// steeply with the input once the input passes the release's elastic range, so each measured
// value fixes the input closely. Measured: 0.81 GPa at 196 m/s between the inputs 1.10 (reads
// 0.70) and 1.15 GPa (0.95); 0.96 at 288 m/s between 1.10 (0.73) and 1.15 (0.97); 1.08 at
// 490 m/s between 1.20 (1.01) and 1.25 (1.14). Checked: every reading lies between those of
// the inputs 1.05 and 1.30 GPa.
TEST(SpallPlate, PublishedSeriesFixesTheStrengthNear1p2GPa) {
    constexpr double kLowGPa = 1.05, kHighGPa = 1.30;
    for (const SeriesShot& shot : kSeries) {
        const double low =
            bulkSpallReading(runReference(kLowGPa, kReferenceCellMm, shot.speedKmS).pullBack);
        const double high =
            bulkSpallReading(runReference(kHighGPa, kReferenceCellMm, shot.speedKmS).pullBack);
        std::printf("%.0f m/s: reading %.3f GPa at an input of %.2f GPa, %.3f at %.2f; measured "
                    "%.2f\n",
                    1e3 * shot.speedKmS, low, kLowGPa, high, kHighGPa, shot.spallGPa);
        EXPECT_LT(low, shot.spallGPa);
        EXPECT_GT(high, shot.spallGPa);
    }
}

TEST(SpallPlate, DISABLED_PublishedSeriesFeReadings) {
    const double strength = test::envOr("SPALL_GPA", 1.2);
    for (const SeriesShot& shot : kSeries) {
        const PullBack fe = runSpall(strength, shot.speedKmS);
        std::printf("%.0f m/s, input %.3f GPa: FE reading %.3f GPa (measured %.2f), largest "
                    "tension of unfailed material %.3f GPa (mean tension %.3f), %zu failed in the "
                    "centre band\n",
                    1e3 * shot.speedKmS, strength, bulkSpallReading(fe), shot.spallGPa,
                    fe.maxTensionGPa, fe.maxMeanTensionGPa, fe.spalled);
    }
}
