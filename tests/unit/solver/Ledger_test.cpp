// The conservation ledger and the deletion rule (solver/Ledger.hpp, solver/DeletionRule.hpp):
// what a deletion takes out of the alive totals the ledger books, so E + E_deleted and the
// mass and z-momentum budgets are unchanged by it (to rounding); the rule's runaway speed and
// default domain box follow the scene as documented; a non-finite state names its point.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "core/Error.hpp"
#include "solver/DeletionRule.hpp"
#include "solver/Ledger.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <omp.h>

using namespace hvi;
using nlohmann::json;

namespace {

scene::Scene sphereOnPlate() {
    const json doc = {
        {"sph", {{"particle_spacing_mm", 0.1}, {"runaway_speed_factor", 3.0}}},
        {"run", {{"end_time_us", 1.0}}},
        {"domain", {{"radius_mm", 6.0}}},
        {"bodies",
         {test::projectileBody(0.5, 4.0), test::plateBody("wall", "rear_wall", 2.0, 1.5, 5.0)}}};
    return test::makeScene(doc);
}

// Four particles: one at rest, one moving, one out of the box behind, one a runaway.
sph::ParticleSet fourParticles() {
    sph::ParticleSet ps;
    ps.add(0.0, 0.5, 0.0, 0.0, 2.0, 0.1, 2.7, 0.01, 0);
    ps.add(1.0, 1.0, 3.0, -1.0, 1.5, 0.1, 2.7, 0.2, 0);
    ps.add(9.0, 1.0, 1.0, 0.5, 0.5, 0.1, 2.7, 0.3, 1);
    ps.add(1.0, 2.0, 13.0, 0.0, 0.25, 0.1, 2.7, 0.4, 1);
    return ps;
}

double energyOf(const solver::Totals& t) {
    return t.kinetic + t.internal + t.deletedEnergy;
}

} // namespace

TEST(Ledger, TotalsOfParticles) {
    const auto ps = fourParticles();
    const solver::Ledger ledger;
    const auto t = ledger.totals(ps, nullptr, nullptr, 4);
    // By hand: KE = 1/2 sum m v^2, IE = sum m e.
    const double ke = 0.5 * (1.5 * 10.0 + 0.5 * 1.25 + 0.25 * 169.0);
    const double ie = 2.0 * 0.01 + 1.5 * 0.2 + 0.5 * 0.3 + 0.25 * 0.4;
    EXPECT_NEAR(t.kinetic, ke, 1e-12);
    EXPECT_NEAR(t.internal, ie, 1e-12);
    EXPECT_NEAR(t.mass, 4.25, 1e-12);
    EXPECT_NEAR(t.momentumZ, 1.5 * 3.0 + 0.5 + 0.25 * 13.0, 1e-12);
    EXPECT_EQ(t.alive, 4u);
    EXPECT_EQ(t.deleted, 0u);
}

TEST(Ledger, EnergyErrorIsRelativeToTheStartAndAbsoluteWithoutEnergy) {
    solver::Ledger ledger;
    solver::Totals t;
    t.kinetic = 9.0;
    t.internal = 1.5;
    t.deletedEnergy = 0.5;
    ledger.setInitialEnergy(10.0);
    EXPECT_NEAR(ledger.energyError(t), 0.1, 1e-15);
    ledger.setInitialEnergy(-10.0);
    EXPECT_NEAR(ledger.energyError(t), 2.1, 1e-15);
    ledger.setInitialEnergy(0.0);
    EXPECT_NEAR(ledger.energyError(t), 11.0, 1e-15);
}

