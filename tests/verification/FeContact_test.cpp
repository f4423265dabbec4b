// Contact between SPH and FE bodies and between FE bodies (issue #5, item 2): an Al block
// (SPH or FE, 1 mm x 0.25 mm in plane strain) dropped at 0.1 km/s on an FE steel plate
// rebounds (1-D elastic theory: the stiffer plate sends it back at about 0.044 km/s once the
// release from its rear face has crossed it twice, 0.08 us), never sinks into the plate by
// more than a tenth of a
// particle spacing (element size for an FE body), and the total z-momentum is conserved to
// 1e-6 of the initial momentum through the contact (momentum exchange is pairwise and exact;
// planar mode, where the SPH pair forces conserve momentum to round-off, so that the check
// measures the contact alone). The total energy is conserved to 0.5 % of the small impact
// energy: measured 0.12 % (SPH block) and 0.22 % (FE block). The contact stops each touching
// pair inelastically, and books as heat the kinetic energy that takes less what the
// elements' forces added unpaid in the step (contact/ContactHeat.hpp); booking all of it,
// the errors were 7.8 % and 37 %, and with the pressing of lasting FE contacts left out,
// 7.8 % and 2.2 %.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "Tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <vector>

using namespace hvi;
using nlohmann::json;

namespace {

constexpr double kSpacing = 0.025;
constexpr double kSpeed = 0.1;

json dropScene(bool feProjectile) {
    json projectile = {{"name", "projectile"},
                       {"role", "projectile"},
                       {"material", "Al6061-T6"},
                       {"velocity", {{"z_km_s", kSpeed}}}};
    // An Al block 0.25 mm thick and 1 mm wide, 1 um above the plate (a particle touches a
    // surface at its radius, half a spacing, which is where the lattice puts the block's front
    // row).
    projectile["shape"] = {{"type", "rectangle"},
                           {"z_min_mm", -0.251},
                           {"z_max_mm", -0.001},
                           {"r_min_mm", 1.0},
                           {"r_max_mm", 2.0}};
    if (feProjectile) {
        projectile["discretization"] = "fe";
    }
    return {{"geometry", "planar"},
            {"sph", {{"particle_spacing_mm", kSpacing}}},
            {"fe", {{"element_size_mm", kSpacing}}},
            {"run",
             {{"end_time_us", 0.6},
              {"stop_debris_speed_km_s", 0.0},
              {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 20.0}}},
            {"bodies",
             {projectile,
              {{"name", "plate"},
               {"role", "bumper"},
               {"material", "Steel4340"},
               {"discretization", "fe"},
               {"shape",
                {{"type", "rectangle"},
                 {"z_min_mm", 0.0},
                 {"z_max_mm", 1.0},
                 {"r_min_mm", 0.0},
                 {"r_max_mm", 3.0}}}}}}};
}

/// z of the plate's front surface at r, interpolated between its front nodes.
double frontSurface(const fe::FeSolid& fe, double r) {
    const auto& nd = fe.nodes();
    double best = 1e300, zAt = 0.0;
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (nd.body[n] != 1) {
            continue;
        }
        // Front nodes are the upstream-most of each column: take the nearest in r among the
        // nodes within half a spacing of the initial front face.
        if (std::fabs(nd.z[n]) < 0.5 * kSpacing + 0.05 && std::fabs(nd.r[n] - r) < best) {
            best = std::fabs(nd.r[n] - r);
            zAt = nd.z[n];
        }
    }
    return zAt;
}

struct DropResult {
    double maxSink = 0.0;       ///< deepest penetration of the projectile past the surface [mm]
    double momentumDrift = 0.0; ///< max |p_z - p_z0| / p_z0
    double maxEnergyError = 0.0;
    double finalProjectileVz = 0.0;
    double dissipated = 0.0; ///< contact heat / initial energy
};

