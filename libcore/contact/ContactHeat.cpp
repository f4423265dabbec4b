#include "contact/ContactHeat.hpp"

#include "contact/ContactSolver.hpp"

namespace hvi::contact {

namespace {

/// Raises the alive elements of a node by a specific energy (shared among them by mass,
/// heat raises each by the same amount).
void heatNode(const ContactPoints& pts, std::size_t node, double specificEnergy) {
    const auto& s = pts.surface;
    const auto& nc = s.nodeCorners;
    for (int64_t k = nc.offset[node]; k < nc.offset[node + 1]; ++k) {
        pts.el.e[fe::NodeCorners::elementOf(nc.corners[static_cast<std::size_t>(k)])] +=
            specificEnergy;
    }
}

/// The mass that takes the master side's heat, and where it goes.
struct MasterSide {
    const ContactPoints& pts;
    const ConstraintSet& set;
    const Constraint& con;

    std::size_t segmentElement(std::size_t q) const {
        return static_cast<std::size_t>(
            pts.surface.segElement[static_cast<std::size_t>(set.footSegments[q].index)]);
    }

    double heatMass() const {
        double mass = 0.0;
        if (con.target < 0) {
            mass = pts.ps.mass[con.j];
        } else if (pts.isParticle(con.slave)) {
            for (std::size_t q = con.segmentFirst; q < con.segmentFirst + con.segmentCount; ++q) {
                mass += set.footSegments[q].weight * pts.el.mass[segmentElement(q)];
            }
        } else {
            for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
                mass += set.footNodes[q].weight *
                        pts.surface.nodeElementMass(
                            pts.el, static_cast<std::size_t>(set.footNodes[q].index));
            }
        }
        return mass;
    }

    void heat(double share, double heatMass) const {
        if (con.target < 0) {
            (*pts.half.e)[con.j] += share / pts.ps.mass[con.j];
        } else if (pts.isParticle(con.slave)) {
            for (std::size_t q = con.segmentFirst; q < con.segmentFirst + con.segmentCount; ++q) {
                const auto e = segmentElement(q);
                pts.el.e[e] += share * set.footSegments[q].weight / pts.el.mass[e];
            }
        } else if (heatMass > 0.0) {
            for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
                heatNode(pts, static_cast<std::size_t>(set.footNodes[q].index),
                         share * set.footNodes[q].weight / heatMass);
            }
        }
    }
};

/// The part of a constraint's relative normal velocity that the FE forces' first half kick of
/// this step made (the slave node's kick less the master nodes' weighted kicks along n):
/// the elements pay for that kick only through the motion left after the constraint.
double unpaidApproach(const ContactPoints& pts, const ConstraintSet& set, const Constraint& con,
                      double halfDt) {
    const auto& nd = pts.nd;
    const auto kickAlongN = [&](std::size_t node) {
        return halfDt / nd.mass[node] *
               (nd.fz[node] * con.nz + pts.radialFreedom(node) * nd.fr[node] * con.nr);
    };
    double approach = 0.0;
    if (!pts.isParticle(con.slave)) {
        approach += kickAlongN(pts.pointOf(con.slave));
    }
    if (con.target >= 0) {
        for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
            approach -= set.footNodes[q].weight *
                        kickAlongN(static_cast<std::size_t>(set.footNodes[q].index));
        }
    }
    return approach;
}

} // namespace

void markContacts(const ContactPoints& pts, const ConstraintSet& set, StepContacts& step) {
    for (const auto& con : set.list) {
        const std::size_t k = con.slave;
        if (con.kicked) {
            if (pts.isParticle(k)) {
                step.touchedParticles.push_back(static_cast<int32_t>(pts.pointOf(k)));
            } else {
                step.touchedNodes.push_back(static_cast<int32_t>(pts.pointOf(k)));
            }
            if (con.target < 0) {
                step.touchedParticles.push_back(static_cast<int32_t>(con.j));
            } else {
                for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
                    step.touchedNodes.push_back(set.footNodes[q].index);
                }
            }
        }
        if (con.impulse > 0.0) {
            ++step.contactCount;
        }
    }
}

void shareHeat(const ContactPoints& pts, const ConstraintSet& set, double dt,
               ContactEnergy& energy) {
    for (const auto& con : set.list) {
        if (!con.kicked) {
            continue;
        }
        const bool isParticle = pts.isParticle(con.slave);
        const std::size_t idx = pts.pointOf(con.slave);
        const double heat =
            -con.impulse * (0.5 * (con.approachBefore + normalVelocity(pts, set, con)) -
                            unpaidApproach(pts, set, con, 0.5 * dt));
        energy.dissipated += heat;
        const double slaveElementMass = isParticle ? 0.0 : pts.surface.nodeElementMass(pts.el, idx);
        const bool slaveIsFree = !isParticle && slaveElementMass <= 0.0;
        const double slaveHeatMass = isParticle    ? pts.ps.mass[idx]
                                     : slaveIsFree ? pts.nd.mass[idx]
                                                   : slaveElementMass;
        const MasterSide master{pts, set, con};
        const double masterHeatMass = master.heatMass();
        const double slaveShare = heat * slaveHeatMass / (slaveHeatMass + masterHeatMass);
        master.heat(heat - slaveShare, masterHeatMass);
        if (isParticle) {
            (*pts.half.e)[idx] += slaveShare / pts.ps.mass[idx];
        } else if (!slaveIsFree) {
            heatNode(pts, idx, slaveShare / slaveElementMass);
        } else {
            energy.freeNodeHeat += slaveShare;
        }
    }
}

} // namespace hvi::contact
