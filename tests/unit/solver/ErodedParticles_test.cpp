// Eroded elements becoming particles (solver/ErodedParticles.hpp): the conversion conserves
// mass, momentum and energy exactly, a node whose last element went is gone with exactly zero
// mass, and the particle carries the element's state.
#include "fe/FeMesh.hpp"
#include "solver/ErodedParticles.hpp"
#include "sph/ParticleSet.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi;

namespace {

struct Ledger {
    double mass = 0.0, pz = 0.0, pr = 0.0, energy = 0.0;
};

Ledger ledger(const fe::NodeSet& nd, const fe::ElementSet& el, const sph::ParticleSet& ps) {
    Ledger l;
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (nd.alive[n]) {
            l.mass += nd.mass[n];
            l.pz += nd.mass[n] * nd.vz[n];
            l.pr += nd.mass[n] * nd.vr[n];
            l.energy += 0.5 * nd.mass[n] * (nd.vz[n] * nd.vz[n] + nd.vr[n] * nd.vr[n]);
        }
    }
    for (std::size_t e = 0; e < el.size(); ++e) {
        if (el.alive[e]) {
            l.energy += el.mass[e] * el.e[e];
        }
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.alive[i]) {
            l.mass += ps.mass[i];
            l.pz += ps.mass[i] * ps.vz[i];
            l.pr += ps.mass[i] * ps.vr[i];
            l.energy += ps.mass[i] * (0.5 * (ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i]) + ps.e[i]);
        }
    }
    return l;
}

std::size_t unusedSlots(const sph::ParticleSet& ps) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        count += sph::isUnusedSlot(ps.alive[i], ps.mass[i]) ? 1 : 0;
    }
    return count;
}

/// Erodes element e as FeSolid does (alive flag, the corner nodes' element counts).
void erode(fe::ElementSet& el, fe::NodeSet& nd, std::size_t e) {
    el.alive[e] = 0;
    for (int a = 0; a < 4; ++a) {
        --nd.elementCount[static_cast<std::size_t>(el.node(e, a))];
    }
}

class ErodedParticlesTest : public ::testing::Test {
protected:
    void SetUp() override {
        // A 3 x 2 axisymmetric Al plate against the axis, 0.1 mm elements; the nodes move
        // with distinct velocities and the elements hold distinct states.
        scene::Body plate;
        plate.name = "wall";
        plate.discretization = scene::Discretization::Fe;
        plate.spacing = 0.1;
        plate.shape.kind = scene::ShapeKind::Plate;
        plate.shape.zFront = 1.0;
        plate.shape.thickness = 0.3;
        plate.shape.innerRadius = 0.0;
        plate.shape.outerRadius = 0.2;
        elements.enableStrength();
        mesh = fe::meshBody(plate, 0, 2.703, 0.0, true, nodes, elements);
        particles.enableStrength();
        firstSlot = converter.reserve(mesh, 0, 2.703, nodes, elements, particles);
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            nodes.vz[n] = 1.0 + 0.3 * std::sin(1.7 * static_cast<double>(n));
            nodes.vr[n] = nodes.onAxis[n] ? 0.0 : 0.2 * std::cos(0.9 * static_cast<double>(n));
        }
        for (std::size_t e = 0; e < elements.size(); ++e) {
            elements.e[e] = 0.01 * static_cast<double>(e + 1);
            elements.rho[e] = 2.5 + 0.01 * static_cast<double>(e);
            elements.szz[e] = 0.1;
            elements.srr[e] = -0.05;
            elements.srz[e] = 0.02;
            elements.plasticStrain[e] = 0.3;
            elements.damage[e] = 1.0;
        }
    }

    fe::NodeSet nodes;
    fe::ElementSet elements;
    fe::BodyMesh mesh;
    sph::ParticleSet particles;
    solver::ErodedParticles converter{true, 1.3};
    std::size_t firstSlot = 0;
    const std::vector<double> rhoMin{0.1}, rhoMax{6.0};
};

TEST_F(ErodedParticlesTest, ReserveHoldsOneUnusedSlotPerElement) {
    ASSERT_EQ(mesh.elementCount, 6u);
    EXPECT_EQ(firstSlot, 0u);
    EXPECT_EQ(particles.size(), 6u);
    EXPECT_EQ(unusedSlots(particles), 6u);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        EXPECT_EQ(particles.alive[i], 0);
        EXPECT_EQ(particles.mass[i], 0.0);
    }
    EXPECT_EQ(converter.slotOf(4), 4);
    EXPECT_EQ(converter.slotOf(6), -1);
}