DropResult drop(bool feProjectile) {
    const auto scene = test::makeScene(dropScene(feProjectile));
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    const double p0 = sim.totals().momentumZ;
    DropResult out;
    auto track = [&](const solver::Simulation& s) {
        const auto t = s.totals();
        out.momentumDrift = std::max(out.momentumDrift, std::fabs(t.momentumZ - p0) / p0);
        out.maxEnergyError = std::max(out.maxEnergyError, std::fabs(s.energyError()));
        out.dissipated = s.contact()->dissipatedEnergy() / s.initialEnergy();
        const fe::FeSolid& fe = *s.finiteElements();
        if (feProjectile) {
            // The projectile's leading nodes against the plate's front surface.
            const auto& nd = fe.nodes();
            for (std::size_t n = 0; n < nd.size(); ++n) {
                if (nd.body[n] == 0) {
                    out.maxSink = std::max(out.maxSink, nd.z[n] - frontSurface(fe, nd.r[n]));
                }
            }
        } else {
            // A particle rests at half a spacing from the surface (its radius).
            const auto& ps = s.particles();
            for (std::size_t i = 0; i < ps.size(); ++i) {
                if (ps.body[i] != 0) {
                    continue; // the plate's reserve of particles for eroded elements
                }
                out.maxSink =
                    std::max(out.maxSink, ps.z[i] + 0.5 * kSpacing - frontSurface(fe, ps.r[i]));
            }
        }
    };
    test::runUntil(sim, 0.6, track);
    double m = 0.0, pz = 0.0;
    if (feProjectile) {
        const auto& nd = sim.finiteElements()->nodes();
        for (std::size_t n = 0; n < nd.size(); ++n) {
            if (nd.body[n] == 0) {
                m += nd.mass[n];
                pz += nd.mass[n] * nd.vz[n];
            }
        }
    } else {
        const auto& ps = sim.particles();
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (ps.body[i] == 0) {
                m += ps.mass[i];
                pz += ps.mass[i] * ps.vz[i];
            }
        }
    }
    out.finalProjectileVz = pz / m;
    std::printf("%s on FE plate: sink %.4f mm (%.2f spacings), momentum drift %.2e, energy "
                "error %.2e (contact heat %.2e), projectile vz %.4f km/s after 0.6 us\n",
                feProjectile ? "FE block" : "SPH block", out.maxSink, out.maxSink / kSpacing,
                out.momentumDrift, out.maxEnergyError, out.dissipated, out.finalProjectileVz);
    return out;
}

void check(const DropResult& r) {
    EXPECT_LT(r.finalProjectileVz, 0.0) << "the projectile must rebound";
    EXPECT_LE(r.maxSink, 0.1 * kSpacing) << "interpenetration beyond a tenth of a spacing";
    EXPECT_LT(r.momentumDrift, 1e-6);
    EXPECT_LT(r.maxEnergyError, 5e-3);
}

} // namespace

TEST(FeContact, SphBlockReboundsFromFePlate) {
    check(drop(false));
}
TEST(FeContact, FeBlockReboundsFromFePlate) {
    check(drop(true));
}

namespace {

constexpr double kImpactSize = 0.04;

// A uniform impact (axisymmetric): an Al plate 0.4 mm thick and 1.5 mm in radius, SPH or FE,
// at 2 km/s on an FE Al plate 0.6 mm thick, 0.04 mm elements and particle spacing. Far from
// the edges, and until the release from the flyer's edge reaches the axis (0.25 us), the
// impact is one-dimensional: the struck surface should move, and its front row strain, alike
// at every radius.
scene::Scene uniformImpactScene(bool sphFlyer) {
    json flyer = test::plateBody("flyer", "projectile", -0.42, 0.4, 1.5);
    if (!sphFlyer) {
        flyer["discretization"] = "fe";
    }
    flyer["velocity"] = {{"z_km_s", 2.0}};
    json target = test::plateBody("target", "rear_wall", 0.0, 0.6, 2.0);
    target["discretization"] = "fe";
    return test::makeScene({{"geometry", "axisymmetric"},
                            {"sph", {{"particle_spacing_mm", kImpactSize}}},
                            {"fe", {{"element_size_mm", kImpactSize}}},
                            {"run", {{"end_time_us", 0.25}}},
                            {"bodies", {flyer, target}}});
}

/// The nodes that started on the axis are still on it: contact gives them no radial impulse.
void expectAxisNodesOnAxis(const fe::NodeSet& nd, const std::vector<double>& r0) {
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (r0[n] == 0.0) {
            EXPECT_EQ(nd.r[n], 0.0) << "axis node " << n << " left the axis";
        }
    }
}

} // namespace

