// The Taylor anvil test (issue #24, item 1): a 6061-T6 rod strikes a steel anvil at a few
// hundred m/s, mushrooms, and is recovered whole. The rods, FE and SPH, strike a 4340 steel FE
// block, as in the test. TAYLOR_ANVIL=mirror instead strikes two identical rods at +-V, the rod
// on a rigid, frictionless anvil (the contact plane is a symmetry plane): a stiffer anvil than
// the test's, which loads the rod's core harder (see the FE tests below), and for SPH rods no
// anvil at all, since two SPH bodies pressed together are one continuum that held the
// rebounding rods together in tension (76 particles failed at 227 m/s, against 21 on steel).
// Data: House, Lewis, Gillis, Wilson, IJIE 16 (1995) 189, rods 7.595 mm across and 11.39 mm
// long (L/D = 1.5), final length and foot diameter as transcribed in the public
// HighRateExptData collection (TaylorData/MATLAB/plot6061T6Al.m; not checked against the paper):
//   227 m/s: L_f 10.2 mm, D_f 9.9 mm;   339 m/s: L_f 8.3 mm, D_f 12.8 mm.
// What must hold: no point of a rod fails (damage 1) and none is eroded, in FE and in SPH,
// at both speeds. The final shape is checked loosely (10 % on L_f and D_f): it measures the
// Johnson-Cook strength constants (unchanged here), not the failure model under test, and
// those constants are fitted at lower strain rates than a Taylor foot sees.
// Diagnostics (docs/notebook/spall-and-damage.md): TAYLOR_H and TAYLOR_SPH_H set the spacing,
// TAYLOR_DROP=spall|failure removes that block of the material, TAYLOR_PATCH merge-patches its
// library entry (e.g. '{"failure":{"compression_closure":0}}' or '{"spall":{"strength_GPa":2.5}}'),
// TAYLOR_EROSION sets the FE erosion factor, TAYLOR_ANVIL=steel|mirror the anvil,
// TAYLOR_WHERE=1 lists the failed and eroded points, TAYLOR_TRACE=1 the largest tension of each
// time window, TAYLOR_ELEMENT=i an FE element's stress state and the face centre's node,
// TAYLOR_SPH_KERNEL and TAYLOR_SPH_HFAC set the SPH kernel and h / spacing, TAYLOR_SPH_ASTRESS
// its artificial stress epsilon, TAYLOR_DIAG=1 each point's failure (FailureLog); each run
// prints the largest principal and mean tension of the rod, and where the first was.
#include "SceneRun.hpp"
#include "Tolerance.hpp"
#include "material/MaterialLibrary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

constexpr double kDiameterMm = 7.595;
constexpr double kLengthMm = 11.39;
constexpr double kEndTimeUs = 40.0;

/// The anvil: a 4340 steel FE block at rest, as in the test, or the rod's mirror image at -V
/// (a rigid, frictionless anvil; a diagnostic, see the file's header).
enum class Anvil { Mirror, Steel };

json taylorScene(double speedKmS, const char* discretization, double spacing, Anvil anvil) {
    auto rod = [&](const char* name, const char* role, double z0, double v) {
        return json{{"name", name},
                    {"role", role},
                    {"material", "Al6061-T6"},
                    {"discretization", discretization},
                    {"shape",
                     {{"type", "rectangle"},
                      {"z_min_mm", z0},
                      {"z_max_mm", z0 + kLengthMm},
                      {"r_min_mm", 0.0},
                      {"r_max_mm", 0.5 * kDiameterMm}}},
                    {"velocity", {{"z_km_s", v}}}};
    };
    json steel = {{"name", "anvil"},
                  {"role", "rear_wall"},
                  {"material", "Steel4340"},
                  {"discretization", "fe"},
                  {"shape",
                   {{"type", "rectangle"},
                    {"z_min_mm", 0.0},
                    {"z_max_mm", 10.0},
                    {"r_min_mm", 0.0},
                    {"r_max_mm", 15.0}}}};
    return {
        {"geometry", "axisymmetric"},
        {"sph", {{"particle_spacing_mm", spacing}}},
        {"fe", {{"element_size_mm", spacing}}},
        {"run",
         {{"end_time_us", kEndTimeUs},
          {"stop_debris_speed_km_s", 0.0},
          {"stop_no_new_penetration_us", 0.0},
          {"stop_on_rear_wall_perforation", false}}},
        {"domain", {{"radius_mm", 30.0}}},
        {"bodies",
         {rod("rod", "projectile", -kLengthMm - 0.5 * spacing, speedKmS),
          anvil == Anvil::Mirror ? rod("anvil", "rear_wall", 0.5 * spacing, -speedKmS) : steel}}};
}

