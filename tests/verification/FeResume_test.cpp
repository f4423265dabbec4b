// Stop and resume (developers' guide: long runs can be stopped and resumed): a run with SPH
// particles, an eroding FE plate and contact, checkpointed to disk midway and resumed in a new
// Simulation, ends bit for bit where the uninterrupted run ends. The aluminium carries the
// cyclic damage options (compression closure, degradation), whose per-point state
// (tensionOnset) the checkpoint must carry too.
#include "SceneRun.hpp"
#include "TestPaths.hpp"
#include "io/Checkpoint.hpp"
#include "material/MaterialLibrary.hpp"
#include "solver/RunLoop.hpp"

#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

template <class Set, std::size_t N>
void expectSameFields(const Set& a, const Set& b, const std::array<Field<Set>, N>& fields) {
    for (const auto& f : fields) {
        EXPECT_EQ(a.*f.member, b.*f.member) << f.name;
    }
}

/// Al 6061-T6 with full closure and lambda = 1, as the scene's material "AlCyclic".
json cyclicAluminium() {
    json entry = json::parse(material::MaterialLibrary::builtin().get("Al6061-T6").definitionJson);
    entry["failure"]["compression_closure"] = 1.0;
    entry["failure"]["cyclic_degradation"] = 1.0;
    return {{"AlCyclic", entry}};
}

/// `energyUpdate`: the particles' energy update (sph.energy_update).
json resumeScene(const std::string& energyUpdate) {
    return {{"geometry", "axisymmetric"},
            {"materials", cyclicAluminium()},
            {"sph", {{"particle_spacing_mm", 0.05}, {"energy_update", energyUpdate}}},
            {"fe", {{"element_size_mm", 0.05}}},
            {"run",
             {{"end_time_us", 10.0},
              {"stop_debris_speed_km_s", 0.0},
              {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 4.5}}},
            {"bodies",
             {{{"name", "projectile"},
               {"role", "projectile"},
               {"material", "AlCyclic"},
               {"shape", {{"type", "sphere"}, {"center_z_mm", -0.55}, {"radius_mm", 0.5}}},
               {"velocity", {{"z_km_s", 3.0}}}},
              {{"name", "plate"},
               {"role", "bumper"},
               {"material", "AlCyclic"},
               {"discretization", "fe"},
               {"shape",
                {{"type", "plate"},
                 {"z_front_mm", 0.0},
                 {"thickness_mm", 0.5},
                 {"outer_radius_mm", 4.0}}}}}}};
}

void expectResumeEndsBitForBit(const std::string& energyUpdate) {
    const json doc = resumeScene(energyUpdate);
    const auto sc = test::makeScene(doc);
    const auto library = scene::sceneLibrary(doc["materials"], "<test>");
    solver::Simulation straight(sc, library);
    for (int k = 0; k < 150; ++k) {
        straight.advance();
    }
    const auto path = test::tempPath("fe_resume.ckpt.h5");
    io::writeCheckpoint(path, solver::checkpointOf(straight, 0.0));
    solver::Simulation resumed(sc, library);
    resumed.restore(io::readCheckpoint(path));
    for (int k = 0; k < 150; ++k) {
        straight.advance();
        resumed.advance();
    }
    ASSERT_GT(straight.finiteElements()->erodedCount(), 0U) << "the test must cover erosion";
    ASSERT_GT(straight.contact()->dissipatedEnergy(), 0.0) << "and contact";
    EXPECT_EQ(straight.time(), resumed.time());
    // Every evolved field of every point set, by its list (eroded elements became particles:
    // their slots and the nodes' reduced masses are in it), and the pressures, which the
    // resumed run recomputes (an eroded element's included: it holds none).
    const auto& sp = straight.particles();
    const auto& rp = resumed.particles();
    expectSameFields(sp, rp, sph::kParticleStateFields);
    expectSameFields(sp, rp, sph::kParticleStrengthFields);
    EXPECT_EQ(sp.p, rp.p);
    const auto& sn = straight.finiteElements()->nodes();
    const auto& rn = resumed.finiteElements()->nodes();
    expectSameFields(sn, rn, fe::kNodeStateFields);
    const auto& se = straight.finiteElements()->elements();
    const auto& re = resumed.finiteElements()->elements();
    expectSameFields(se, re, fe::kElementStateFields);
    expectSameFields(se, re, fe::kElementStrengthFields);
    EXPECT_EQ(se.p, re.p);
    EXPECT_EQ(se.alive, re.alive);
    EXPECT_EQ(straight.energyError(), resumed.energyError());
    EXPECT_EQ(straight.contact()->dissipatedEnergy(), resumed.contact()->dissipatedEnergy());
    // Some points began a tensile excursion after compressive flow (the damage state).
    const auto& onset = se.tensionOnset;
    ASSERT_TRUE(std::any_of(onset.begin(), onset.end(), [](double v) { return v > 0.0; }))
        << "the test must cover a tensile excursion after compression";
}

} // namespace

TEST(FeResume, CheckpointedRunEndsBitForBit) {
    expectResumeEndsBitForBit("trapezoid");
}

// The compatible update's first kick after the resume pays the pair work of the evaluation
// before the checkpoint (sph/PairWork.hpp), which the checkpoint must carry.
TEST(FeResume, CheckpointedRunEndsBitForBitWithTheCompatibleEnergyUpdate) {
    expectResumeEndsBitForBit("compatible");
}
