#include "contact/ContactConstraints.hpp"

namespace hvi::contact {

namespace {

/// Normal, inverse effective mass and footprint of a slave against a segment; the gap
/// beyond the slave's radius.
double againstSegment(const ContactPoints& pts, std::size_t k, Constraint& con, ConstraintSet& set,
                      std::vector<Share>& nodeShares, std::vector<Share>& segmentShares) {
    const Slave& sl = con.sl;
    const auto seg = static_cast<std::size_t>(con.target);
    const SegmentHit h = pts.segmentHit(*sl.z, *sl.r, seg);
    con.nz = h.nz;
    con.nr = h.nr;
    con.invSum = (h.nz * h.nz + sl.radialFreedom * h.nr * h.nr) / sl.mass;
    const double halfWidth = pts.isParticle(k) && pts.options.smoothingLengthFactor > 0.0
                                 ? 0.5 * pts.ps.h[k] / pts.options.smoothingLengthFactor
                                 : 0.0;
    const auto& surface = pts.surface;
    const SurfaceChain chain{surface.segA, surface.segB, surface.segNext,
                             surface.segPrev, pts.nd.z,    pts.nd.r};
    footprintShares(chain, con.target, h.xi, halfWidth, pts.options.axisymmetric, nodeShares,
                    segmentShares);
    con.nodeFirst = set.footNodes.size();
    con.nodeCount = nodeShares.size();
    con.segmentFirst = set.footSegments.size();
    con.segmentCount = segmentShares.size();
    for (const Share& n : nodeShares) {
        const auto node = static_cast<std::size_t>(n.index);
        con.invSum += n.weight * n.weight *
                      (h.nz * h.nz + pts.radialFreedom(node) * h.nr * h.nr) / pts.nd.mass[node];
        set.footNodes.push_back(n);
    }
    set.footSegments.insert(set.footSegments.end(), segmentShares.begin(), segmentShares.end());
    return h.gap - sl.radius;
}

} // namespace

ConstraintSet buildConstraints(const ContactPoints& pts, const std::vector<SlaveContacts>& found,
                               double dt) {
    ConstraintSet set;
    std::vector<Share> nodeShares, segmentShares;
    for (std::size_t k = 0; k < found.size(); ++k) {
        const SlaveContacts& c = found[k];
        if (c.count == 0) {
            continue;
        }
        const Slave sl = pts.slave(k);
        for (int q = 0; q < c.count; ++q) {
            Constraint con;
            con.slave = k;
            con.sl = sl;
            con.target = c.target[static_cast<std::size_t>(q)];
            double gap = 0.0;
            if (con.target >= 0) {
                gap = againstSegment(pts, k, con, set, nodeShares, segmentShares);
            } else {
                con.j = static_cast<std::size_t>(-1 - con.target);
                const SegmentHit h = pts.particleHit(sl, con.j);
                if (!h.valid) {
                    continue;
                }
                con.nz = h.nz;
                con.nr = h.nr;
                gap = h.gap;
                con.invSum = (h.nz * h.nz + sl.radialFreedom * h.nr * h.nr) / sl.mass +
                             1.0 / pts.ps.mass[con.j];
            }
            const double size = pts.bodySize(sl.body);
            const double recovered =
                gap > -kRecoverableOverlap * size ? kOverlapRecovery * gap : 0.0;
            con.allowed = (gap >= 0.0 ? gap : recovered) / dt;
            set.list.push_back(con);
        }
    }
    return set;
}

} // namespace hvi::contact