TEST_F(ErodedParticlesTest, ConversionConservesMassMomentumAndEnergy) {
    const Ledger before = ledger(nodes, elements, particles);
    // Erode everything in two updates: first two elements, then the rest (nodes lose their
    // last element in both).
    erode(elements, nodes, 0);
    erode(elements, nodes, 3);
    auto created = converter.convert({0, 3}, elements, nodes, particles, rhoMin, rhoMax);
    EXPECT_EQ(created, (std::vector<int32_t>{0, 3}));
    const Ledger middle = ledger(nodes, elements, particles);
    for (const std::size_t e : {1u, 2u, 4u, 5u}) {
        erode(elements, nodes, e);
    }
    created = converter.convert({1, 2, 4, 5}, elements, nodes, particles, rhoMin, rhoMax);
    EXPECT_EQ(created.size(), 4u);
    const Ledger after = ledger(nodes, elements, particles);
    for (const Ledger* l : {&middle, &after}) {
        EXPECT_NEAR(l->mass, before.mass, 1e-14 * before.mass);
        EXPECT_NEAR(l->pz, before.pz, 1e-14 * std::fabs(before.pz));
        EXPECT_NEAR(l->pr, before.pr, 1e-13 * before.mass);
        EXPECT_NEAR(l->energy, before.energy, 1e-14 * before.energy);
    }
    // No element left: every node is gone, with exactly zero mass; all mass is in particles.
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        EXPECT_EQ(nodes.alive[n], 0) << "node " << n;
        EXPECT_EQ(nodes.mass[n], 0.0) << "node " << n;
    }
    EXPECT_EQ(unusedSlots(particles), 0u);
}

TEST_F(ErodedParticlesTest, ParticleTakesTheElementsStateAndPlace) {
    erode(elements, nodes, 2); // the middle element of the axis row: its corners are shared
    converter.convert({2}, elements, nodes, particles, rhoMin, rhoMax);
    const std::size_t i = 2;
    ASSERT_EQ(particles.alive[i], 1);
    // Every corner still has other elements: the particle has exactly the element's mass,
    // the mean velocity of the corners, and the element's stress state and density.
    EXPECT_NEAR(particles.mass[i], elements.mass[2], 1e-15 * elements.mass[2]);
    double vz = 0.0, z = 0.0, r = 0.0, ke = 0.0;
    for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(elements.node(2, a));
        vz += 0.25 * nodes.vz[n];
        z += 0.25 * nodes.z[n];
        r += 0.25 * nodes.r[n];
        ke += 0.125 * (nodes.vz[n] * nodes.vz[n] + nodes.vr[n] * nodes.vr[n]);
        EXPECT_EQ(nodes.alive[n], 1);
    }
    EXPECT_NEAR(particles.vz[i], vz, 1e-14);
    EXPECT_NEAR(particles.z[i], z, 1e-14);
    EXPECT_NEAR(particles.r[i], r, 1e-14);
    // The kinetic energy of the corners' spread about their mean is heat in the particle.
    const double spread =
        ke - 0.5 * (particles.vz[i] * particles.vz[i] + particles.vr[i] * particles.vr[i]);
    EXPECT_GT(spread, 0.0);
    EXPECT_NEAR(particles.e[i], elements.e[2] + spread, 1e-14);
    EXPECT_EQ(particles.rho[i], elements.rho[2]);
    EXPECT_EQ(particles.szz[i], 0.1);
    EXPECT_EQ(particles.srz[i], 0.02);
    EXPECT_EQ(particles.plasticStrain[i], 0.3);
    EXPECT_EQ(particles.damage[i], 1.0);
    // h: the side of the (z, r) square it stands for, times the smoothing factor; the element
    // is 0.1 mm square at density 2.52 against the reference 2.703.
    const double side = std::sqrt(particles.mass[i] / (2.0 * M_PI * r * particles.rho[i]));
    EXPECT_NEAR(particles.h[i], 1.3 * side, 1e-12);
    EXPECT_NEAR(side, 0.1 * std::sqrt(2.703 / particles.rho[i]), 2e-3);
    EXPECT_EQ(unusedSlots(particles), 5u);
}

} // namespace
