// Eroded finite elements become SPH particles.
//
// Why: with erosion alone, an eroded element leaves its mass on its corner nodes, and a node
// with no element left flies on as a point mass with no pressure and, on the axis, no radial
// freedom (its v_r is held at 0). In the source study's foam panels and Whipple shields the
// eroded material of the axis elements then travels ahead of the debris cloud in single file
// at 1.5-3 km/s and punches a one-element column through the rear wall, an artefact of the 2D
// axisymmetric reduction (nothing lines up like that in 3D) that decided three verdicts the
// wrong way. Turned into particles, the eroded material keeps its pressure and strength
// state, spreads radially and joins the debris cloud, as the study's hybrid Autodyn setup
// and the open codes do: EPIC converts distorted elements into particles (Johnson, Stryk,
// Holmquist & Beissel (2002), "An algorithm to automatically convert distorted finite
// elements into meshless particles during dynamic deformation", Int. J. Impact Eng.
// 27:997), and OpenRadioss activates SPH particles held in reserve when a solid fails
// (/SOL2SPH, ../shared/reference/hydrocode-notes.md section 3).
//
// Reserve: every element of an FE body has one particle slot, appended after the body's
// place in the particle set when the scene is built, so each body's particles stay one
// contiguous range for the material pipeline. A slot that has not been used has zero mass and
// is not alive (a deleted particle has its mass).
//
// Conversion of element e with mass M, corner nodes a = 1..4 (exact conservation):
//   each corner gives up its share dm_a = M/4 of the lumped mass (all it has left when e was
//   its last element, so a node's mass reaches exactly 0 and the node is gone);
//   the particle takes mass M = sum dm_a and momentum sum dm_a v_a, so v_p = sum dm_a v_a / M
//   and the nodes keep their velocities: momentum is conserved exactly;
//   the kinetic energy the averaging removes, sum dm_a v_a^2/2 - M v_p^2/2 >= 0, is added to
//   the particle's internal energy with the element's own: energy is conserved exactly;
//   density, stress deviator, plastic strain and damage are the element's; the particle sits
//   at the mean of the corners with h = smoothingFactor sqrt(M / (2 pi r rho)) (the side of
//   the square of the (z, r) plane it stands for; planar: sqrt(M / rho)).
//
// Units: mm, us, mg (km/s, g/cm^3, MJ/kg, J).
#pragma once

#include "fe/FeMesh.hpp"
#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace hvi::solver {

class ErodedParticles {
public:
    ErodedParticles(bool axisymmetric, double smoothingFactor)
        : m_axisymmetric(axisymmetric), m_smoothingFactor(smoothingFactor) {}

    /// Appends one unused particle slot per element of the body `mesh` (of scene body
    /// `bodyIndex`, reference density rho0) to `particles`, at the element centroids.
    /// Returns the index of the first slot.
    std::size_t reserve(const fe::BodyMesh& mesh, int32_t bodyIndex, double rho0,
                        const fe::NodeSet& nodes, const fe::ElementSet& elements,
                        sph::ParticleSet& particles);

    /// Turns the listed eroded elements into their particles (see above) with densities
    /// clamped to [rhoMin, rhoMax] of each body (indexed by body); returns the particle
    /// indices, ascending. Nodes left with no mass are marked not alive.
    std::vector<int32_t> convert(const std::vector<int32_t>& erodedElements,
                                 const fe::ElementSet& elements, fe::NodeSet& nodes,
                                 sph::ParticleSet& particles, const std::vector<double>& rhoMin,
                                 const std::vector<double>& rhoMax) const;

    /// The particle slot of element e (-1: its body has no reserve).
    int32_t slotOf(std::size_t element) const;

private:
    struct Range {
        std::size_t firstElement = 0, elementCount = 0, firstParticle = 0;
    };
    bool m_axisymmetric;
    double m_smoothingFactor;
    std::vector<Range> m_ranges;
};

} // namespace hvi::solver