struct RodShape {
    double lengthMm = 0.0;
    double footDiameterMm = 0.0;
    std::size_t failed = 0; ///< points of the rod with damage 1
    std::size_t eroded = 0; ///< points of the rod no longer alive
    std::size_t points = 0;
};

struct Position {
    double z = 0.0, r = 0.0;
};
Position positionOf(const fe::FeSolid& fe, std::size_t i) {
    const test::ElementCentroid c = test::elementCentroid(fe, i);
    return {c.z, c.r};
}
Position positionOf(const sph::ParticleSet& ps, std::size_t i) {
    return {ps.z[i], ps.r[i]};
}
const fe::ElementSet& pointsOf(const fe::FeSolid& fe) {
    return fe.elements();
}
const sph::ParticleSet& pointsOf(const sph::ParticleSet& ps) {
    return ps;
}

/// Failed and eroded points of the rod (body 0) of an element or particle set.
template <class Set>
void countRod(const Set& set, RodShape& out) {
    const auto& pts = pointsOf(set);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (pts.body[i] != 0) {
            continue;
        }
        ++out.points;
        out.eroded += pts.alive[i] ? 0 : 1;
        out.failed += pts.damage[i] >= 1.0 ? 1 : 0;
        if ((pts.damage[i] >= 1.0 || !pts.alive[i]) && std::getenv("TAYLOR_WHERE")) {
            const Position at = positionOf(set, i);
            std::printf("%s point at z %.2f r %.2f\n", pts.damage[i] >= 1.0 ? "failed" : "eroded",
                        at.z, at.r);
        }
    }
}

/// The largest principal tension of the rod's unfailed points, and their largest mean tension
/// (-P, what a pressure cutoff reads; a plate's spall plane carries sigma_1 = -P + 2Y/3).
struct Tension {
    double gpa = 0.0, timeUs = 0.0;
    Position at;
    double meanGPa = 0.0;
    double expansionPerS = 0.0;  ///< volumetric expansion rate -d ln(rho)/dt there [1/s]
    std::vector<double> lastRho; ///< each point's density at the previous call
    double lastTime = 0.0;
};
template <class Set>
void trackTension(const Set& set, double time, Tension& t) {
    const auto& pts = pointsOf(set);
    const bool rates = t.lastRho.size() == pts.size() && time > t.lastTime;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (pts.body[i] != 0 || !pts.alive[i] || pts.damage[i] >= 1.0) {
            continue;
        }
        const material::StressDeviator dev{pts.szz[i], pts.srr[i], pts.srz[i]};
        const double sigma1 = dev.maxPrincipal() - pts.p[i];
        if (sigma1 > t.gpa) {
            t.gpa = sigma1;
            t.timeUs = time;
            t.at = positionOf(set, i);
            t.expansionPerS =
                rates ? -1e6 * std::log(pts.rho[i] / t.lastRho[i]) / (time - t.lastTime) : 0.0;
        }
        t.meanGPa = std::max(t.meanGPa, -pts.p[i]);
    }
    t.lastRho = pts.rho;
    t.lastTime = time;
}

/// TAYLOR_DIAG=1 (SPH rods): each rod particle as it fails, with its plastic strain and its
/// mean stress triaxiality over its plastic flow (weighted by the plastic strain increments),

/// The rod (body 0) is meshed with finite elements (the anvil may be, whatever the rod is).
bool feRod(const solver::Simulation& sim) {
    if (!sim.finiteElements()) {
        return false;
    }
    const auto& body = sim.finiteElements()->elements().body;
    return std::find(body.begin(), body.end(), 0) != body.end();
}

/// trackTension over the rod's points, elements or particles.
void trackRodTension(const solver::Simulation& sim, Tension& t) {
    if (feRod(sim)) {
        trackTension(*sim.finiteElements(), sim.time(), t);
    } else {
        trackTension(sim.particles(), sim.time(), t);
    }
}

