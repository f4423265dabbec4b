// Stop and resume (developers' guide: long runs can be stopped and resumed): a run with SPH
// particles, an eroding FE plate and contact, checkpointed to disk midway and resumed in a new
// Simulation, ends bit for bit where the uninterrupted run ends.
#include "SceneRun.hpp"
#include "TestPaths.hpp"
#include "io/Checkpoint.hpp"
#include "solver/RunLoop.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

json resumeScene() {
    return {{"geometry", "axisymmetric"},
            {"sph", {{"particle_spacing_mm", 0.05}}},
            {"fe", {{"element_size_mm", 0.05}}},
            {"run", {{"end_time_us", 10.0}, {"stop_debris_speed_km_s", 0.0},
                     {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 4.5}}},
            {"bodies",
             {{{"name", "projectile"}, {"role", "projectile"}, {"material", "Al6061-T6"},
               {"shape", {{"type", "sphere"}, {"center_z_mm", -0.55}, {"radius_mm", 0.5}}},
               {"velocity", {{"z_km_s", 3.0}}}},
              {{"name", "plate"}, {"role", "bumper"}, {"material", "Al6061-T6"},
               {"discretization", "fe"},
               {"shape", {{"type", "plate"}, {"z_front_mm", 0.0}, {"thickness_mm", 0.5},
                          {"outer_radius_mm", 4.0}}}}}}};
}

} // namespace

TEST(FeResume, CheckpointedRunEndsBitForBit) {
    const auto sc = test::makeScene(resumeScene());
    const auto library = solver::sceneLibrary(json::object(), "<test>");
    solver::Simulation straight(sc, library);
    for (int k = 0; k < 150; ++k) {
        straight.advance();
    }
    const auto path = test::tempPath("fe_resume.ckpt.h5");
    io::writeCheckpoint(path, solver::checkpointOf(straight, 0.0));
    solver::Simulation resumed(sc, library);
    solver::restoreCheckpoint(resumed, io::readCheckpoint(path));
    for (int k = 0; k < 150; ++k) {
        straight.advance();
        resumed.advance();
    }
    ASSERT_GT(straight.finiteElements()->erodedCount(), 0U) << "the test must cover erosion";
    ASSERT_GT(straight.contact()->dissipatedEnergy(), 0.0) << "and contact";
    EXPECT_EQ(straight.time(), resumed.time());
    EXPECT_EQ(straight.particles().z, resumed.particles().z);
    EXPECT_EQ(straight.particles().vz, resumed.particles().vz);
    EXPECT_EQ(straight.particles().e, resumed.particles().e);
    EXPECT_EQ(straight.finiteElements()->nodes().z, resumed.finiteElements()->nodes().z);
    EXPECT_EQ(straight.finiteElements()->nodes().vr, resumed.finiteElements()->nodes().vr);
    // Eroded elements became particles: their slots and the nodes' reduced masses.
    EXPECT_EQ(straight.particles().mass, resumed.particles().mass);
    EXPECT_EQ(straight.finiteElements()->nodes().mass, resumed.finiteElements()->nodes().mass);
    EXPECT_EQ(straight.finiteElements()->elements().e, resumed.finiteElements()->elements().e);
    EXPECT_EQ(straight.finiteElements()->elements().alive,
              resumed.finiteElements()->elements().alive);
    EXPECT_EQ(straight.energyError(), resumed.energyError());
    EXPECT_EQ(straight.contact()->dissipatedEnergy(), resumed.contact()->dissipatedEnergy());
}
