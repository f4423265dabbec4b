// What the XDMF sidecar shows of a snapshot (io/RunFileView): only alive particles, only
// alive elements and the nodes they use (renumbered), every field of both blocks where the
// other block has it centred alike, the stress deviator as named components with the hoop
// one, and each item's slot in the snapshot's own datasets.
#include "io/RunFileView.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace hvi::io;

namespace {

/// The view's reals are single precision: the values as the view stores them.
std::vector<float> floats(std::initializer_list<double> values) {
    std::vector<float> out;
    for (double v : values) {
        out.push_back(static_cast<float>(v));
    }
    return out;
}

const ViewArray* arrayNamed(const ViewBlock& block, std::string_view name) {
    for (const auto& array : block.arrays) {
        if (array.spec->field.name == name) {
            return &array;
        }
    }
    return nullptr;
}

/// Five particle slots: alive, deleted (mass kept), alive, unused (mass 0), alive.
struct FiveParticles {
    std::vector<double> z{1, 2, 3, 4, 5}, r{0.5, 0.6, 0.7, 0.8, 0.9};
    std::vector<double> vz{-1, -2, -3, -4, -5}, vr{0.1, 0.2, 0.3, 0.4, 0.5};
    std::vector<double> mass{1, 1, 2, 0, 3}, density{2.7, 9.9, 2.8, 0, 2.9};
    std::vector<double> pressure{1, 500, 2, 0, 3}, energy{0.1, 52, 0.2, 0, 0.3};
    std::vector<double> h{0.1, 0.1, 0.1, 0.1, 0.1}, damage{0, 1, 0.5, 0, 0.25};
    std::vector<double> plastic{0, 2, 0.1, 0, 0.2};
    std::vector<double> deviator{1, 2, 3, 9, 9, 9, 4, 5, 6, 9, 9, 9, 7, -8, 0.5};
    std::vector<std::int32_t> body{0, 0, 1, 2, 1};
    std::vector<std::uint8_t> alive{1, 0, 1, 0, 1};

    ParticleFieldsView view(bool strength = true) const {
        ParticleFieldsView v;
        v.z = z;
        v.r = r;
        v.vz = vz;
        v.vr = vr;
        v.mass = mass;
        v.density = density;
        v.pressure = pressure;
        v.internalEnergy = energy;
        v.smoothingLength = h;
        if (strength) {
            v.damage = damage;
            v.plasticStrain = plastic;
            v.stressDeviator = deviator;
        }
        v.bodyId = body;
        v.alive = alive;
        return v;
    }
};

/// Nodes 0-5 on a 3 x 2 grid plus node 6 that no element uses; element 0 (nodes 0 1 4 3)
/// alive, element 1 (nodes 1 2 5 4) eroded.
struct TwoQuads {
    std::vector<double> z{0, 1, 2, 0, 1, 2, 9}, r{0, 0, 0, 1, 1, 1, 9};
    std::vector<double> vz{1, 2, 3, 4, 5, 6, 3.4}, vr{0, 0.1, 0.2, 0.3, 0.4, 0.5, 3.4};
    std::vector<double> nodeMass{1, 2, 3, 4, 5, 6, 7};
    std::vector<std::int32_t> connectivity{0, 1, 4, 3, 1, 2, 5, 4};
    std::vector<std::uint8_t> alive{1, 0};
    std::vector<double> damage{0.2, 1}, plastic{0.3, 4}, geometric{0.1, 2}, pressure{1.5, -3},
        density{2.7, 0.1};
    std::vector<std::int32_t> body{4, 4};

    FeFieldsView view() const {
        FeFieldsView v;
        v.nodes.z = z;
        v.nodes.r = r;
        v.nodes.vz = vz;
        v.nodes.vr = vr;
        v.nodes.mass = nodeMass;
        v.elements.connectivity = connectivity;
        v.elements.alive = alive;
        v.elements.damage = damage;
        v.elements.plasticStrain = plastic;
        v.elements.geometricStrain = geometric;
        v.elements.pressure = pressure;
        v.elements.density = density;
        v.elements.bodyId = body;
        return v;
    }
};

} // namespace

