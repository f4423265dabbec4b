// What the contact steps of one time step act on (contact/KinematicContact.hpp): the slaves
// (alive particles, then the alive FE nodes that lie on a surface or are free), read and
// written through one accessor, and the geometry of a slave against a master segment or a
// master particle. The steps themselves are contact/ContactSearch (candidates and time-step
// votes), contact/ContactConstraints, contact/ContactSolver and contact/ContactHeat.
//
// Units: mm, us, mg (km/s).
#pragma once

#include "fe/FeMesh.hpp"
#include "fe/SurfaceTopology.hpp"
#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace hvi::contact {

struct ContactOptions {
    bool axisymmetric = true;
    /// h / spacing of the particles: a particle's footprint on a surface is h / this wide
    /// (contact/Footprint.hpp). 0: particles press on a point, as nodes do.
    double smoothingLengthFactor = 0.0;
};

/// The particles' half-step state (the leapfrog's v^{n+1/2} and e^{n+1/2} arrays).
struct ParticleHalfStep {
    std::vector<double>* vz = nullptr;
    std::vector<double>* vr = nullptr;
    std::vector<double>* e = nullptr;
};

/// What contact needs to know about the bodies (scene body index -> size, discretisation).
struct ContactBody {
    bool finiteElement = false;
    double size = 0.0; ///< particle spacing or element size [mm]
};

/// The state of a slave: pointers into the particle or node arrays.
struct Slave {
    double* z;
    double* r;
    double* vz;
    double* vr;
    double mass, radius;
    int32_t body;
    bool free; ///< a node no alive element uses
    /// 0 for a node held on the axis (axisymmetric: it moves along z only), else 1.
    double radialFreedom;
};

/// A slave at (z, r) against a master segment (or, for a free node, a master particle).
struct SegmentHit {
    double xi = 0.0;   ///< projection on the segment, A = 0, B = 1
    double gap = 0.0;  ///< signed distance along the outward normal
    double nz = 0.0, nr = 0.0;
    double band = 0.0; ///< half the master body's element size
    bool valid = false;
};

struct ContactPoints {
    ContactPoints(sph::ParticleSet& particles, const ParticleHalfStep& half,
                  fe::ElementSet& elements, fe::NodeSet& nodes,
                  const fe::SurfaceTopology& surface, const std::vector<ContactBody>& bodies,
                  const ContactOptions& options);

    sph::ParticleSet& ps;
    ParticleHalfStep half;
    fe::ElementSet& el;
    fe::NodeSet& nd;
    const fe::SurfaceTopology& surface;
    const std::vector<ContactBody>& bodies;
    const ContactOptions& options;
    std::size_t np;                  ///< particles: slaves [0, np)
    std::vector<int32_t> slaveNodes; ///< the nodes of slaves np, np + 1, ...

    std::size_t slaveCount() const { return np + slaveNodes.size(); }
    bool isParticle(std::size_t slave) const { return slave < np; }
    /// The particle or node index of a slave.
    std::size_t pointOf(std::size_t slave) const {
        return slave < np ? slave : static_cast<std::size_t>(slaveNodes[slave - np]);
    }
    double bodySize(int32_t body) const { return bodies[static_cast<std::size_t>(body)].size; }
    /// A node held on the axis takes no radial impulse: the axis carries it (radial momentum
    /// is not conserved in axisymmetry; z-momentum, the conserved one, is unaffected).
    double radialFreedom(std::size_t node) const {
        return options.axisymmetric && nd.onAxis[node] ? 0.0 : 1.0;
    }
    Slave slave(std::size_t k) const;
    SegmentHit segmentHit(double z, double r, std::size_t segment) const;
    /// A free-node slave against particle j: the line of centres (n from the particle to the
    /// slave) and the gap beyond both radii; invalid for coincident points.
    SegmentHit particleHit(const Slave& slave, std::size_t j) const;
};

} // namespace hvi::contact
