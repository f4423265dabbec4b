// Rear-wall perforation, the P/NP verdict (assess/RearWallPerforation.hpp), on a 1 mm rear
// wall (20 particles across) with failure patterns and debris placed by hand: through-
// thickness failure paths (straight, diagonal, eroded), paths that do not connect, material
// beyond the rear face, a bulged unbroken wall, stray particles, and perforation that must
// stay found once seen.
#include "AssessScenes.hpp"
#include "assess/Verdict.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi;
using test::placeDebris;
using test::SyntheticRun;

namespace {

constexpr double kSpacing = 0.05;
constexpr double kWallFront = 5.0;

/// Fails the rear-wall particles for which `where(z0, r0)` holds.
template <class Where>
void failWall(const SyntheticRun& run, io::ParticleFields& snap, Where where) {
    run.forBody(snap, "rear", [&](std::size_t i) {
        if (where(run.initial.z[i], run.initial.r[i])) {
            snap.damage[i] = 1.0;
        }
    });
}

/// Lattice row and column of a rear-wall particle.
long row(double z0) {
    return std::lround((z0 - kWallFront) / kSpacing - 0.5);
}
long column(double r0) {
    return std::lround(r0 / kSpacing - 0.5);
}

assess::Assessment assessWall(const SyntheticRun& run, const std::string& name) {
    auto a = test::assessSynthetic(run, name);
    EXPECT_TRUE(a.rearWallPerforated.has_value());
    return a;
}

/// The perforation's extent: open columns, outer radius [mm], confined to the axis band.
void expectExtent(const assess::Assessment& a, std::size_t openColumns, double radiusMm,
                  bool axisConfined) {
    EXPECT_EQ(a.openColumns, openColumns);
    EXPECT_NEAR(a.perforationRadiusMm, radiusMm, 1e-9);
    EXPECT_EQ(a.axisConfined, axisConfined);
}

} // namespace

TEST(RearWallPerforation, IntactWallWithDebrisInFrontIsNotPerforated) {
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 50, 4.9, 1.0);
    const auto a = assessWall(run, "wall_intact");
    EXPECT_FALSE(*a.rearWallPerforated);
    EXPECT_EQ(assess::verdictJson(a)["verdict"], "NP");
}

TEST(RearWallPerforation, FailedColumnThroughTheThicknessIsPerforation) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 < 0.3; });
    const auto a = assessWall(run, "wall_column");
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_TRUE(a.throughThicknessFailure);
    EXPECT_FALSE(a.materialCrossed);
    EXPECT_EQ(assess::verdictJson(a)["verdict"], "P");
}

TEST(RearWallPerforation, FailureThroughHalfTheThicknessIsNot) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double z0, double r0) { return r0 < 1.0 && z0 < 5.5; });
    const auto a = assessWall(run, "wall_half");
    EXPECT_FALSE(*a.rearWallPerforated);
    EXPECT_FALSE(a.throughThicknessFailure);
}

TEST(RearWallPerforation, DiagonalCrackConnectsThroughCornerNeighbours) {
    // One particle per row, each one column further out: a 45-degree crack, connected only
    // through diagonal neighbours (sqrt(2) spacings apart).
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0),
             [](double z0, double r0) { return column(r0) == row(z0) + 10; });
    const auto a = assessWall(run, "wall_diagonal");
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_TRUE(a.throughThicknessFailure);
}

TEST(RearWallPerforation, CrackWithAGapIsNot) {
    // The same crack with rows 9 and 10 shifted by 3 columns: no connected path.
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double z0, double r0) {
        const long shift = row(z0) >= 10 ? 3 : 0;
        return column(r0) == row(z0) + 10 + shift;
    });
    const auto a = assessWall(run, "wall_gap");
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, DisconnectedFrontAndRearDamageIsNot) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double z0, double r0) {
        return (r0 < 0.5 && z0 < 5.6) || (r0 > 1.0 && r0 < 1.5 && z0 > 5.4);
    });
    const auto a = assessWall(run, "wall_disconnected");
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, ErodedPlugIsPerforation) {
    // Particles deleted (Alive = 0) count as eroded: a ring of them through the thickness.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "rear", [&](std::size_t i) {
        const double r0 = run.initial.r[i];
        if (r0 > 0.8 && r0 < 0.9) {
            snap.alive[i] = 0;
        }
    });
    EXPECT_TRUE(*assessWall(run, "wall_eroded").rearWallPerforated);
}

TEST(RearWallPerforation, MaterialBeyondTheRearFaceIsPerforation) {
    // Ten projectile particles 0.3 mm behind an otherwise intact wall, moving outward.
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 10, 6.3, 1.0);
    const auto a = assessWall(run, "wall_crossed");
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_TRUE(a.materialCrossed);
    EXPECT_FALSE(a.throughThicknessFailure);
}

