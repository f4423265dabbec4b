// Runs with finite-element bodies (optional in a run file): a rear wall meshed with quads
// instead of particles. The metrics read elements as items (centroid, nodal mass share), an
// eroded column of elements perforates the wall, the counts report nodes and elements, and
// the pictures draw the quads.
#include "AssessScenes.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/Pictures.hpp"
#include "assess/RearWallDamageProfile.hpp"
#include "assess/Verdict.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using namespace hvi;
using test::SyntheticRun;

namespace {

nlohmann::json feWallScene() {
    auto doc = test::whippleScene();
    doc["bodies"][2]["discretization"] = "fe";
    return doc;
}

/// Erodes the wall's elements whose centroid is within `radius` of the axis.
std::size_t erodeCore(SyntheticRun& run, double radius) {
    auto& fe = run.feSnapshots.back();
    std::size_t eroded = 0;
    for (std::size_t e = 0; e < fe.elements.alive.size(); ++e) {
        double r = 0.0;
        for (std::size_t k = 0; k < 4; ++k) {
            r += 0.25 * fe.nodes.r[static_cast<std::size_t>(fe.elements.connectivity[4 * e + k])];
        }
        if (r < radius) {
            fe.elements.alive[e] = 0;
            ++eroded;
        }
    }
    return eroded;
}

/// Appends to every snapshot one unused particle slot per wall element (Alive 0, Mass 0, at
/// the element's centroid), as hvi-run holds them in reserve for eroded elements.
void addReserveSlots(SyntheticRun& run) {
    const auto& fe = run.initialFe;
    const std::size_t ne = fe.elements.alive.size();
    std::vector<io::ParticleFields*> all{&run.initial};
    for (auto& snap : run.snapshots) {
        all.push_back(&snap);
    }
    for (io::ParticleFields* f : all) {
        for (std::size_t e = 0; e < ne; ++e) {
            double z = 0.0, r = 0.0;
            for (std::size_t k = 0; k < 4; ++k) {
                const auto n = static_cast<std::size_t>(fe.elements.connectivity[4 * e + k]);
                z += 0.25 * fe.nodes.z[n];
                r += 0.25 * fe.nodes.r[n];
            }
            f->z.push_back(z);
            f->r.push_back(r);
            f->vz.push_back(0.0);
            f->vr.push_back(0.0);
            f->mass.push_back(0.0);
            f->density.push_back(2.703);
            f->pressure.push_back(0.0);
            f->internalEnergy.push_back(0.0);
            f->smoothingLength.push_back(0.065);
            f->damage.push_back(0.0);
            f->plasticStrain.push_back(0.0);
            if (!f->stressDeviator.empty()) {
                f->stressDeviator.insert(f->stressDeviator.end(), 3, 0.0);
            }
            f->bodyId.push_back(fe.elements.bodyId[e]);
            f->alive.push_back(0);
        }
    }
}

} // namespace

TEST(FiniteElements, UnusedParticleSlotsAreNotMaterial) {
    // An intact meshed wall whose reserve of particle slots (not alive, no mass) fills it:
    // the slots are no failed or deleted material, so the wall holds and nothing is counted.
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    const std::size_t particles = run.initial.z.size();
    addReserveSlots(run);
    ASSERT_EQ(run.initial.z.size(), particles + 2000);
    const auto a = test::assessSynthetic(run, "fe_reserve");
    ASSERT_TRUE(a.rearWallPerforated);
    EXPECT_FALSE(*a.rearWallPerforated);
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["verdict"], "NP");
    EXPECT_EQ(v["counts"]["particles"], particles);
    EXPECT_EQ(v["mass"]["deleted_particles"], 0);
}

TEST(FiniteElements, IntactMeshedWallIsNotPerforated) {
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    const auto a = test::assessSynthetic(run, "fe_intact");
    ASSERT_TRUE(a.rearWallPerforated);
    EXPECT_FALSE(*a.rearWallPerforated);
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["counts"]["elements"], 2000); // 20 x 100 cells of 0.05 mm
    EXPECT_EQ(v["counts"]["nodes"], 21 * 101);
    EXPECT_EQ(v["mass"]["eroded_elements"], 0);
    EXPECT_EQ(v["resolution"]["element_size_mm"], 0.05);
    // The wall's mass is on its nodes: counted in the initial mass.
    double nodeMass = 0.0;
    for (double m : run.initialFe.nodes.mass) {
        nodeMass += m;
    }
    double particleMass = 0.0;
    for (double m : run.initial.mass) {
        particleMass += m;
    }
    EXPECT_NEAR(a.initialMassMg, nodeMass + particleMass, 1e-9 * a.initialMassMg);
}