TEST(DeletionRule, FollowsTheScene) {
    const auto scene = sphereOnPlate();
    const auto rule = solver::DeletionRule::of(scene);
    EXPECT_DOUBLE_EQ(rule.runawaySpeed, 3.0 * 4.0);
    // The bodies span z = -1.05 (a 1.0 mm sphere, 0.05 mm in front of 0) to 3.5 mm; the box
    // opens twice the longest body (the 1.5 mm wall) in front of them and 5 mm behind.
    EXPECT_NEAR(rule.zMin, -1.05 - 2.0 * 1.5, 1e-12);
    EXPECT_NEAR(rule.zMax, 3.5 + 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(rule.rMax, 6.0);
    EXPECT_EQ(rule.reason(0.0, 1.0, 11.9 * 11.9), std::nullopt);
    EXPECT_EQ(rule.reason(0.0, 1.0, 12.1 * 12.1), solver::DeletionReason::Runaway);
    EXPECT_EQ(rule.reason(8.6, 1.0, 0.0), solver::DeletionReason::OutOfDomain);
    EXPECT_EQ(rule.reason(0.0, 6.1, 0.0), solver::DeletionReason::OutOfDomain);
    EXPECT_EQ(rule.reason(0.0, -6.1, 0.0), solver::DeletionReason::OutOfDomain);

    // Nothing moving at the start: no runaway speed.
    auto still = scene;
    for (auto& body : still.bodies) {
        body.velocityZ = 0.0;
    }
    EXPECT_TRUE(std::isinf(solver::DeletionRule::of(still).runawaySpeed));
}

TEST(DeletionRule, DeletionKeepsTheBudgets) {
    const auto scene = sphereOnPlate();
    const auto rule = solver::DeletionRule::of(scene);
    auto ps = fourParticles();
    solver::Ledger ledger;
    const auto before = ledger.totals(ps, nullptr, nullptr, 4);
    ledger.setInitialEnergy(energyOf(before));
    const std::size_t gone = solver::deleteParticles(ps, nullptr, rule, scene, {0.5, 7}, ledger);
    EXPECT_EQ(gone, 2u);
    EXPECT_EQ(ps.alive[2], 0);
    EXPECT_EQ(ps.alive[3], 0);
    EXPECT_EQ(ledger.account().runaway, 1u);
    EXPECT_EQ(ledger.account().outOfDomain, 1u);
    const auto after = ledger.totals(ps, nullptr, nullptr, 2);
    EXPECT_EQ(after.deleted, 2u);
    EXPECT_NEAR(energyOf(after), energyOf(before), 1e-12 * energyOf(before));
    EXPECT_NEAR(after.mass + after.deletedMass, before.mass, 1e-12);
    EXPECT_NEAR(after.momentumZ + after.deletedMomentumZ, before.momentumZ, 1e-12);
    EXPECT_NEAR(ledger.energyError(after), 0.0, 1e-14);
}

TEST(DeletionRule, OnlyTheListedParticlesAreChecked) {
    const auto scene = sphereOnPlate();
    auto ps = fourParticles();
    solver::Ledger ledger;
    const std::vector<int32_t> items{0, 1, 2};
    EXPECT_EQ(solver::deleteParticles(ps, &items, solver::DeletionRule::of(scene), scene, {0.5, 7},
                                      ledger),
              1u);
    EXPECT_EQ(ps.alive[3], 1); // the runaway was not listed
}

TEST(DeletionRule, NonFiniteStateNamesThePoint) {
    const auto scene = sphereOnPlate();
    auto ps = fourParticles();
    ps.e[1] = std::numeric_limits<double>::quiet_NaN();
    solver::Ledger ledger;
    try {
        solver::deleteParticles(ps, nullptr, solver::DeletionRule::of(scene), scene, {0.5, 7},
                                ledger);
        FAIL() << "no error for a NaN energy";
    } catch (const RuntimeFailure& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("particle 1 of body 'projectile'"), std::string::npos) << what;
        EXPECT_NE(what.find("step 7"), std::string::npos) << what;
    }
}

// Above the threading threshold (core/Parallel.hpp) the pass scans on two threads for the
// first point to delete and books from there in order: the same points go and the ledger
// holds the same bits as on one thread, wherever the deletions fall.
TEST(DeletionRule, ThreadedScanDeletesTheSamePointsInTheSameOrder) {
    const auto scene = sphereOnPlate();
    const auto rule = solver::DeletionRule::of(scene);
    auto many = [] {
        sph::ParticleSet ps;
        for (int k = 0; k < 9000; ++k) {
            const bool runaway = k == 4321 || k == 8998;
            const bool outside = k == 6000 || k == 8999;
            ps.add(outside ? 9.0 : 1.0, 0.5 + 1e-4 * k, runaway ? 13.0 + 1e-3 * k : 1.0, 0.0,
                   1.0 + 1e-5 * k, 0.1, 2.7, 0.1, 0);
        }
        return ps;
    };
    solver::Ledger::Account accounts[2];
    std::vector<uint8_t> alive[2];
    for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        auto ps = many();
        solver::Ledger ledger;
        EXPECT_EQ(solver::deleteParticles(ps, nullptr, rule, scene, {0.5, 7}, ledger), 4u);
        accounts[threads - 1] = ledger.account();
        alive[threads - 1] = ps.alive;
    }
    omp_set_num_threads(1);
    EXPECT_EQ(alive[0], alive[1]);
    EXPECT_EQ(accounts[1].runaway, 2u);
    EXPECT_EQ(accounts[1].outOfDomain, 2u);
    EXPECT_EQ(accounts[0].deletedEnergy, accounts[1].deletedEnergy);
    EXPECT_EQ(accounts[0].deletedMass, accounts[1].deletedMass);
    EXPECT_EQ(accounts[0].deletedMomentumZ, accounts[1].deletedMomentumZ);
    EXPECT_EQ(alive[1][4321] + alive[1][6000] + alive[1][8998] + alive[1][8999], 0);
}