TEST(RearWallPerforation, MaterialBehindMovingBackIsNot) {
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 10, 6.3, -0.5);
    EXPECT_FALSE(*assessWall(run, "wall_backwards").rearWallPerforated);
}

TEST(RearWallPerforation, TwoStrayParticlesAreNot) {
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 2, 6.3, 1.0);
    EXPECT_FALSE(*assessWall(run, "wall_stray").rearWallPerforated);
}

TEST(RearWallPerforation, BulgedUnbrokenWallHoldingDebrisIsNot) {
    // The wall within r < 2 bulges into a dome 1.5 mm deep at the axis (more than its
    // thickness) without failing; debris rests in the dent, behind the wall's original rear
    // face but in front of its material. (A block moved 1.5 mm with a sheared edge would be a
    // plug that has left the wall: a perforation.)
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "rear", [&](std::size_t i) {
        const double r0 = run.initial.r[i];
        if (r0 < 2.0) {
            snap.z[i] += 1.5 * (1.0 - 0.25 * r0 * r0);
            snap.vz[i] = 0.2;
        }
    });
    placeDebris(run, snap, 30, 6.3, 0.2);
    const auto a = assessWall(run, "wall_bulge");
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, FailedWallMaterialInPlaceStillHoldsDebris) {
    // The wall within r < 1 failed through its thickness (criterion a) and bulged 0.3 mm;
    // debris behind the original rear face but in front of that failed material has not
    // crossed the wall (criterion b).
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "rear", [&](std::size_t i) {
        if (run.initial.r[i] < 1.0) {
            snap.z[i] += 0.3;
            snap.damage[i] = 1.0;
        }
    });
    placeDebris(run, snap, 30, 6.1, 0.5);
    const auto a = assessWall(run, "wall_failed_in_place");
    EXPECT_TRUE(a.throughThicknessFailure);
    EXPECT_FALSE(a.materialCrossed);
    EXPECT_FALSE(a.detachedSpall);
}

TEST(RearWallPerforation, DetachedSpallIsReportedButIsNotPerforation) {
    // The last three rows within r < 0.5 failed and flew 1 mm off the rear face.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "rear", [&](std::size_t i) {
        if (run.initial.r[i] < 0.5 && run.initial.z[i] > 5.85) {
            snap.z[i] += 1.0;
            snap.vz[i] = 0.5;
            snap.damage[i] = 1.0;
        }
    });
    const auto a = assessWall(run, "wall_spall");
    EXPECT_TRUE(a.detachedSpall);
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, ASoundScabThatLeftTheWallIsDetachedSpallWithItsMass) {
    // A scab: the last 8 rows within r < 1 are sound but 1 mm behind the wall, flying off;
    // the row under them failed in place. The wall's rear surface is the wall's, not the
    // scab's: the scab is detached spall, all of its mass, and no bulge.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    double scabMass = 0.0;
    run.forBody(snap, "rear", [&](std::size_t i) {
        const long k = row(run.initial.z[i]);
        if (run.initial.r[i] < 1.0 && k >= 12) {
            snap.z[i] += 1.0;
            snap.vz[i] = 0.3;
            scabMass += snap.mass[i];
        } else if (run.initial.r[i] < 1.0 && k == 11) {
            snap.damage[i] = 1.0;
        }
    });
    const auto a = assessWall(run, "wall_scab");
    EXPECT_TRUE(a.detachedSpall);
    EXPECT_NEAR(a.spallMassMg, scabMass, 1e-9 * scabMass);
    EXPECT_LT(a.bulgeMm, kSpacing);
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, AStretchedBulgeIsStillOneWall) {
    // Within r < 1 the rear half of the wall is stretched axially by 80 % and moves out:
    // neighbours 1.8 spacings apart, beyond the 1.5-spacing link of failed material, still
    // one sound wall. A bulge of 0.4 mm, no spall.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "rear", [&](std::size_t i) {
        const double z0 = run.initial.z[i];
        if (run.initial.r[i] < 1.0 && z0 > kWallFront + 0.5) {
            snap.z[i] += 0.8 * (z0 - kWallFront - 0.5);
            snap.vz[i] = 0.2;
        }
    });
    const auto a = assessWall(run, "wall_stretched");
    EXPECT_FALSE(a.detachedSpall);
    EXPECT_NEAR(a.bulgeMm, 0.8 * (0.5 - 0.5 * kSpacing), 1e-6);
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(RearWallPerforation, OncePerforatedAlwaysPerforated) {
    // Debris crosses at 1 us; by 1.5 us it has left the domain (deleted): still P, first seen
    // at 1 us.
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 10, 6.3, 1.0);
    auto& later = run.addSnapshot(1.5);
    placeDebris(run, later, 10, 6.8, 1.0);
    run.forBody(later, "projectile", [&](std::size_t i) {
        if (later.z[i] > 6.5) {
            later.alive[i] = 0;
        }
    });
    const auto a = assessWall(run, "wall_history");
    EXPECT_FALSE(a.last().rearWall->perforated);
    EXPECT_TRUE(*a.rearWallPerforated);
    ASSERT_TRUE(a.perforationTimeUs);
    EXPECT_EQ(*a.perforationTimeUs, 1.0);
}

