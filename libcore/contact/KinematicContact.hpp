// Contact between bodies that do not share a discretisation: SPH particles against
// finite-element surfaces, FE nodes against the surfaces of other FE bodies, and free nodes
// (left behind by erosion) against both. SPH particles of different bodies need none of this:
// they interact through the SPH pair forces.
//
// Method: node-to-segment contact enforced on the velocities of the half step, before the
// drift ("speculative" contact: a constraint on the velocity that closes the gap and no
// more, Catto E. (2013), "Continuous collision", GDC; the node-on-segment geometry and the
// momentum-exchange form are those of the eroding-interface contact of EPIC, Johnson G.R.,
// Stryk R.A. (1987), Int. J. Impact Eng. 5:411-421, and of particles against element
// surfaces, Johnson, Beissel & Stryk (2002), Comput. Methods Appl. Mech. Eng. 191:2451).
// After the first half kick of a step dt, a slave (particle, surface node or free node) of
// radius R at signed distance g from a master segment A -> B of another body (a particle
// made of an eroded element also meets its own body's surfaces) (outward normal n,
// projection xi in [0, 1], and -l/2 < g with l the master body's element size, so a slave
// deeper than half an element is never pushed out through the far side of a thin layer),
// approaching it with normal speed -v_n larger than the gap it may still close, (g - R)/dt
// (0 once touching), gets the normal impulse that brings the approach down to that,
//     J = (-v_n - max(g - R, 0)/dt) / (1/m_s + (1-xi)^2/m_A + xi^2/m_B),
// applied as +J n to the slave and -J (1-xi) n, -J xi n to A and B. A particle spreads its
// impulse over its footprint instead (contact/Footprint.hpp): the master velocity is
// sum_k w_k v_k over the footprint's nodes, the denominator 1/m_s + sum_k w_k^2/m_k, and
// node k takes -J w_k n. Nodes held on the axis take no radial impulse (they move along z
// only), so contact never moves them off it. (A slave slightly inside,
// R - g below 2 % of its spacing, which the iteration below can leave when it stops short,
// is made to separate at 0.2 (R - g)/dt, so overlaps never build up;
// a deeper one, left by erosion exposing a surface, is only kept from growing). So the drift never
// makes it penetrate, the pair's momentum is conserved exactly, nothing is ever pushed apart or
// pulled back (no position corrections, no sticking), and contact cannot create energy.
// The kinetic energy an impulse takes (a perfectly inelastic normal collision of the contact
// points), less the part the FE forces' kick of the step added unpaid, becomes heat, shared
// by mass between the slave (a particle, or the elements around a node) and the master side
// (the elements under the footprint or around the master nodes), as in a real impact where
// it goes into shock heating (contact/ContactHeat.hpp). Measured energy errors: 0.12 % and
// 0.22 % of the small impact energy in the 0.1 km/s elastic rebounds of
// tests/verification/FeContact_test.cpp (SPH and FE block on an FE plate).
// Master segments are the boundary edges of the alive elements of each FE body (edges of
// exactly one alive element), so surfaces exposed by erosion become masters as soon as an
// element erodes. Radii: a particle R = spacing / 2 (its lattice half-width, so particles rest
// against a surface at the spacing they keep among themselves); a node R = 0. Free nodes
// against particles: the same impulse along the line of centres.
// Time step: a slave approaching a segment at normal speed v_n votes dt <= (c/2) / v_n (c: the
// search cell, 2.5 times the largest body spacing; times the Courant factor), so no approach
// outruns the search, and every pair that could touch within a step is constrained (no
// pass-through at any speed). Contacts are found in parallel; the impulses of a step are
// solved together by projected Gauss-Seidel passes in slave order (each contact's
// accumulated impulse stays >= 0), so the result does not depend on the thread count.
// The steps, each in its own file: the master surface (fe/SurfaceTopology), candidates and
// votes (contact/ContactSearch), constraints (contact/ContactConstraints), impulses
// (contact/ContactSolver), contact counts and heat (contact/ContactHeat).
//
// Units: mm, us, mg (km/s, J).
#pragma once

#include "contact/ContactPoints.hpp"
#include "contact/ContactHeat.hpp"
#include "fe/SurfaceTopology.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace hvi::contact {

class KinematicContact {
public:
    KinematicContact(ContactOptions options, std::vector<ContactBody> bodies);

    /// Constrains the half-step velocities of a step of length dt [us] before the drift, at
    /// the start-of-step positions: node velocities (nodes.vz/vr) and the particles'
    /// half-step arrays change, and, as heat, specific energies (the particles' half-step
    /// energy, elements' e); momentum and total energy do not change.
    void resolve(sph::ParticleSet& particles, const ParticleHalfStep& half,
                 fe::ElementSet& elements, fe::NodeSet& nodes, double dt);

    /// Only the time-step vote for the current state (start of a run, resume): changes
    /// nothing.
    void vote(sph::ParticleSet& particles, const ParticleHalfStep& half, fe::ElementSet& elements,
              fe::NodeSet& nodes, double dt);

    /// Largest time step without pass-through, from the last resolve() [us] (+inf if nothing
    /// approaches a surface).
    double stableTimeStep() const { return m_stableDt; }
    /// Kinetic energy turned into heat at contacts since the start [J].
    double dissipatedEnergy() const { return m_energy.dissipated; }
    void restoreDissipatedEnergy(double energy) { m_energy.dissipated = energy; }
    /// The part of it that went into free nodes (eroded material, which carries no internal
    /// energy of its own): booked with the eroded energy [J].
    double freeNodeHeat() const { return m_energy.freeNodeHeat; }
    void restoreFreeNodeHeat(double energy) { m_energy.freeNodeHeat = energy; }
    /// Contacts resolved in the last resolve().
    std::size_t contactCount() const { return m_contactCount; }
    /// The last vote: the state a checkpoint must carry for a resumed run to repeat the
    /// original bit for bit.
    void restoreStableTimeStep(double stableDt) { m_stableDt = stableDt; }
    /// Particles whose half-step state the last resolve() changed (may repeat): the solver
    /// must advance them even when the SPH evaluation skips them as dormant.
    const std::vector<int32_t>& touchedParticles() const { return m_touchedParticles; }
    /// FE nodes whose half-step velocity the last resolve() changed (may repeat).
    const std::vector<int32_t>& touchedNodes() const { return m_touchedNodes; }
    /// Master segments (FE surface edges) in use.
    std::size_t segmentCount() const { return m_surface.segmentCount(); }

private:
    void run(sph::ParticleSet& particles, const ParticleHalfStep& half, fe::ElementSet& elements,
             fe::NodeSet& nodes, double dt, bool constrain);

    ContactOptions m_options;
    std::vector<ContactBody> m_bodies;
    fe::SurfaceTopology m_surface;    ///< master segments, node-element lists
    std::vector<int32_t> m_touchedParticles;
    std::vector<int32_t> m_touchedNodes;
    double m_stableDt = std::numeric_limits<double>::infinity();
    ContactEnergy m_energy;
    std::size_t m_contactCount = 0;
};

} // namespace hvi::contact
