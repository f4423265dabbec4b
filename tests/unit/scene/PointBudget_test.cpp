// The point budget checked before a run allocates anything (scene/PointBudget.hpp): counts
// from the bodies' boxes against hand counts, FE bodies counted with their erosion slots,
// and the refusal that names the largest body.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "scene/PointBudget.hpp"

#include <gtest/gtest.h>

using namespace hvi;

namespace {

nlohmann::json budgetScene(bool feWall) {
    nlohmann::json wall = test::plateBody("wall", "rear_wall", 5.0, 1.0, 10.0);
    if (feWall) {
        wall["discretization"] = "fe";
    }
    return {{"id", "budget"},
            {"sph", {{"particle_spacing_mm", 0.1}}},
            {"run", {{"end_time_us", 1.0}}},
            {"bodies", {test::projectileBody(0.5, 3.0), wall}}};
}

} // namespace

TEST(PointBudget, CountsAreTheBodiesBoxesOverTheSpacingSquared) {
    const auto points = scene::estimatedPoints(test::makeScene(budgetScene(false)));
    ASSERT_EQ(points.size(), 2u);
    EXPECT_NEAR(points[0], 1.0 * 0.5 / 0.01, 1e-9);  // sphere r 0.5: box 1 x 0.5 mm
    EXPECT_NEAR(points[1], 1.0 * 10.0 / 0.01, 1e-9); // plate 1 x 10 mm: 10 x 100 points
    const auto fe = scene::estimatedPoints(test::makeScene(budgetScene(true)));
    EXPECT_NEAR(fe[1], 2.0 * 1000.0, 1e-9); // elements and their erosion slots
}

TEST(PointBudget, ARunBeyondTheMemoryIsRefusedNamingTheLargestBody) {
    const auto sc = test::makeScene(budgetScene(false));
    const double bytes = (50.0 + 1000.0) * scene::kBytesPerPoint;
    EXPECT_NO_THROW(scene::requirePointBudget(sc, "s.json", 1.01 * bytes));
    try {
        scene::requirePointBudget(sc, "s.json", 0.99 * bytes);
        FAIL() << "not refused";
    } catch (const InputError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].file, "s.json");
        EXPECT_EQ(e.issues()[0].pointer, "/bodies/1");
        EXPECT_NE(e.issues()[0].problem.find("'wall'"), std::string::npos) << e.what();
    }
}

TEST(PointBudget, AvailableMemoryIsReadFromTheSystem) {
    const double available = scene::availableMemoryBytes();
    EXPECT_GT(available, 1e6); // at least a megabyte, wherever the tests run
}