// FE on FE: the axis element of the target's front row against the median of the row at
// r = 0.2-0.6 mm at 0.25 us. The contact impulses used to be resolved in a single pass in
// slave order, which left the struck surface's nodes at velocities that followed the order
// (0.891 km/s on the axis to 0.848 km/s at r = 0.28 mm just after touching) and the axis
// element at 0.42 plastic strain against 0.24 beside it (+71 %). The impulses solved
// together gave +4 %, +9 % by 2026-11-23 (with the axis nodes drifting off the axis), +12 %
// since the axis nodes take no radial impulse, +3.6 % since a surface pressing back makes no
// heat (UniformFeBlowHeatsTheFrontRowsAlike); the bar is 8 %, which the +12 % fails.
TEST(FeContact, UniformImpactStrainsTheAxisElementLikeItsNeighbours) {
    solver::Simulation sim(uniformImpactScene(false),
                           scene::sceneLibrary(json::object(), "<test>"));
    const std::vector<double> z0 = sim.finiteElements()->nodes().z;
    const std::vector<double> r0 = sim.finiteElements()->nodes().r;
    test::runUntil(sim, 0.25);
    const fe::FeSolid& fe = *sim.finiteElements();
    const auto& el = fe.elements();
    const auto& nd = fe.nodes();
    expectAxisNodesOnAxis(nd, r0);
    // The target's front row: elements with a node that started at z = 0; the axis element
    // is the one with a node that started at r = 0.
    double axisStrain = -1.0;
    std::vector<double> row;
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (el.body[i] != 1) {
            continue;
        }
        double zMin = 1e300, rMin = 1e300, rMax = -1e300, rMin0 = 1e300;
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(el.node(i, a));
            zMin = std::min(zMin, z0[n]);
            rMin = std::min(rMin, nd.r[n]);
            rMax = std::max(rMax, nd.r[n]);
            rMin0 = std::min(rMin0, r0[n]);
        }
        if (std::fabs(zMin) > 0.5 * kImpactSize) {
            continue;
        }
        if (rMin0 == 0.0) {
            axisStrain = el.plasticStrain[i];
        } else if (rMin > 0.2 && rMax < 0.6) {
            row.push_back(el.plasticStrain[i]);
        }
    }
    ASSERT_GE(axisStrain, 0.0) << "no axis element in the target's front row";
    ASSERT_GE(row.size(), 8u);
    std::sort(row.begin(), row.end());
    const double median = row[row.size() / 2];
    std::printf("front row plastic strain: axis element %.3f, median at r = 0.2-0.6 mm %.3f "
                "(%+.1f %%)\n",
                axisStrain, median, 100.0 * (axisStrain / median - 1.0));
    EXPECT_GT(median, 0.1) << "the impact should strain the row plastically";
    EXPECT_LE(std::fabs(axisStrain / median - 1.0), 0.08);
}

// FE on FE: the first blow heats both front rows alike at every radius. Two touching
// surfaces have a constraint each way; when the impulse passes to the other constraint (the
// struck plate's axis node pressing back on the flyer's), that pressing is the unpaid kick of
// the elements' forces and makes no heat (contact/ContactHeat.hpp). Booked as a new
// collision, it gave the target's axis element 0.220 MJ/kg against 0.104 beside it at
// 0.011 us (2.1 times; the flyer's 0.215 against 0.101). Each side's heat goes to the
// elements around its nodes by mass.
TEST(FeContact, UniformFeBlowHeatsTheFrontRowsAlike) {
    solver::Simulation sim(uniformImpactScene(false),
                           scene::sceneLibrary(json::object(), "<test>"));
    const std::vector<double> z0 = sim.finiteElements()->nodes().z;
    const std::vector<double> r0 = sim.finiteElements()->nodes().r;
    test::runUntil(sim, 0.011);
    const auto& el = sim.finiteElements()->elements();
    for (const int32_t body : {0, 1}) {
        // The row at the struck face: the flyer's front row, the target's.
        const double face = body == 0 ? -0.02 : 0.0;
        double eMin = 1e300, eMax = 0.0;
        int count = 0;
        for (std::size_t i = 0; i < el.size(); ++i) {
            if (el.body[i] != body) {
                continue;
            }
            bool onFace = false;
            double rMax = 0.0;
            for (int a = 0; a < 4; ++a) {
                const auto n = static_cast<std::size_t>(el.node(i, a));
                onFace = onFace || std::fabs(z0[n] - face) < 1e-9;
                rMax = std::max(rMax, r0[n]);
            }
            if (onFace && rMax < 0.6) {
                eMin = std::min(eMin, el.e[i]);
                eMax = std::max(eMax, el.e[i]);
                ++count;
            }
        }
        std::printf("body %d front row (%d elements): specific internal energy %.4f to %.4f "
                    "MJ/kg\n",
                    body, count, eMin, eMax);
        ASSERT_GE(count, 10);
        EXPECT_GT(eMin, 0.05) << "the blow should have heated the row";
        EXPECT_LE(eMax / eMin - 1.0, 0.05);
    }
}

