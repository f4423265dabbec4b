#include "contact/ContactPoints.hpp"

#include <cmath>

namespace hvi::contact {

ContactPoints::ContactPoints(sph::ParticleSet& particles, const ParticleHalfStep& halfStep,
                             fe::ElementSet& elements, fe::NodeSet& nodes,
                             const fe::SurfaceTopology& topology,
                             const std::vector<ContactBody>& bodyList,
                             const ContactOptions& contactOptions)
    : ps(particles), half(halfStep), el(elements), nd(nodes), surface(topology),
      bodies(bodyList), options(contactOptions), np(particles.size()) {
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (nd.alive[n] && (surface.surfaceNode[n] || nd.elementCount[n] == 0)) {
            slaveNodes.push_back(static_cast<int32_t>(n));
        }
    }
}

Slave ContactPoints::slave(std::size_t k) const {
    const std::size_t idx = pointOf(k);
    Slave s{};
    if (isParticle(k)) {
        s = {&ps.z[idx], &ps.r[idx], &(*half.vz)[idx], &(*half.vr)[idx], ps.mass[idx], 0.0,
             ps.body[idx], false, 1.0};
        // A particle's radius is its lattice half-width, so particles rest against a surface
        // at the spacing they keep among themselves; a node's is 0.
        s.radius = 0.5 * bodySize(s.body);
    } else {
        s = {&nd.z[idx],   &nd.r[idx],   &nd.vz[idx], &nd.vr[idx], nd.mass[idx], 0.0,
             nd.body[idx], nd.elementCount[idx] == 0, radialFreedom(idx)};
    }
    return s;
}

SegmentHit ContactPoints::segmentHit(double z, double r, std::size_t s) const {
    SegmentHit h;
    const auto a = static_cast<std::size_t>(surface.segA[s]);
    const auto b = static_cast<std::size_t>(surface.segB[s]);
    const double tz = nd.z[b] - nd.z[a], tr = nd.r[b] - nd.r[a];
    const double length = std::sqrt(tz * tz + tr * tr);
    if (!(length > 0.0)) {
        return h;
    }
    const double uz = tz / length, ur = tr / length;
    h.nz = ur; // outward: the element lies to the left of A -> B
    h.nr = -uz;
    const double pz = z - nd.z[a], pr = r - nd.r[a];
    h.xi = (pz * uz + pr * ur) / length;
    h.gap = pz * h.nz + pr * h.nr;
    h.band = 0.5 * bodySize(surface.segBody[s]);
    h.valid = h.xi >= 0.0 && h.xi <= 1.0;
    return h;
}

SegmentHit ContactPoints::particleHit(const Slave& sl, std::size_t j) const {
    SegmentHit h;
    const double reach = sl.radius + 0.5 * bodySize(ps.body[j]);
    const double dz = *sl.z - ps.z[j], dr = *sl.r - ps.r[j];
    const double dist = std::sqrt(dz * dz + dr * dr);
    if (!(dist > 0.0)) {
        return h;
    }
    h.nz = dz / dist;
    h.nr = dr / dist;
    h.gap = dist - reach;
    h.valid = true;
    return h;
}

} // namespace hvi::contact