TEST(RearWallPerforation, SceneWithoutRearWallHasNoVerdict) {
    auto doc = test::whippleScene();
    doc["bodies"].erase(2);
    SyntheticRun run(doc);
    run.addSnapshot(1.0);
    const auto a = test::assessSynthetic(run, "wall_none");
    EXPECT_FALSE(a.rearWallPerforated.has_value());
    const auto v = assess::verdictJson(a);
    EXPECT_TRUE(v["verdict"].is_null());
    EXPECT_TRUE(v["rear_wall_perforated"].is_null());
}

// The perforation's extent (informational, docs/metrics.md): open columns, its outer radius
// and whether it lies within the axis band (3 spacings = 0.15 mm here).

TEST(RearWallPerforation, OpenColumnsGiveThePerforationsRadius) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 < 0.3; });
    const auto a = assessWall(run, "wall_open_radius");
    expectExtent(a, 6, 0.3, false);
    EXPECT_NEAR(a.openRadiusMm, 0.3, 1e-9);
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["rear_wall"]["open_columns"], 6);
    EXPECT_FALSE(v["rear_wall"]["axis_confined"].get<bool>());
    for (const auto& w : a.warnings) {
        EXPECT_EQ(w.find("of the axis"), std::string::npos) << w;
    }
}

TEST(RearWallPerforation, PerforationWithinTheAxisBandIsFlaggedNotOverruled) {
    // Two columns at the axis failed through the thickness: still P, flagged.
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 < 0.1; });
    const auto a = assessWall(run, "wall_axis_only");
    EXPECT_TRUE(*a.rearWallPerforated);
    expectExtent(a, 2, 0.1, true);
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["verdict"], "P");
    EXPECT_TRUE(v["rear_wall"]["axis_confined"].get<bool>());
    bool warned = false;
    for (const auto& w : a.warnings) {
        warned |= w.find("only within 0.1 mm of the axis") != std::string::npos;
    }
    EXPECT_TRUE(warned);
}

TEST(RearWallPerforation, TheAxisBandCountsColumnsWhenTheyAreWiderThanTheSpacing) {
    // A 5.01 mm wide wall holds 100 columns 0.0501 mm wide: its first three, 0.1503 mm, are
    // the axis band although 3 x 0.05 mm is 0.15 mm (a 40 mm FE wall meshed at 0.03 mm has
    // such columns).
    auto doc = test::whippleScene();
    doc["bodies"][2]["shape"]["outer_radius_mm"] = 5.01;
    SyntheticRun run(doc);
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 < 0.151; });
    const auto a = assessWall(run, "wall_wide_columns");
    EXPECT_TRUE(*a.rearWallPerforated);
    expectExtent(a, 3, 0.1503, true);
}

TEST(RearWallPerforation, ARingCrackAwayFromTheAxisIsNotConfinedToIt) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 > 1.0 && r0 < 1.1; });
    const auto a = assessWall(run, "wall_ring");
    EXPECT_TRUE(*a.rearWallPerforated);
    expectExtent(a, 2, 1.1, false);
}

TEST(RearWallPerforation, CrossingMaterialSetsTheRadiusWithoutAnOpenColumn) {
    // Debris out to r = 0.475 behind an intact wall: radius 0.475 + half a spacing.
    SyntheticRun run(test::whippleScene());
    placeDebris(run, run.addSnapshot(1.0), 10, 6.3, 1.0);
    expectExtent(assessWall(run, "wall_crossed_radius"), 0, 0.5, false);
}

TEST(RearWallPerforation, AHoleThatWidensLaterIsNotConfinedToTheAxis) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double, double r0) { return r0 < 0.1; });
    failWall(run, run.addSnapshot(1.5), [](double, double r0) { return r0 < 0.5; });
    expectExtent(assessWall(run, "wall_widens"), 10, 0.5, false);
}

TEST(RearWallPerforation, NoPerforationHasNoRadius) {
    SyntheticRun run(test::whippleScene());
    failWall(run, run.addSnapshot(1.0), [](double z0, double r0) { return r0 < 1.0 && z0 < 5.5; });
    const auto a = assessWall(run, "wall_no_radius");
    expectExtent(a, 0, 0.0, false);
    EXPECT_TRUE(assess::verdictJson(a)["rear_wall"]["perforation_radius_mm"].is_null());
}
