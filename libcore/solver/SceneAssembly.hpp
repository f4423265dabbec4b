// What a scene becomes before the time loop starts: the particles of the SPH bodies, the
// nodes and elements of the FE bodies (with the particle slots their eroded elements will
// take), each body's material description for the two point sets, and what contact needs to
// know of each body. The one place that reads a scene's bodies into point sets; Simulation
// hands the parts to its packages.
//
// Units: mm, mg, g/cm^3.
#pragma once

#include "contact/KinematicContact.hpp"
#include "fe/FeMesh.hpp"
#include "material/MaterialLibrary.hpp"
#include "material/MaterialPackage.hpp"
#include "scene/Scene.hpp"
#include "solver/ErodedParticles.hpp"
#include "sph/ParticleGenerator.hpp"
#include "sph/ParticleSet.hpp"

#include <memory>
#include <vector>

namespace hvi::solver {

/// The FE bodies' share (empty in a scene without FE bodies).
struct FeAssembly {
    fe::NodeSet nodes;
    fe::ElementSet elements;
    std::vector<material::BodyMaterial> materials; ///< per body; count 0 for SPH bodies
    std::vector<double> erosionFactors;            ///< per body
    std::vector<contact::ContactBody> contactBodies;
    std::unique_ptr<ErodedParticles> eroded; ///< null unless eroded elements become particles
};

struct SceneAssembly {
    /// One per body. BodyMaterial::spec points into this vector: it is filled once and only
    /// moved afterwards (a moved vector keeps its elements in place).
    std::vector<material::MaterialSpec> specs;
    /// One per body: an SPH body's particles, an FE body's reserve of eroded-element slots.
    std::vector<sph::BodyFill> fills;
    sph::ParticleSet particles;
    std::vector<material::BodyMaterial> particleMaterials; ///< per body
    FeAssembly fe;
    double minSpacing = 0.0; ///< the finest particle spacing or element size [mm]
};

SceneAssembly assembleScene(const scene::Scene& scene, const material::MaterialLibrary& library);

} // namespace hvi::solver