/// which tells a failure in tension from one in compressive shear.
struct FailureLog {
    std::vector<double> damage, strain, triaxialityWork, damagingStrain, damagingWork;
    template <class Set>
    void observe(const Set& set, double time) {
        const auto& ps = pointsOf(set);
        for (auto* v : {&damage, &strain, &triaxialityWork, &damagingStrain, &damagingWork}) {
            v->resize(ps.size(), 0.0);
        }
        for (std::size_t i = 0; i < ps.size(); ++i) {
            const double seq = material::StressDeviator{ps.szz[i], ps.srr[i], ps.srz[i]}.vonMises();
            const double dEp = ps.plasticStrain[i] - strain[i];
            if (seq > 0.0 && dEp > 0.0) {
                const double sStar = -ps.p[i] / seq;
                triaxialityWork[i] += dEp * sStar;
                if (sStar >= -1.0 / 3.0) { // the increments Johnson-Cook damage counts
                    damagingStrain[i] += dEp;
                    damagingWork[i] += dEp * sStar;
                }
            }
            if (ps.body[i] == 0 && ps.damage[i] >= 1.0 && damage[i] < 1.0) {
                const Position at = positionOf(set, i);
                std::printf("point %zu fails at t %.2f us, z %.2f r %.2f mm: plastic strain %.3f, "
                            "mean triaxiality %.2f; above -1/3: strain %.3f at mean %.2f\n",
                            i, time, at.z, at.r, ps.plasticStrain[i],
                            triaxialityWork[i] / std::max(strain[i], 1e-12), damagingStrain[i],
                            damagingWork[i] / std::max(damagingStrain[i], 1e-12));
            }
            damage[i] = ps.damage[i];
            strain[i] = ps.plasticStrain[i];
        }
    }
};

/// The rod (body 0): extent along z, largest radius, failed and eroded points.
RodShape measure(const solver::Simulation& sim) {
    RodShape out;
    double zMin = 1e30, zMax = -1e30, rMax = 0.0;
    auto extend = [&](double z, double r) {
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
        rMax = std::max(rMax, r);
    };
    if (feRod(sim)) {
        const auto& nd = sim.finiteElements()->nodes();
        for (std::size_t n = 0; n < nd.size(); ++n) {
            if (nd.body[n] == 0) {
                extend(nd.z[n], nd.r[n]);
            }
        }
        countRod(*sim.finiteElements(), out);
    } else {
        const auto& ps = sim.particles();
        const double h = sim.scene().sph.particleSpacing;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (ps.body[i] == 0) {
                // A particle stands for a cell of one spacing: its edge is half a spacing out.
                extend(ps.z[i] - 0.5 * h, ps.r[i] + 0.5 * h);
                extend(ps.z[i] + 0.5 * h, ps.r[i] + 0.5 * h);
            }
        }
        countRod(ps, out);
    }
    out.lengthMm = zMax - zMin;
    out.footDiameterMm = 2.0 * rMax;
    return out;
}

/// The diagnostics' changes to the scene and the rod's material (see the file's header), after
/// a test's own merge patch of the rod's library entry (`rodPatch`, null for none).
void applyDiagnosticKnobs(json& doc, const json& rodPatch) {
    if (const char* kernel = std::getenv("TAYLOR_SPH_KERNEL")) {
        doc["sph"]["kernel"] = kernel;
    }
    if (const char* factor = std::getenv("TAYLOR_SPH_HFAC")) {
        doc["sph"]["smoothing_length_factor"] = std::atof(factor);
    }
    if (const char* epsilon = std::getenv("TAYLOR_SPH_ASTRESS")) {
        doc["sph"]["artificial_stress"] = std::atof(epsilon);
    }
    if (const char* factor = std::getenv("TAYLOR_EROSION")) {
        doc["fe"]["erosion_factor"] = std::atof(factor);
    }
    const char* drop = std::getenv("TAYLOR_DROP");   // drop "spall" or "failure",
    const char* patch = std::getenv("TAYLOR_PATCH"); // or merge-patch the entry (JSON)
    if (drop || patch || !rodPatch.is_null()) {
        json entry =
            json::parse(material::MaterialLibrary::builtin().get("Al6061-T6").definitionJson);
        if (!rodPatch.is_null()) {
            entry.merge_patch(rodPatch);
        }
        if (drop) {
            entry.erase(drop);
        }
        if (patch) {
            entry.merge_patch(json::parse(patch));
        }
        doc["materials"] = {{"AlT", entry}};
        for (auto& b : doc["bodies"]) {
            if (b["material"] == "Al6061-T6") {
                b["material"] = "AlT";
            }
        }
    }
}

