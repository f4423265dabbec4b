#include "contact/ContactSolver.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::contact {

namespace {

/// Changes the velocity of a point by dv along n.
void kick(double& vz, double& vr, double dv, double nz, double nr) {
    vz += dv * nz;
    vr += dv * nr;
}

/// Applies a change of a constraint's impulse to its slave and master.
void applyImpulse(const ContactPoints& pts, const ConstraintSet& set, const Constraint& con,
                  double change) {
    const Slave& sl = con.sl;
    kick(*sl.vz, *sl.vr, change / sl.mass, con.nz, sl.radialFreedom * con.nr);
    if (con.target >= 0) {
        for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
            const auto node = static_cast<std::size_t>(set.footNodes[q].index);
            kick(pts.nd.vz[node], pts.nd.vr[node],
                 -change * set.footNodes[q].weight / pts.nd.mass[node], con.nz,
                 pts.radialFreedom(node) * con.nr);
        }
    } else {
        kick((*pts.half.vz)[con.j], (*pts.half.vr)[con.j], -change / pts.ps.mass[con.j],
             con.nz, con.nr);
    }
}

} // namespace

double normalVelocity(const ContactPoints& pts, const ConstraintSet& set, const Constraint& con) {
    const Slave& sl = con.sl;
    if (con.target < 0) {
        return (*sl.vz - (*pts.half.vz)[con.j]) * con.nz +
               (*sl.vr - (*pts.half.vr)[con.j]) * con.nr;
    }
    double vmz = 0.0, vmr = 0.0;
    for (std::size_t q = con.nodeFirst; q < con.nodeFirst + con.nodeCount; ++q) {
        const auto node = static_cast<std::size_t>(set.footNodes[q].index);
        vmz += set.footNodes[q].weight * pts.nd.vz[node];
        vmr += set.footNodes[q].weight * pts.nd.vr[node];
    }
    return (*sl.vz - vmz) * con.nz + (*sl.vr - vmr) * con.nr;
}

void solveImpulses(const ContactPoints& pts, ConstraintSet& set) {
    for (auto& con : set.list) {
        con.approachBefore = normalVelocity(pts, set, con);
    }
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        double largestChange = 0.0;
        for (auto& con : set.list) {
            const double vn = normalVelocity(pts, set, con);
            const double wanted = std::max(con.impulse + (-vn - con.allowed) / con.invSum, 0.0);
            const double change = wanted - con.impulse;
            if (change == 0.0) {
                continue;
            }
            con.impulse = wanted;
            con.kicked = true;
            largestChange = std::max(largestChange, std::fabs(change) * con.invSum);
            applyImpulse(pts, set, con, change);
        }
        if (largestChange <= kPassTolerance) {
            break;
        }
    }
}

} // namespace hvi::contact