// SPH on FE: the first blow of a uniform SPH plate moves the struck FE surface uniformly,
// axis node included (the footprint shares match the nodes' lumped masses,
// contact/Footprint.hpp). Measured just after first contact (0.012 us) over r < 0.6 mm: the
// largest deviation from the median speed is 0.4 % (as with point contact, which splits a
// particle centred on a segment equally too); the radius-weighted hat integrals (mortar in
// RZ) left the axis node at 0.69 of its neighbours' speed (31 %). The bar is 5 %. (Later the
// SPH first column's own axial excess drives the axis node ahead: at 0.25 us the axis
// element has +388 % of its row's plastic strain, docs/notebook/fe-erosion.md.)
TEST(FeContact, UniformSphBlowMovesTheStruckSurfaceUniformly) {
    solver::Simulation sim(uniformImpactScene(true), scene::sceneLibrary(json::object(), "<test>"));
    const std::vector<double> z0 = sim.finiteElements()->nodes().z;
    const std::vector<double> r0 = sim.finiteElements()->nodes().r;
    const std::vector<double> flyerZ0 = sim.particles().z;
    test::runUntil(sim, 0.012);
    const auto& nd = sim.finiteElements()->nodes();
    expectAxisNodesOnAxis(nd, r0);
    std::vector<double> front;
    double axis = 0.0;
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (nd.body[n] == 1 && z0[n] == 0.0 && nd.r[n] < 0.6) {
            front.push_back(nd.vz[n]);
            if (nd.r[n] == 0.0) {
                axis = nd.vz[n];
            }
        }
    }
    ASSERT_GE(front.size(), 10u);
    std::vector<double> sorted = front;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    double spread = 0.0;
    for (const double v : front) {
        spread = std::max(spread, std::fabs(v / median - 1.0));
    }
    std::printf("struck surface after first contact: median vz %.3f km/s, axis node %.3f, "
                "largest deviation %.1f %%\n",
                median, axis, 100.0 * spread);
    EXPECT_GT(median, 0.5) << "the blow should have moved the surface";
    EXPECT_LE(spread, 0.05);
    // The flyer's front layer took the collision's heat alike at every radius. The heat of
    // each constraint is J (v_n before + v_n after) / 2, independent of the order of the
    // impulse passes. Summing each kick's energy as it was made gave the layer 0.418 to
    // 0.581 MJ/kg at 0.012 us (+39 %, the most on the first columns); now 0.412 to 0.417.
    const auto& ps = sim.particles();
    double frontZ0 = -1e300; // the flyer's (body 0's) front layer; other slots are unused
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.body[i] == 0 && ps.alive[i]) {
            frontZ0 = std::max(frontZ0, flyerZ0[i]);
        }
    }
    double eMin = 1e300, eMax = 0.0;
    int frontCount = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.body[i] == 0 && ps.alive[i] && flyerZ0[i] > frontZ0 - 0.25 * kImpactSize &&
            ps.r[i] < 0.6) {
            eMin = std::min(eMin, ps.e[i]);
            eMax = std::max(eMax, ps.e[i]);
            ++frontCount;
        }
    }
    std::printf("front layer (%d particles) specific internal energy %.4f to %.4f MJ/kg\n",
                frontCount, eMin, eMax);
    ASSERT_GE(frontCount, 10);
    EXPECT_GT(eMin, 0.1) << "the collision should have heated the front layer";
    EXPECT_LE(eMax / eMin - 1.0, 0.02);
}
