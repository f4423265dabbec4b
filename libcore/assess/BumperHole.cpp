#include "assess/BumperHole.hpp"

#include "assess/MaterialState.hpp"
#include "core/Units.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::assess {

HoleEdge holeEdge(const std::vector<double>& fraction, double rMin, double w,
                  const Criteria& criteria) {
    HoleEdge edge;
    const std::size_t n = fraction.size();
    // Usable bins: not the outermost holeEdgeBins (but always at least one).
    const auto edgeBins = static_cast<std::size_t>(std::max(0, criteria.holeEdgeBins));
    const std::size_t usable = n > edgeBins ? n - edgeBins : std::min<std::size_t>(n, 1);
    const double span = criteria.holeSpanFraction;
    std::optional<std::size_t> lastOpen;
    for (std::size_t k = 0; k < usable; ++k) {
        if (fraction[k] < span) {
            lastOpen = k;
        }
    }
    if (!lastOpen) {
        return edge; // no hole
    }
    const std::size_t k = *lastOpen;
    double radius = 0.0;
    if (k + 1 >= usable) {
        edge.reachesEdge = true;
        radius = rMin + static_cast<double>(usable) * w;
    } else {
        const double fa = fraction[k], fb = fraction[k + 1];
        const double t = std::clamp((span - fa) / (fb - fa), 0.0, 1.0);
        radius = rMin + (static_cast<double>(k) + 0.5 + t) * w;
    }
    edge.diameterMm = 2.0 * radius;
    return edge;
}

std::optional<BumperHole> bumperHole(const MaterialItems& items, const ShieldLayout& layout,
                                     const Criteria& criteria) {
    if (!layout.bumper) {
        return std::nullopt;
    }
    const std::size_t b = *layout.bumper;
    const BodyLayout& body = layout.bodies[b];
    const double extent = body.rMax - body.rMin;
    // Bins aligned with the particle lattice (the generator puts round(extent / spacing)
    // columns across the plate).
    const long count = std::max(1L, std::lround(extent / body.spacing));
    const double w = extent / static_cast<double>(count);
    const auto n = static_cast<std::size_t>(count);
    auto binOf = [&](double r) -> long {
        return static_cast<long>(std::floor((r - body.rMin) / w));
    };

    // Original mass per bin: the reference items' masses when the run keeps its particle
    // slots, else rho_ref * thickness * ring area.
    std::vector<double> original(n, 0.0), inPlace(n, 0.0), intact(n, 0.0);
    if (items.hasReference) {
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (belongsTo(items, i, b)) {
                const long k = binOf(items.r0[i]);
                if (k >= 0 && k < count) {
                    original[static_cast<std::size_t>(k)] += items.mass[i];
                }
            }
        }
    } else {
        for (std::size_t k = 0; k < n; ++k) {
            const double r0 = body.rMin + static_cast<double>(k) * w, r1 = r0 + w;
            const double area = layout.axisymmetric ? units::kPi * (r1 * r1 - r0 * r0) : w;
            original[k] = body.referenceDensity * body.thickness() * area;
        }
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!belongsTo(items, i, b) || !isInPlace(items, i, layout, criteria)) {
            continue;
        }
        const long k = binOf(items.r[i]);
        if (k >= 0 && k < count) {
            inPlace[static_cast<std::size_t>(k)] += items.mass[i];
            if (!isFailed(items, i, layout, criteria)) {
                intact[static_cast<std::size_t>(k)] += items.mass[i];
            }
        }
    }

    BumperHole hole;
    hole.binWidthMm = w;
    for (std::size_t k = 0; k < n; ++k) {
        hole.binCentreMm.push_back(body.rMin + (static_cast<double>(k) + 0.5) * w);
        hole.inPlaceFraction.push_back(original[k] > 0.0 ? inPlace[k] / original[k] : 1.0);
        hole.intactFraction.push_back(original[k] > 0.0 ? intact[k] / original[k] : 1.0);
    }
    const HoleEdge clear = holeEdge(hole.inPlaceFraction, body.rMin, w, criteria);
    hole.diameterMm = clear.diameterMm;
    hole.reachesEdge = clear.reachesEdge;
    hole.failedZoneDiameterMm = holeEdge(hole.intactFraction, body.rMin, w, criteria).diameterMm;
    return hole;
}

} // namespace hvi::assess
