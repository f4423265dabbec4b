#include "assess/DebrisCloud.hpp"

#include "assess/MaterialState.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace hvi::assess {

namespace {

/// The value v[order[k]] at which the mass met from the top of `order` first exceeds
/// `fraction` of `total` (order sorts the items by decreasing value).
double massQuantileFromTop(const std::vector<double>& v, const std::vector<double>& m,
                           const std::vector<std::size_t>& order, double total, double fraction) {
    double seen = 0.0;
    for (std::size_t k : order) {
        seen += m[k];
        if (seen > fraction * total) {
            return v[k];
        }
    }
    return v[order.back()];
}

std::vector<std::size_t> descendingOrder(const std::vector<double>& v) {
    std::vector<std::size_t> order(v.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return v[a] > v[b]; });
    return order;
}

} // namespace

DebrisCloud debrisCloud(const MaterialItems& items, const ShieldLayout& layout,
                        const Criteria& criteria) {
    DebrisCloud cloud;
    cloud.timeUs = items.timeUs;
    const double origin = layout.depthOriginZ();
    const double bumperBeyond =
        layout.bumper ? origin + axialWindow(layout.bodies[*layout.bumper], criteria) : origin;

    std::vector<double> z, r, vz, m;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items.alive[i] || items.body[i] < 0) {
            continue;
        }
        const auto b = static_cast<std::size_t>(items.body[i]);
        const BodyLayout& body = layout.bodies[b];
        bool debris = false;
        switch (body.role) {
        case scene::BodyRole::Projectile:
        case scene::BodyRole::Bumper:
            debris = items.z[i] > bumperBeyond;
            break;
        case scene::BodyRole::CoreLayer:
        case scene::BodyRole::CoreRing:
        case scene::BodyRole::RearWall:
            debris = items.z[i] - items.z0[i] > 2.0 * body.spacing &&
                     isFailed(items, i, layout, criteria);
            break;
        default:
            break;
        }
        if (debris) {
            z.push_back(items.z[i]);
            r.push_back(items.r[i]);
            vz.push_back(items.vz[i]);
            m.push_back(items.mass[i]);
        }
    }
    cloud.items = z.size();
    if (z.empty()) {
        return cloud;
    }
    const double total = std::accumulate(m.begin(), m.end(), 0.0);
    cloud.massMg = total;
    const auto byZ = descendingOrder(z);
    cloud.leadingEdgeZMm = massQuantileFromTop(z, m, byZ, total, criteria.leadingEdgeMassFraction);
    cloud.leadingEdgeDepthMm = cloud.leadingEdgeZMm - origin;
    // The front slab: from the leading edge back to the frontMassFraction quantile (the few
    // items ahead of the leading edge are left out of the speed as they are of the position).
    double seen = 0.0, frontMass = 0.0, frontMomentum = 0.0;
    for (std::size_t k : byZ) {
        seen += m[k];
        if (seen <= criteria.leadingEdgeMassFraction * total) {
            continue; // ahead of the leading edge
        }
        if (frontMass > 0.0 && seen > criteria.frontMassFraction * total) {
            break;
        }
        frontMass += m[k];
        frontMomentum += m[k] * vz[k];
    }
    cloud.leadingEdgeSpeedKmS = frontMass > 0.0 ? frontMomentum / frontMass : 0.0;
    cloud.maxAxialSpeedKmS = *std::max_element(vz.begin(), vz.end());
    cloud.radiusMm =
        massQuantileFromTop(r, m, descendingOrder(r), total, criteria.leadingEdgeMassFraction);
    double mz = 0.0, mv = 0.0;
    for (std::size_t k = 0; k < z.size(); ++k) {
        mz += m[k] * z[k];
        mv += m[k] * vz[k];
    }
    cloud.centreOfMassZMm = total > 0.0 ? mz / total : 0.0;
    cloud.centreOfMassSpeedKmS = total > 0.0 ? mv / total : 0.0;
    return cloud;
}

} // namespace hvi::assess
