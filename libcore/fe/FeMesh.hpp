// Structure-of-arrays storage of the Lagrange finite-element bodies: nodes (position,
// velocity, lumped mass, force) and 4-node quadrilateral elements (connectivity and the
// material state at the element's single integration point).
//
// The element state uses the same field names as sph::ParticleSet (rho, e, p, cs, szz, srr,
// srz, plasticStrain, damage, body, alive), so the one material pipeline
// (material::MaterialPackage) runs over elements and particles alike.
//
// Mass: an element carries the true (3D) mass of the ring it sweeps, 2 pi rho0 integral(r dA)
// (axisymmetric) or rho0 A per unit depth (planar), lumped a quarter to each corner node
// (Hallquist, LS-DYNA Theory Manual, volume-weighted 2D element). Units: mm, us, mg (km/s,
// GPa, g/cm^3, MJ/kg); see docs/conventions.md.
#pragma once

#include "core/FieldList.hpp"
#include "scene/Scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi::fe {

struct NodeSet {
    std::vector<double> z, r;          ///< position [mm]
    std::vector<double> vz, vr;        ///< velocity [km/s]
    std::vector<double> mass;          ///< lumped mass [mg] (an eroded element that becomes a
                                       ///< particle takes its share; 0: the node is gone)
    std::vector<double> fz, fr;        ///< force of the current step [mg mm/us^2 = kN]
    std::vector<int32_t> body;         ///< scene body index
    std::vector<uint8_t> alive;        ///< 0 once deleted (runaway, left the domain)
    std::vector<uint8_t> onAxis;       ///< axisymmetric: started at r = 0, kept there
    std::vector<int32_t> elementCount; ///< alive elements using the node (0: a free node)

    std::size_t size() const { return z.size(); }
};

struct ElementSet {
    std::vector<int32_t> connectivity;   ///< 4 node indices per element, counter-clockwise
    std::vector<int32_t> body;           ///< scene body index
    std::vector<uint8_t> alive;          ///< 0 once eroded
    std::vector<double> mass;            ///< [mg]
    std::vector<double> rho, e, p, cs;   ///< g/cm^3, MJ/kg, GPa, km/s
    std::vector<double> q;               ///< artificial bulk viscosity pressure [GPa]
    std::vector<double> szz, srr, srz;   ///< stress deviator [GPa] (empty without strength)
    std::vector<double> plasticStrain;   ///< [-] (empty without strength)
    std::vector<double> damage;          ///< [-] (empty without strength)
    std::vector<double> tensionOnset;    ///< damage state (JohnsonCookDamage::damageAfter) [-]
    std::vector<double> geometricStrain; ///< the strain erosion tests (fe/ErosionStrain.hpp) [-]

    std::size_t size() const { return body.size(); }
    bool hasStrength() const { return m_withStrength; }
    /// Allocates the strength arrays (zero) for every element.
    void enableStrength();
    /// Node a (0..3) of element i.
    int32_t node(std::size_t i, int a) const {
        return connectivity[4 * i + static_cast<std::size_t>(a)];
    }

private:
    bool m_withStrength = false;
};

/// The nodes' evolved state (alive is an integer field), by checkpoint name ("node_" +).
inline constexpr std::array<Field<NodeSet>, 7> kNodeStateFields{{
    {"z", &NodeSet::z},
    {"r", &NodeSet::r},
    {"vz", &NodeSet::vz},
    {"vr", &NodeSet::vr},
    {"fz", &NodeSet::fz},
    {"fr", &NodeSet::fr},
    {"mass", &NodeSet::mass}, // eroded elements turned into particles take theirs
}};
/// The elements' evolved state without strength, by checkpoint name ("element_" +).
inline constexpr std::array<Field<ElementSet>, 4> kElementStateFields{{
    {"rho", &ElementSet::rho},
    {"e", &ElementSet::e},
    {"q", &ElementSet::q},
    {"geometric_strain", &ElementSet::geometricStrain},
}};
/// The strength state (allocated only with strength), by checkpoint name ("element_" +).
inline constexpr std::array<Field<ElementSet>, 6> kElementStrengthFields{{
    {"szz", &ElementSet::szz},
    {"srr", &ElementSet::srr},
    {"srz", &ElementSet::srz},
    {"plastic_strain", &ElementSet::plasticStrain},
    {"damage", &ElementSet::damage},
    {"tension_onset", &ElementSet::tensionOnset},
}};

/// The index ranges one body occupies.
/// Which element corners meet at each node (CSR): corners[offset[n] .. offset[n + 1]) are the
/// slots 4 e + a (element e, corner a) at node n, in element order. The FE update gathers
/// corner forces through it (over every element); the contact surface shares heat and mass
/// among a node's elements through it (over the alive ones).
struct NodeCorners {
    std::vector<int64_t> offset; ///< nodes + 1
    std::vector<int32_t> corners;

    static NodeCorners of(const ElementSet& elements, std::size_t nodeCount, bool aliveOnly);
    static std::size_t elementOf(int32_t corner) { return static_cast<std::size_t>(corner) / 4; }
};

struct BodyMesh {
    std::size_t firstNode = 0, nodeCount = 0;
    std::size_t firstElement = 0, elementCount = 0;
    std::size_t divisionsZ = 0, divisionsR = 0;
    double elementSize = 0.0; ///< the larger edge of the structured cells [mm]
};

/// Meshes a plate or rectangle body with a structured grid of n_z x n_r quadrilaterals
/// (n = ceil(length / spacing), as geometry::GmshMesher, so the .msh written beside a run is
/// the same mesh), at density rho0 and specific energy e0, moving with the body's velocity.
/// Spheres cannot be meshed (InputError naming the body).
BodyMesh meshBody(const scene::Body& body, int32_t bodyIndex, double rho0, double e0,
                  bool axisymmetric, NodeSet& nodes, ElementSet& elements);

} // namespace hvi::fe
