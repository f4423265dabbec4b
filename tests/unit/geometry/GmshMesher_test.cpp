// GmshMesher: structured division counts, a small mesh whose element and node counts are
// the hand-computed structured ones, the written file, and failures that leave nothing.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "geometry/GmshMesher.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <omp.h>
#include <stdexcept>
#include <string>

using hvi::geometry::GmshMesher;
using hvi::geometry::MeshRectangle;

namespace {

long elementCountInFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line == "$Elements") {
            long blocks = 0;
            long elements = -1;
            in >> blocks >> elements;
            return elements;
        }
    }
    return -1;
}

} // namespace

TEST(GmshMesher, Divisions) {
    EXPECT_EQ(GmshMesher::divisions(0.03, 0.015), 2u);  // exact, despite rounding
    EXPECT_EQ(GmshMesher::divisions(0.3, 0.1), 3u);     // 2.9999999999999996
    EXPECT_EQ(GmshMesher::divisions(0.0988, 0.03), 4u); // 3.29 -> 4
    EXPECT_EQ(GmshMesher::divisions(0.001, 0.015), 1u); // at least one
    EXPECT_EQ(GmshMesher::divisions(50.8, 0.015), 3387u);
}

// Two bodies: 0.1 x 1 mm at 0.05 mm -> 2 x 20 = 40 quads, 3 x 21 = 63 nodes;
// 0.254 x 1 mm at 0.05 mm -> ceil(5.08) = 6 x 20 = 120 quads, 7 x 21 = 147 nodes.
TEST(GmshMesher, SmallMeshHasTheStructuredCounts) {
    const std::vector<MeshRectangle> rects = {
        {"layer", 1.0, 1.1, 0.0, 1.0, 0.05},
        {"rear", 5.0, 5.254, 0.0, 1.0, 0.05},
    };
    const auto expected = GmshMesher::expectedCounts(rects);
    EXPECT_EQ(expected.elements, 160u);
    EXPECT_EQ(expected.nodes, 210u);

    const auto path = hvi::test::tempPath("GmshMesher_small.msh");
    std::filesystem::remove(path);
    const auto counts = GmshMesher::write(rects, path);
    EXPECT_EQ(counts.elements, 160u);
    EXPECT_EQ(counts.nodes, 210u);
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(elementCountInFile(path), 160);
    std::filesystem::path gmshName = path;
    gmshName += ".msh";
    EXPECT_FALSE(std::filesystem::exists(gmshName)) << "gmsh's own file name left behind";

    // A second session in the same process works (initialize/finalize are paired).
    EXPECT_EQ(GmshMesher::write(rects, path).elements, 160u);
}

TEST(GmshMesher, AnnulusAwayFromTheAxis) {
    // A ring 0.0508 mm wide, 5 mm high, at 0.02 mm: 3 x 250 quads.
    const std::vector<MeshRectangle> rects = {{"ring", 1.27, 6.27, 2.35585, 2.40665, 0.02}};
    const auto path = hvi::test::tempPath("GmshMesher_ring.msh");
    EXPECT_EQ(GmshMesher::write(rects, path).elements, 750u);
}

TEST(GmshMesher, LeavesTheOpenMpThreadCountAsItFoundIt) {
    // gmsh sets the OpenMP thread count to its General.NumThreads (1 by default) when it
    // meshes; every scene with an FE body then ran its whole simulation on one thread.
    const int before = omp_get_max_threads();
    omp_set_num_threads(3);
    const std::vector<MeshRectangle> rects = {{"plate", 0.0, 0.2, 0.0, 1.0, 0.05}};
    GmshMesher::write(rects, hvi::test::tempPath("GmshMesher_threads.msh"));
    EXPECT_EQ(omp_get_max_threads(), 3);
    omp_set_num_threads(before);
}

TEST(GmshMesher, BadRequestsWriteNothing) {
    const auto path = hvi::test::tempPath("GmshMesher_bad.msh");
    std::filesystem::remove(path);
    EXPECT_THROW(GmshMesher::write({}, path), std::invalid_argument);
    EXPECT_THROW(GmshMesher::write({{"empty", 1.0, 1.0, 0.0, 1.0, 0.1}}, path),
                 std::invalid_argument);
    EXPECT_THROW(GmshMesher::write({{"huge", 0.0, 100.0, 0.0, 100.0, 1e-4}}, path),
                 hvi::RuntimeFailure);
    EXPECT_FALSE(std::filesystem::exists(path));

    const auto missingDir = hvi::test::tempPath("no_such_dir/x.msh");
    EXPECT_THROW(GmshMesher::write({{"b", 0.0, 0.1, 0.0, 0.1, 0.05}}, missingDir),
                 hvi::RuntimeFailure);
    EXPECT_FALSE(std::filesystem::exists(missingDir));
}