/// TAYLOR_TRACE=1: the largest tension of each window (0.25 us to 6 us, then 2 us);
/// TAYLOR_ELEMENT=i (FE rods): element i's stress state and the face centre node every 0.05 us.
struct Trace {
    const bool windows = std::getenv("TAYLOR_TRACE") != nullptr;
    const char* element = std::getenv("TAYLOR_ELEMENT");
    Tension window;
    double windowEnd = 0.25, nextElementTime = 0.0;

    void observe(const solver::Simulation& s) {
        if (windows) {
            observeWindow(s);
        }
        if (element && feRod(s) && s.time() >= nextElementTime) {
            nextElementTime += 0.05;
            printElement(*s.finiteElements(), std::strtoul(element, nullptr, 10), s.time());
        }
    }
    void observeWindow(const solver::Simulation& s) {
        trackRodTension(s, window);
        if (s.time() >= windowEnd) {
            std::printf("to %.2f us: tension %.3f GPa at t %.2f, z %.2f r %.2f\n", windowEnd,
                        window.gpa, window.timeUs, window.at.z, window.at.r);
            window = Tension{};
            windowEnd += windowEnd < 6.0 ? 0.25 : 2.0;
        }
    }
    static void printElement(const fe::FeSolid& fe, std::size_t i, double time) {
        const auto& el = fe.elements();
        const auto& nd = fe.nodes();
        std::size_t face = 0; // the rod's node on the axis nearest the anvil
        double faceZ = -1e30;
        for (std::size_t n = 0; n < nd.size(); ++n) {
            if (nd.body[n] == 0 && nd.r[n] < 1e-9 && nd.z[n] > faceZ) {
                face = n;
                faceZ = nd.z[n];
            }
        }
        const double seq = material::StressDeviator{el.szz[i], el.srr[i], el.srz[i]}.vonMises();
        std::printf("t %.2f face centre node z %.4f vz %.4f; element %zu p %.3f q %.3f seq %.3f "
                    "s* %.2f szz %.3f srr %.3f shh %.3f ep %.3f D %.3f\n",
                    time, nd.z[face], nd.vz[face], i, el.p[i], el.q[i], seq,
                    -el.p[i] / std::max(seq, 1e-9), el.szz[i], el.srr[i], -el.szz[i] - el.srr[i],
                    el.plasticStrain[i], el.damage[i]);
    }
};

void expectWholeRod(double speedKmS, const char* discretization, double spacing, double lengthMm,
                    double footMm, Anvil anvil, const json& rodPatch = nullptr) {
    if (const char* choice = std::getenv("TAYLOR_ANVIL")) {
        const std::string name = choice;
        ASSERT_TRUE(name == "steel" || name == "mirror") << "TAYLOR_ANVIL=steel|mirror: " << name;
        anvil = name == "steel" ? Anvil::Steel : Anvil::Mirror;
    }
    json doc = taylorScene(speedKmS, discretization, spacing, anvil);
    applyDiagnosticKnobs(doc, rodPatch);
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene,
                           scene::sceneLibrary(doc.value("materials", json::object()), "<test>"));
    Tension tension;
    FailureLog failures;
    const bool diagnose = std::getenv("TAYLOR_DIAG") != nullptr;
    Trace trace;
    test::runUntil(sim, kEndTimeUs, [&](const solver::Simulation& s) {
        if (diagnose) {
            if (feRod(s)) {
                failures.observe(*s.finiteElements(), s.time());
            } else {
                failures.observe(s.particles(), s.time());
            }
        }
        trackRodTension(s, tension);
        trace.observe(s);
    });
    std::printf("largest principal tension in the rod %.3f GPa at t %.2f us, z %.2f r %.2f mm "
                "(expanding at %.2e /s); largest mean tension %.3f GPa\n",
                tension.gpa, tension.timeUs, tension.at.z, tension.at.r, tension.expansionPerS,
                tension.meanGPa);
    const RodShape rod = measure(sim);
    std::printf("Taylor %s %.0f m/s, spacing %.3f mm: L_f %.2f mm (test %.1f), D_f %.2f mm "
                "(test %.1f); %zu of %zu points failed, %zu eroded; energy error %.2e\n",
                discretization, speedKmS * 1000.0, spacing, rod.lengthMm, lengthMm,
                rod.footDiameterMm, footMm, rod.failed, rod.points, rod.eroded, sim.energyError());
    EXPECT_EQ(rod.failed, 0u) << "the test's rods were recovered whole";
    EXPECT_EQ(rod.eroded, 0u);
    EXPECT_TRUE(test::near("L_f [mm]", rod.lengthMm, lengthMm, 0.0, 0.10));
    EXPECT_TRUE(test::near("D_f [mm]", rod.footDiameterMm, footMm, 0.0, 0.10));
}

} // namespace