TEST(RunFileView, ParticlesShowOnlyTheAliveOnes) {
    const FiveParticles p;
    const ViewBlock block = particleView(p.view());
    ASSERT_EQ(block.pointCount, 3u);
    EXPECT_EQ(block.cellCount, 3u);
    EXPECT_EQ(block.points, floats({1, 0.5, 0, 3, 0.7, 0, 5, 0.9, 0}));
    EXPECT_EQ(block.cells, (std::vector<std::int32_t>{0, 1, 2}));
    EXPECT_EQ(arrayNamed(block, "Slot")->integer, (std::vector<std::int32_t>{0, 2, 4}));
    EXPECT_EQ(arrayNamed(block, "Velocity")->real, floats({-1, 0.1, 0, -3, 0.3, 0, -5, 0.5, 0}));
    EXPECT_EQ(arrayNamed(block, "Pressure")->real, floats({1, 2, 3}));
    EXPECT_EQ(arrayNamed(block, "InternalEnergy")->real, floats({0.1, 0.2, 0.3}));
    EXPECT_EQ(arrayNamed(block, "BodyId")->integer, (std::vector<std::int32_t>{0, 1, 1}));
    EXPECT_EQ(arrayNamed(block, "Damage")->real, floats({0, 0.5, 0.25}));
    EXPECT_EQ(arrayNamed(block, "StressDeviatorZZ")->real, floats({1, 4, 7}));
    EXPECT_EQ(arrayNamed(block, "StressDeviatorRR")->real, floats({2, 5, -8}));
    EXPECT_EQ(arrayNamed(block, "StressDeviatorRZ")->real, floats({3, 6, 0.5}));
    EXPECT_EQ(arrayNamed(block, "StressDeviatorTT")->real, floats({-3, -9, 1}));
    EXPECT_EQ(arrayNamed(block, "Alive"), nullptr) << "every item shown is alive";
    EXPECT_EQ(arrayNamed(block, "Z"), nullptr) << "positions are the points";
    for (const auto& array : block.arrays) {
        const std::size_t values = std::max(array.real.size(), array.integer.size());
        EXPECT_EQ(values, 3u * static_cast<std::size_t>(array.spec->field.components))
            << array.spec->field.name;
        EXPECT_EQ(array.spec->centre, ViewCentre::Cell) << array.spec->field.name;
    }
}

TEST(RunFileView, StrengthlessParticlesHaveNoStrengthArrays) {
    const ViewBlock block = particleView(FiveParticles{}.view(false));
    EXPECT_EQ(block.arrays.size(), 8u);
    for (const char* name : {"Damage", "PlasticStrain", "StressDeviatorZZ", "StressDeviatorTT"}) {
        EXPECT_EQ(arrayNamed(block, name), nullptr) << name;
    }
}

TEST(RunFileView, NothingAliveIsAnEmptyBlock) {
    FiveParticles p;
    p.alive.assign(5, 0);
    const ViewBlock block = particleView(p.view());
    EXPECT_EQ(block.pointCount, 0u);
    EXPECT_EQ(block.cellCount, 0u);
    EXPECT_TRUE(block.arrays.empty());
    EXPECT_TRUE(block.points.empty());
}

