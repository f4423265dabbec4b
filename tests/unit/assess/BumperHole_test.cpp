// Bumper hole diameter on plates with holes of known size (assess/BumperHole.hpp): the hole
// is cut by moving the plate material inside it away as debris, and the metric must find the
// cut, ignore debris left in the hole or flying behind it, keep a bent or failed lip as plate
// (and report the failed zone beside the hole), and give the same diameter at two
// resolutions.
#include "AssessScenes.hpp"
#include "Tolerance.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi;
using test::SyntheticRun;

namespace {

/// Cuts a hole of radius `radius` in the bumper of `snap`: the material inside flies 3 mm
/// downstream at 2 km/s, fully damaged.
void cutHole(const SyntheticRun& run, io::ParticleFields& snap, double radius) {
    run.forBody(snap, "bumper", [&](std::size_t i) {
        if (run.initial.r[i] < radius) {
            snap.z[i] += 3.0;
            snap.vz[i] = 2.0;
            snap.damage[i] = 1.0;
        }
    });
}

double holeDiameter(const SyntheticRun& run, const std::string& name) {
    const auto a = test::assessSynthetic(run, name);
    EXPECT_TRUE(a.last().hole.has_value());
    return a.last().hole ? a.last().hole->diameterMm : -1.0;
}

} // namespace

TEST(BumperHole, IntactPlateHasNoHole) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    EXPECT_EQ(holeDiameter(run, "hole_none"), 0.0);
}

TEST(BumperHole, HoleOnALatticeLineIsExact) {
    // 1.5 mm is a column boundary at 0.05 mm spacing: the fraction jumps 0 -> 1 there and the
    // interpolation puts the edge exactly on it (round-off only).
    SyntheticRun run(test::whippleScene());
    cutHole(run, run.addSnapshot(1.0), 1.5);
    EXPECT_TRUE(test::near("diameter [mm]", holeDiameter(run, "hole_exact"), 3.0, 1e-9, 0.0));
}

TEST(BumperHole, HoleBetweenLatticeLinesIsWithinOneSpacing) {
    // A cut at 1.52 mm removes the columns centred below it (up to 1.475 mm): the true hole of
    // the lattice is 3.0 mm; any answer within one spacing of the cut is a correct one.
    SyntheticRun run(test::whippleScene());
    cutHole(run, run.addSnapshot(1.0), 1.52);
    EXPECT_TRUE(test::near("diameter [mm]", holeDiameter(run, "hole_between"), 3.04, 0.1, 0.0));
}

TEST(BumperHole, DebrisInTheHoleIsNotPlate) {
    // Expanded material (0.6 rho_ref) left near the plate's z and intact fragments flying
    // 2.5 mm behind it sit at the hole's radii: neither closes it.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "bumper", [&](std::size_t i) {
        const double r = run.initial.r[i];
        if (r < 0.8) {
            snap.density[i] *= 0.6;
            snap.damage[i] = 1.0;
        } else if (r < 1.5) {
            snap.z[i] += 2.5; // an intact fragment, flying
            snap.vz[i] = 1.5;
        }
    });
    EXPECT_TRUE(test::near("diameter [mm]", holeDiameter(run, "hole_debris"), 3.0, 1e-9, 0.0));
}

TEST(BumperHole, FailedLipBoundsTheHoleAndTheFailedZone) {
    // A 3 mm hole whose lip, out to 2 mm, failed (D = 1) but stayed in place: the clear hole
    // is 3 mm, the failed zone 4 mm.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    cutHole(run, snap, 1.5);
    run.forBody(snap, "bumper", [&](std::size_t i) {
        const double r = run.initial.r[i];
        if (r >= 1.5 && r < 2.0) {
            snap.damage[i] = 1.0;
        }
    });
    const auto a = test::assessSynthetic(run, "hole_failed_lip");
    ASSERT_TRUE(a.last().hole);
    EXPECT_TRUE(test::near("clear hole [mm]", a.last().hole->diameterMm, 3.0, 1e-9, 0.0));
    EXPECT_TRUE(
        test::near("failed zone [mm]", a.last().hole->failedZoneDiameterMm, 4.0, 1e-9, 0.0));
}