// Spacing 0.2 mm (38 elements across), on the 4340 steel anvil. At 0.1 mm the 227 m/s rod ends
// 10.04 mm long with a 9.86 mm foot and nothing fails (even at 1.2 GPa of spall strength); the
// 339 m/s rod ends 8.94 mm long with a 12.07 mm foot, nothing failed and 2 of 4332 elements
// eroded (by the erosion strain, at the foot's rim). On the rigid anvil (TAYLOR_ANVIL=mirror:
// two rods at +-V) the 227 m/s rod's core carries 1.60 GPa of principal tension (0.96 on steel)
// and the 339 m/s rod's 2.44 GPa (1.37 on steel), where 21 points fail: a rigid face reflects the
// full impact stress, steel about 0.73 of it (elastic impedances rho c_L 46 and 17 GPa s/km), and
// the lateral release that converges on the axis carries that difference into the core.
TEST(TaylorAnvil, FeRodAt227MetresPerSecondStaysWhole) {
    expectWholeRod(0.227, "fe", test::envOr("TAYLOR_H", 0.2), 10.2, 9.9, Anvil::Steel);
}
TEST(TaylorAnvil, FeRodAt339MetresPerSecondStaysWhole) {
    expectWholeRod(0.339, "fe", test::envOr("TAYLOR_H", 0.2), 8.3, 12.8, Anvil::Steel);
}

// The spall strength the measured 6061 plate series fixes in this model (1.2 GPa,
// SpallPlate_test.cpp, PublishedSeries...; workflows/materials/spall-1.2.json) keeps the
// 227 m/s rod whole: its core's largest principal tension is 0.96 GPa (1.02 at 0.1 mm). On the
// rigid anvil 42 of its 1083 points fail.
TEST(TaylorAnvil, FeRodAt227MetresPerSecondStaysWholeAtTheSeriesSpallStrength) {
    expectWholeRod(0.227, "fe", test::envOr("TAYLOR_H", 0.2), 10.2, 9.9, Anvil::Steel,
                   {{"spall", {{"strength_GPa", 1.2}}}});
}

// Known failures, the open part of issue #24; run them with --gtest_also_run_disabled_tests.
// At 1.2 GPa the 339 m/s rod fails 27 of its 1083 points, 24 of them in a core within 1.2 mm of
// the axis and 0.5-1.9 mm behind the face (six columns, not the axis column alone), which
// without failure carries 1.37 GPa of principal and 1.24 GPa of mean tension (the series' plates
// spall at 0.97-1.00 GPa of mean tension at that input): no rate-independent strength keeps
// this rod whole and spalls the 196 m/s plate (largest tension 1.29 GPa). SPH rods fail at
// 227 m/s at the library's 2.0 GPa already, behind the face and by spall in the core.
// Measurements in docs/notebook/spall-and-damage.md and docs/notebook/axis.md.
TEST(TaylorAnvil, DISABLED_FeRodAt339MetresPerSecondStaysWholeAtTheSeriesSpallStrength) {
    expectWholeRod(0.339, "fe", test::envOr("TAYLOR_H", 0.2), 8.3, 12.8, Anvil::Steel,
                   {{"spall", {{"strength_GPa", 1.2}}}});
}
TEST(TaylorAnvil, DISABLED_SphRodAt227MetresPerSecondStaysWhole) {
    expectWholeRod(0.227, "sph", test::envOr("TAYLOR_SPH_H", 0.2), 10.2, 9.9, Anvil::Steel);
}
TEST(TaylorAnvil, DISABLED_SphRodAt339MetresPerSecondStaysWhole) {
    expectWholeRod(0.339, "sph", test::envOr("TAYLOR_SPH_H", 0.2), 8.3, 12.8, Anvil::Steel);
}