TEST(RunFileView, MeshShowsAliveElementsAndTheirNodesOnly) {
    const TwoQuads q;
    const ViewBlock block = meshView(q.view());
    ASSERT_EQ(block.cellCount, 1u);
    ASSERT_EQ(block.pointCount, 4u) << "nodes 2 and 5 (eroded element only) and 6 (orphan) out";
    // Nodes 0 1 3 4 become points 0 1 2 3; element 0 (0 1 4 3) becomes (0 1 3 2).
    EXPECT_EQ(block.cells, (std::vector<std::int32_t>{0, 1, 3, 2}));
    EXPECT_EQ(block.points, floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
    EXPECT_EQ(arrayNamed(block, "NodeVelocity")->real,
              floats({1, 0, 0, 2, 0.1, 0, 4, 0.3, 0, 5, 0.4, 0}));
    EXPECT_EQ(arrayNamed(block, "NodeMass")->real, floats({1, 2, 4, 5}));
    const auto& velocity = arrayNamed(block, "Velocity")->real;
    ASSERT_EQ(velocity.size(), 3u);
    EXPECT_FLOAT_EQ(velocity[0], static_cast<float>((1 + 2 + 5 + 4) / 4.0));
    EXPECT_FLOAT_EQ(velocity[1], static_cast<float>((0 + 0.1 + 0.4 + 0.3) / 4.0));
    EXPECT_EQ(velocity[2], 0.0);
    EXPECT_EQ(arrayNamed(block, "Damage")->real, floats({0.2}));
    EXPECT_EQ(arrayNamed(block, "Pressure")->real, floats({1.5}));
    EXPECT_EQ(arrayNamed(block, "BodyId")->integer, (std::vector<std::int32_t>{4}));
    EXPECT_EQ(arrayNamed(block, "Slot")->integer, (std::vector<std::int32_t>{0}));
    EXPECT_EQ(arrayNamed(block, "NodeVelocity")->spec->centre, ViewCentre::Point);
    EXPECT_EQ(arrayNamed(block, "Velocity")->spec->centre, ViewCentre::Cell);
}

TEST(RunFileView, AllElementsErodedIsAnEmptyBlock) {
    TwoQuads q;
    q.alive = {0, 0};
    const ViewBlock block = meshView(q.view());
    EXPECT_EQ(block.cellCount, 0u);
    EXPECT_EQ(block.pointCount, 0u);
    EXPECT_TRUE(block.arrays.empty());
}

TEST(RunFileView, FieldsOfBothBlocksAreCentredAlikeWithTheRunFilesUnits) {
    // One colour map serves both blocks only if a name means the same centring and unit.
    for (const auto& particle : viewArraySpecs(ViewBlockKind::Particles)) {
        const ViewArraySpec* element =
            findViewArraySpec(ViewBlockKind::FiniteElements, particle.field.name);
        if (element != nullptr) {
            EXPECT_EQ(element->centre, particle.centre) << particle.field.name;
            EXPECT_EQ(element->field.units, particle.field.units) << particle.field.name;
        }
        const FieldSpec* stored = findFieldSpec(particleFieldSpecs(), particle.field.name);
        if (stored != nullptr) {
            EXPECT_EQ(stored->units, particle.field.units) << particle.field.name;
            EXPECT_EQ(stored->description, particle.field.description);
        }
    }
    for (const char* shared : {"Density", "Pressure", "Damage", "PlasticStrain", "Velocity"}) {
        EXPECT_NE(findViewArraySpec(ViewBlockKind::FiniteElements, shared), nullptr) << shared;
        EXPECT_NE(findViewArraySpec(ViewBlockKind::Particles, shared), nullptr) << shared;
    }
    for (const ViewBlockKind kind : {ViewBlockKind::Particles, ViewBlockKind::FiniteElements}) {
        std::set<std::string_view> names{"Points", "Cells"};
        for (const auto& spec : viewArraySpecs(kind)) {
            EXPECT_TRUE(names.insert(spec.field.name).second) << "twice: " << spec.field.name;
        }
    }
}

TEST(RunFileView, ArraysComeInTableOrder) {
    const ViewBlock block = particleView(FiveParticles{}.view());
    const auto table = viewArraySpecs(ViewBlockKind::Particles);
    ASSERT_EQ(block.arrays.size(), table.size());
    for (std::size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(block.arrays[i].spec, &table[i]) << i;
    }
}
