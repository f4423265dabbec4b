// The contact steps alone (contact/ContactSearch, ContactConstraints, ContactSolver,
// ContactHeat) on a hand-made scene: two particles striking the face of one planar element.
//
// Two slaves of mass m at xi = 1/4 and 3/4 of a segment whose nodes have mass M, striking at
// v0: by symmetry the simultaneous perfectly inelastic solution moves the nodes and the
// slaves at one speed, V = m v0 / (m + M), with impulse J = M V on each slave. A single
// Gauss-Seidel pass does not reach it (the first slave is resolved as if alone: its
// effective mass has (3/4)^2 + (1/4)^2 of the nodes'), so this checks the passes. The heat
// booked must be the kinetic energy lost, exactly (an identity of the impulses), and the
// two sides of each blow must rise by the same specific energy.
#include "contact/ContactConstraints.hpp"
#include "contact/ContactHeat.hpp"
#include "contact/ContactPoints.hpp"
#include "contact/ContactSearch.hpp"
#include "contact/ContactSolver.hpp"
#include "fe/SurfaceTopology.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi;

namespace {

constexpr double kSlaveMass = 0.3;   // mg
constexpr double kNodeMass = 0.5;    // mg
constexpr double kElementMass = 2.0; // mg
constexpr double kSpeed = 2.0;       // km/s
constexpr double kSpacing = 0.2;     // particle spacing: radius 0.1 mm
constexpr double kDt = 1e-3;         // us

struct Scene {
    sph::ParticleSet ps;
    std::vector<double> vz, vr, e;
    fe::NodeSet nd;
    fe::ElementSet el;
    fe::SurfaceTopology surface;
    std::vector<contact::ContactBody> bodies{{false, kSpacing}, {true, 1.0}};
    contact::ContactOptions options{false, 0.0};

    Scene() {
        // A unit square element in (z, r), corners counter-clockwise; its face z = 1 is the
        // segment from node 1 (r = 0) to node 2 (r = 1), outward normal +z.
        const double cz[4] = {0.0, 1.0, 1.0, 0.0}, cr[4] = {0.0, 0.0, 1.0, 1.0};
        for (int a = 0; a < 4; ++a) {
            nd.z.push_back(cz[a]);
            nd.r.push_back(cr[a]);
            nd.vz.push_back(0.0);
            nd.vr.push_back(0.0);
            nd.mass.push_back(kNodeMass);
            nd.fz.push_back(0.0);
            nd.fr.push_back(0.0);
            nd.body.push_back(1);
            nd.alive.push_back(1);
            nd.onAxis.push_back(0);
            nd.elementCount.push_back(1);
        }
        el.connectivity = {0, 1, 2, 3};
        el.body = {1};
        el.alive = {1};
        el.mass = {kElementMass};
        el.e = {0.0};
        surface.update(el, nd, false);
        // Two particles touching the face (centre one radius out), moving onto it.
        for (const double r : {0.25, 0.75}) {
            ps.add(1.0 + 0.5 * kSpacing, r, -kSpeed, 0.0, kSlaveMass, 0.3, 2.7, 0.0, 0);
            vz.push_back(-kSpeed);
            vr.push_back(0.0);
            e.push_back(0.0);
        }
    }
    contact::ContactPoints points() {
        return {ps, {&vz, &vr, &e}, el, nd, surface, bodies, options};
    }
    double kineticEnergy() const {
        double k = 0.0;
        for (std::size_t i = 0; i < vz.size(); ++i) {
            k += 0.5 * kSlaveMass * (vz[i] * vz[i] + vr[i] * vr[i]);
        }
        for (std::size_t n = 0; n < nd.size(); ++n) {
            k += 0.5 * nd.mass[n] * (nd.vz[n] * nd.vz[n] + nd.vr[n] * nd.vr[n]);
        }
        return k;
    }
};

} // namespace

TEST(ContactSteps, SearchFindsTheFaceOnlyAndVotesHalfACellOverTheApproach) {
    Scene s;
    const auto pts = s.points();
    ASSERT_EQ(s.surface.segmentCount(), 4u);
    ASSERT_EQ(pts.slaveCount(), 6u); // the particles, then the element's surface nodes
    const double cell = 2.5;
    const auto found = contact::findCandidates(pts, kDt, cell);
    for (std::size_t k = 2; k < found.size(); ++k) {
        EXPECT_EQ(found[k].count, 0) << "a node never meets its own body's surface";
    }
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& c = found[k];
        ASSERT_EQ(c.count, 1);
        EXPECT_EQ(s.surface.segA[static_cast<std::size_t>(c.target[0])], 1);
        EXPECT_EQ(s.surface.segB[static_cast<std::size_t>(c.target[0])], 2);
        EXPECT_DOUBLE_EQ(c.dt, 0.5 * cell / kSpeed);
    }
    // Receding: a vote of +inf and no candidate.
    s.vz.assign(2, kSpeed);
    for (const auto& c : contact::findCandidates(s.points(), kDt, cell)) {
        EXPECT_EQ(c.count, 0);
        EXPECT_TRUE(std::isinf(c.dt));
    }
}

