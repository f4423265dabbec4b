// The debris cloud (assess/DebrisCloud.hpp): projectile material spread over a known range
// behind the bumper, with one light stray particle far ahead (as SPH produces near the axis,
// where ring masses are small) that must not define the leading edge or its speed.
#include "AssessScenes.hpp"
#include "Tolerance.hpp"

#include <algorithm>
#include <gtest/gtest.h>

using namespace hvi;
using test::SyntheticRun;

TEST(DebrisCloud, LeadingEdgeIgnoresALightStray) {
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    std::vector<std::size_t> projectile;
    run.forBody(snap, "projectile", [&](std::size_t i) { projectile.push_back(i); });
    const std::size_t n = projectile.size();
    ASSERT_GT(n, 100u);
    // Unit masses spread evenly over z in [2, 4], r = 0.01 k, all at 3 km/s...
    double mz = 0.0, mass = 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const std::size_t i = projectile[k];
        snap.z[i] = 2.0 + 2.0 * static_cast<double>(k) / static_cast<double>(n - 2);
        snap.r[i] = 0.01 * static_cast<double>(k);
        snap.vz[i] = 3.0;
        snap.mass[i] = 1.0;
        mz += snap.z[i];
        mass += 1.0;
    }
    // ...and a stray of 0.05 mg (3e-4 of the cloud, under the 1e-3 quantile) at 4.9 mm, 9 km/s.
    const std::size_t stray = projectile.back();
    snap.z[stray] = 4.9;
    snap.r[stray] = 0.0;
    snap.vz[stray] = 9.0;
    snap.mass[stray] = 0.05;
    mz += 0.05 * 4.9;
    mass += 0.05;

    const auto a = test::assessSynthetic(run, "debris_stray");
    const auto& d = a.last().debris;
    EXPECT_EQ(d.items, n);
    EXPECT_TRUE(test::near("mass [mg]", d.massMg, mass, 1e-9, 0.0));
    EXPECT_TRUE(test::near("leading edge [mm]", d.leadingEdgeZMm, 4.0, 1e-12, 0.0));
    EXPECT_TRUE(test::near("leading edge depth [mm]", d.leadingEdgeDepthMm, 3.5, 1e-12, 0.0));
    EXPECT_TRUE(test::near("leading edge speed [km/s]", d.leadingEdgeSpeedKmS, 3.0, 1e-12, 0.0));
    EXPECT_TRUE(test::near("fastest [km/s]", d.maxAxialSpeedKmS, 9.0, 1e-12, 0.0));
    EXPECT_TRUE(
        test::near("radius [mm]", d.radiusMm, 0.01 * static_cast<double>(n - 2), 1e-12, 0.0));
    EXPECT_TRUE(test::near("centre of mass [mm]", d.centreOfMassZMm, mz / mass, 1e-12, 1e-12));
    EXPECT_TRUE(test::near("centre-of-mass speed [km/s]", d.centreOfMassSpeedKmS,
                           (3.0 * (mass - 0.05) + 9.0 * 0.05) / mass, 1e-12, 1e-12));
}

TEST(DebrisCloud, HeavyLeaderIsTheLeadingEdge) {
    // The same stray, as heavy as the others: it is the cloud's front.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    std::size_t count = 0;
    run.forBody(snap, "projectile", [&](std::size_t i) {
        snap.z[i] = count == 0 ? 4.5 : 2.0;
        snap.vz[i] = count == 0 ? 5.0 : 2.0;
        snap.mass[i] = 1.0;
        ++count;
    });
    const auto a = test::assessSynthetic(run, "debris_leader");
    EXPECT_EQ(a.last().debris.leadingEdgeZMm, 4.5);
    EXPECT_EQ(a.last().debris.leadingEdgeSpeedKmS, 5.0);
}

TEST(DebrisCloud, MaterialStillInFrontOfTheBumperIsNotDebris) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(0.1); // the projectile has not arrived yet
    const auto a = test::assessSynthetic(run, "debris_none");
    EXPECT_EQ(a.last().debris.items, 0u);
    EXPECT_FALSE(a.debrisDepthMm.has_value());
}

TEST(DebrisCloud, BumperFragmentsAndFailedCoreMaterialAreDebris) {
    // Bumper material 1 mm behind the bumper is debris; core material is debris only when it
    // failed and moved downstream (an intact layer pushed back is not).
    SyntheticRun run(test::layerScene());
    auto& snap = run.addSnapshot(1.0);
    std::size_t bumper = 0, failedCore = 0;
    run.forBody(snap, "bumper", [&](std::size_t i) {
        if (run.initial.r[i] < 0.3) {
            snap.z[i] += 1.0;
            ++bumper;
        }
    });
    run.forBody(snap, "layer1", [&](std::size_t i) {
        if (run.initial.r[i] < 0.3) {
            snap.z[i] += 0.5;
            snap.damage[i] = 1.0;
            ++failedCore;
        } else if (run.initial.r[i] < 1.0) {
            snap.z[i] += 0.5; // pushed, intact
        }
    });
    const auto a = test::assessSynthetic(run, "debris_kinds");
    EXPECT_EQ(a.last().debris.items, bumper + failedCore);
}
