// Runs with finite-element bodies (optional in a run file): a rear wall meshed with quads
// instead of particles. The metrics read elements as items (centroid, nodal mass share), an
// eroded column of elements perforates the wall, the counts report nodes and elements, and
// the pictures draw the quads.
#include "AssessScenes.hpp"
#include "assess/Pictures.hpp"
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

} // namespace

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