TEST(ContactSteps, PassesReachTheSimultaneousInelasticSolution) {
    Scene s;
    const auto pts = s.points();
    auto set = contact::buildConstraints(pts, contact::findCandidates(pts, kDt, 2.5), kDt);
    ASSERT_EQ(set.list.size(), 2u);
    const double before = s.kineticEnergy();
    contact::solveImpulses(pts, set);
    const double common = kSlaveMass * kSpeed / (kSlaveMass + kNodeMass);
    const double tol = 1e-6; // kPassTolerance, in km/s
    for (int n : {1, 2}) {
        EXPECT_NEAR(s.nd.vz[static_cast<std::size_t>(n)], -common, tol) << "node " << n;
    }
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(s.vz[i], -common, tol) << "slave " << i;
        EXPECT_NEAR(set.list[i].impulse, kNodeMass * common, kNodeMass * tol);
    }
    // z-momentum is conserved exactly (each kick is equal and opposite).
    double pz = 0.0;
    for (std::size_t i = 0; i < 2; ++i) {
        pz += kSlaveMass * s.vz[i];
    }
    for (std::size_t n = 0; n < 4; ++n) {
        pz += kNodeMass * s.nd.vz[n];
    }
    EXPECT_NEAR(pz, -2.0 * kSlaveMass * kSpeed, 1e-14);

    // The heat: the kinetic energy lost, shared so both sides rise by the same amount.
    contact::StepContacts step;
    contact::markContacts(pts, set, step);
    EXPECT_EQ(step.contactCount, 2u);
    EXPECT_EQ(step.touchedParticles, (std::vector<int32_t>{0, 1}));
    contact::ContactEnergy energy;
    contact::shareHeat(pts, set, kDt, energy);
    const double lost = before - s.kineticEnergy();
    EXPECT_GT(lost, 0.0);
    EXPECT_NEAR(energy.dissipated, lost, 1e-12 * before);
    const double deposited = kSlaveMass * (s.e[0] + s.e[1]) + kElementMass * s.el.e[0];
    EXPECT_NEAR(deposited, lost, 1e-12 * before);
    // Each blow raises its particle and the element by the same amount; the element took two.
    // The blows are alike to the passes' tolerance (they stop at kPassTolerance, 1e-6 km/s
    // on a relative speed of order 1 km/s).
    EXPECT_NEAR(s.e[0], s.e[1], 1e-6 * s.e[0]);
    EXPECT_NEAR(s.el.e[0], s.e[0] + s.e[1], 1e-12 * s.el.e[0]);
}

namespace {

/// The face's nodes pushed towards the particles by a force F each (half kick k = F dt / 2M)
/// with half-step velocity `nodeVz`, the particles at `particleVz`; returns the heat booked
/// and the kinetic energy the impulses took plus k . J over the nodes (contact/ContactHeat.hpp:
/// the heat that conserves energy when the elements pay only for the motion left).
struct PressedFace {
    double heat, expected, common;
};
PressedFace pressFace(double kick, double nodeVz, double particleVz) {
    Scene s;
    for (std::size_t n : {1u, 2u}) {
        s.nd.fz[n] = 2.0 * kNodeMass * kick / kDt;
        s.nd.vz[n] = nodeVz;
    }
    s.vz.assign(2, particleVz);
    const auto pts = s.points();
    auto set = contact::buildConstraints(pts, contact::findCandidates(pts, kDt, 2.5), kDt);
    const double before = s.kineticEnergy();
    const std::vector<double> nodeBefore = s.nd.vz;
    contact::solveImpulses(pts, set);
    double expected = before - s.kineticEnergy();
    for (std::size_t n : {1u, 2u}) {
        expected += kick * kNodeMass * (s.nd.vz[n] - nodeBefore[n]);
    }
    contact::ContactEnergy energy;
    contact::shareHeat(pts, set, kDt, energy);
    return {energy.dissipated, expected, s.vz[0]};
}

} // namespace

// A face pressed onto particles at rest by its element's force, step after step (the nodes
// start the step at k from the last half kick and reach 2k): the elements pay for the push
// only through the motion left, so the kinetic energy the impulses take is no heat. Booking
// it made 2 M k^2 of heat per node and step; in a foam core a particle squeezed between
// eroding layers ran away to 2 000 MJ/kg on it.
TEST(ContactSteps, APressingFaceMakesNoHeat) {
    const double k = 0.5; // km/s
    const PressedFace f = pressFace(k, 2.0 * k, 0.0);
    const double common = 2.0 * kNodeMass * k / (kNodeMass + kSlaveMass);
    EXPECT_NEAR(f.common, common, 1e-6);
    // The passes stop within kPassTolerance of the relative speed they aim at, so the heat
    // is zero to the impulses (2 M 2k in all) times that; booking the kinetic energy taken
    // made 0.19 J here.
    const double tol = 4.0 * kNodeMass * k * contact::kPassTolerance;
    EXPECT_NEAR(f.heat, 0.0, tol);
    EXPECT_NEAR(f.expected, 0.0, tol);
}

// Particles striking a face that its element's force pushes towards them: the heat is the
// kinetic energy taken, less the nodes' unpaid kick (the identity above, computed per point
// rather than per constraint), and still positive.
TEST(ContactSteps, ACollisionWithAPushedFaceBooksTheKineticEnergyLessTheUnpaidKick) {
    const double k = 0.1;
    const PressedFace f = pressFace(k, k, -kSpeed);
    EXPECT_GT(f.heat, 0.0);
    EXPECT_NEAR(f.heat, f.expected, 1e-9 * f.expected);
}