TEST(FiniteElements, ErodedColumnPerforatesTheWall) {
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    const std::size_t eroded = erodeCore(run, 0.2); // 4 columns x 20 rows
    EXPECT_EQ(eroded, 80u);
    const auto a = test::assessSynthetic(run, "fe_eroded");
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_TRUE(a.throughThicknessFailure);
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["verdict"], "P");
    EXPECT_EQ(v["mass"]["eroded_elements"], 80);
    EXPECT_EQ(v["counts"]["alive_elements"], 2000 - 80);
    EXPECT_NEAR(v["penetration_depth_mm"].get<double>(), 6.0 - 0.5, 1e-9);
}

TEST(FiniteElements, ParticlesOfErodedElementsDoNotCloseTheHole) {
    // The two axis columns eroded through the thickness and became particles (their reserve
    // slots alive, with mass, flying ahead of the wall as debris): the wall is open there,
    // within the axis band (3 x 0.05 mm), P and flagged.
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    const std::size_t particles = run.initial.z.size();
    EXPECT_EQ(erodeCore(run, 0.1), 40u);
    addReserveSlots(run);
    auto& snap = run.snapshots.back();
    const auto& elements = run.feSnapshots.back().elements;
    for (std::size_t e = 0; e < elements.alive.size(); ++e) {
        if (!elements.alive[e]) {
            snap.alive[particles + e] = 1;
            snap.mass[particles + e] = 1.0e-4;
            snap.z[particles + e] -= 0.5;
            snap.vz[particles + e] = -0.5;
        }
    }
    assess::AssessOptions options;
    options.keepSnapshots = {1};
    const auto a = test::assessSynthetic(run, "fe_axis_column", options);
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_EQ(a.openColumns, 2u);
    EXPECT_NEAR(a.perforationRadiusMm, 0.1, 1e-9);
    EXPECT_TRUE(a.axisConfined);
    // The damage profile (the pictures' curve) sees the same hole: those two columns failed
    // through their whole thickness, the next one intact.
    ASSERT_EQ(a.kept.size(), 1u);
    const auto profile = assess::rearWallDamageProfile(assess::materialItems(a.kept[0], a.first),
                                                       a.layout, a.criteria);
    ASSERT_TRUE(profile);
    EXPECT_DOUBLE_EQ(profile->failedFraction[0], 1.0);
    EXPECT_DOUBLE_EQ(profile->failedFraction[1], 1.0);
    EXPECT_DOUBLE_EQ(profile->failedFraction[2], 0.0);
}

TEST(FiniteElements, FlyingParticlesOfErodedElementsDoNotMoveTheRearSurface) {
    // The wall's rear row within r < 0.5 eroded and its particles flew 1.5 mm off the rear
    // face, undamaged and dense; ten projectile particles followed them 0.3 mm past the rear
    // face, moving outward. The rear surface is where the wall's elements end, not where the
    // flying particles are: the debris has crossed the wall (criterion b) and the particles
    // are reported as detached.
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    const std::size_t particles = run.initial.z.size();
    addReserveSlots(run);
    auto& snap = run.snapshots.back();
    auto& elements = run.feSnapshots.back().elements;
    std::size_t flying = 0;
    for (std::size_t e = 0; e < elements.alive.size(); ++e) {
        const std::size_t slot = particles + e;
        if (run.initial.r[slot] < 0.5 && run.initial.z[slot] > 5.95) {
            elements.alive[e] = 0;
            snap.alive[slot] = 1;
            snap.mass[slot] = 1.0e-4;
            snap.z[slot] += 1.5;
            snap.vz[slot] = 0.5;
            ++flying;
        }
    }
    ASSERT_EQ(flying, 10u);
    test::placeDebris(run, snap, 10, 6.3, 1.0);
    const auto a = test::assessSynthetic(run, "fe_flying_eroded");
    ASSERT_TRUE(a.rearWallPerforated);
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_TRUE(a.materialCrossed);
    EXPECT_FALSE(a.throughThicknessFailure);
    EXPECT_TRUE(a.detachedSpall);
}

TEST(FiniteElements, PicturesDrawTheMesh) {
    SyntheticRun run(feWallScene());
    run.addSnapshot(1.0);
    erodeCore(run, 0.5);
    const auto path = run.write(test::tempPath("fe_pictures.h5"));
    const io::RunFileReader reader(path);
    assess::AssessOptions options;
    options.keepSnapshots = {1};
    const auto a = assess::assessRun(reader, options);
    assess::PictureOptions po;
    po.directory = test::tempPath("fe_pictures").string();
    std::filesystem::remove_all(po.directory);
    const auto files = assess::writePictures(a, {1}, po);
    EXPECT_EQ(files.size(), 6u); // material, damage, rear-wall profile, 3 histories
    for (const auto& f : files) {
        EXPECT_GT(std::filesystem::file_size(f), 1000u) << f;
    }
}