TEST(BumperHole, LowDensityMaterialIsNotPlate) {
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "bumper", [&](std::size_t i) {
        if (run.initial.r[i] < 1.0) {
            snap.density[i] *= 0.6; // expanded, hot material: below 0.8 rho_ref
        }
    });
    EXPECT_TRUE(test::near("diameter [mm]", holeDiameter(run, "hole_density"), 2.0, 1e-9, 0.0));
}

TEST(BumperHole, BentAndThickenedLipIsPlate) {
    // The lip between 1.5 and 2.0 mm is pushed 0.4 mm downstream (less than the thickness)
    // and the material from 1.2 to 1.5 mm is pushed out into it: still plate, the hole is
    // 3 mm.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    cutHole(run, snap, 1.2);
    run.forBody(snap, "bumper", [&](std::size_t i) {
        const double r = run.initial.r[i];
        if (r >= 1.2 && r < 1.5) {
            snap.r[i] += 0.5;
        }
        if (r >= 1.2 && r < 2.0) {
            snap.z[i] += 0.4;
            snap.vz[i] = 0.1;
        }
    });
    EXPECT_TRUE(test::near("diameter [mm]", holeDiameter(run, "hole_lip"), 3.0, 1e-9, 0.0));
}

TEST(BumperHole, CraterOpensOnlyBeyondHalfTheThickness) {
    // A crater that removes 40 % of the thickness leaves the plate closed; 60 % opens it
    // (the edge then lies within a spacing of 1 mm: the interpolation sees 40 % remaining in
    // the last open bin).
    for (const double removed : {0.4, 0.6}) {
        SyntheticRun run(test::whippleScene());
        auto& snap = run.addSnapshot(1.0);
        run.forBody(snap, "bumper", [&](std::size_t i) {
            if (run.initial.r[i] < 1.0 && run.initial.z[i] < removed * 0.5) {
                snap.z[i] -= 2.0; // ejected upstream
                snap.vz[i] = -1.0;
            }
        });
        const double d = holeDiameter(run, "hole_crater");
        if (removed < 0.5) {
            EXPECT_EQ(d, 0.0) << removed;
        } else {
            EXPECT_TRUE(test::near("diameter [mm]", d, 2.0, 0.05, 0.0)) << removed;
        }
    }
}

TEST(BumperHole, ResolutionDoesNotMoveTheEdge) {
    // The same cut at 0.05 and 0.025 mm: both put the edge at the cut (within a fine spacing).
    for (const double spacing : {0.05, 0.025}) {
        SyntheticRun run(test::whippleScene(spacing));
        cutHole(run, run.addSnapshot(1.0), 1.3);
        EXPECT_TRUE(
            test::near("diameter [mm]", holeDiameter(run, "hole_resolution"), 2.6, 0.025, 0.0))
            << "spacing " << spacing;
    }
}

TEST(BumperHole, HoleToTheEdgeIsFlagged) {
    SyntheticRun run(test::whippleScene());
    cutHole(run, run.addSnapshot(1.0), 10.0); // the whole bumper
    const auto a = test::assessSynthetic(run, "hole_edge");
    ASSERT_TRUE(a.last().hole);
    EXPECT_TRUE(a.last().hole->reachesEdge);
    // The two outermost bins are not used: the diameter is a lower bound, 2 (5 - 2 * 0.05).
    EXPECT_TRUE(test::near("diameter [mm]", a.last().hole->diameterMm, 9.8, 1e-9, 0.0));
    bool warned = false;
    for (const auto& w : a.warnings) {
        warned = warned || w.find("lower bound") != std::string::npos;
    }
    EXPECT_TRUE(warned);
}

TEST(BumperHole, GrowingHoleIsReadAtTheLastSnapshot) {
    SyntheticRun run(test::whippleScene());
    cutHole(run, run.addSnapshot(0.5), 0.8);
    cutHole(run, run.addSnapshot(1.0), 1.5);
    const auto a = test::assessSynthetic(run, "hole_growing");
    ASSERT_EQ(a.series.size(), 3u);
    EXPECT_EQ(a.series[0].hole->diameterMm, 0.0);
    EXPECT_TRUE(test::near("diameter at 0.5 us [mm]", a.series[1].hole->diameterMm, 1.6, 1e-9, 0));
    EXPECT_TRUE(test::near("final diameter [mm]", a.last().hole->diameterMm, 3.0, 1e-9, 0.0));
}
