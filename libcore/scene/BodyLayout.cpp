#include "scene/BodyLayout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hvi::scene {

namespace {

struct Box {
    double z0, z1, r0, r1;
};

Box boxOf(const Shape& s) {
    return {s.boundZMin(), s.boundZMax(), s.boundRMin(), s.boundRMax()};
}

double boxBoxDepth(const Box& a, const Box& b) {
    const double dz = std::min(a.z1, b.z1) - std::max(a.z0, b.z0);
    const double dr = std::min(a.r1, b.r1) - std::max(a.r0, b.r0);
    return std::min(dz, dr);
}

/// A half-disc (centre on the axis) against a box: the radius less the distance from the
/// centre to the box, or, with the centre inside the box, the radius plus the centre's depth.
double discBoxDepth(const Shape& disc, const Box& b) {
    const double cz = disc.centerZ, cr = 0.0;
    const double nz = std::clamp(cz, b.z0, b.z1), nr = std::clamp(cr, b.r0, b.r1);
    const double distance = std::hypot(cz - nz, cr - nr);
    if (distance > 0.0) {
        return disc.radius - distance;
    }
    const double inside = std::min({cz - b.z0, b.z1 - cz, b.r1 - cr});
    return disc.radius + inside;
}

std::string mm(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

} // namespace

double overlapDepth(const Shape& a, const Shape& b) {
    const bool aDisc = a.kind == ShapeKind::Sphere, bDisc = b.kind == ShapeKind::Sphere;
    if (aDisc && bDisc) {
        return a.radius + b.radius - std::fabs(a.centerZ - b.centerZ);
    }
    if (aDisc) {
        return discBoxDepth(a, boxOf(b));
    }
    if (bDisc) {
        return discBoxDepth(b, boxOf(a));
    }
    return boxBoxDepth(boxOf(a), boxOf(b));
}

std::vector<InputIssue> bodyLayoutIssues(const Scene& scene, const std::string& file) {
    std::vector<InputIssue> issues;
    const auto& bodies = scene.bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const std::string ptr = "/bodies/" + std::to_string(i) + "/shape";
        for (std::size_t j = 0; j < i; ++j) {
            const double depth = overlapDepth(bodies[i].shape, bodies[j].shape);
            if (depth > 0.5 * std::min(bodies[i].spacing, bodies[j].spacing)) {
                issues.push_back({file, ptr,
                                  "overlaps body '" + bodies[j].name + "' (/bodies/" +
                                      std::to_string(j) + ") by " + mm(depth) + " mm",
                                  "bodies that touch at most"});
            }
        }
        const Shape& s = bodies[i].shape;
        const double slack = 0.5 * bodies[i].spacing;
        if (scene.domain.radius > 0.0 && s.boundRMax() > scene.domain.radius + slack) {
            issues.push_back({file, ptr,
                              "reaches r = " + mm(s.boundRMax()) +
                                  " mm, beyond the domain radius " + mm(scene.domain.radius) +
                                  " mm (plates are not cut to the domain)",
                              "a body within /domain/radius_mm, or a wider domain"});
        }
        if (scene.domain.zMin && s.boundZMin() < *scene.domain.zMin - slack) {
            issues.push_back({file, ptr,
                              "starts at z = " + mm(s.boundZMin()) + " mm, upstream of z_min " +
                                  mm(*scene.domain.zMin) + " mm",
                              "a body within /domain/z_min_mm, or a smaller z_min_mm"});
        }
        if (scene.domain.zMax && s.boundZMax() > *scene.domain.zMax + slack) {
            issues.push_back({file, ptr,
                              "ends at z = " + mm(s.boundZMax()) + " mm, downstream of z_max " +
                                  mm(*scene.domain.zMax) + " mm",
                              "a body within /domain/z_max_mm, or a larger z_max_mm"});
        }
    }
    return issues;
}

std::vector<std::string> bodyLayoutWarnings(const Scene& scene) {
    std::vector<std::string> warnings;
    bool anyMoving = false;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& a = scene.bodies[i];
        anyMoving = anyMoving || a.velocityZ != 0.0 || a.velocityR != 0.0;
        if (a.velocityZ == 0.0) {
            continue;
        }
        // Ahead: another body beyond a's leading face in the direction of travel whose radial
        // extent overlaps a's.
        bool target = false;
        for (std::size_t j = 0; j < scene.bodies.size() && !target; ++j) {
            const Shape& b = scene.bodies[j].shape;
            if (j == i || b.boundRMin() >= a.shape.boundRMax() ||
                a.shape.boundRMin() >= b.boundRMax()) {
                continue;
            }
            target = a.velocityZ > 0.0 ? b.boundZMax() > a.shape.boundZMax()
                                       : b.boundZMin() < a.shape.boundZMin();
        }
        if (!target) {
            warnings.push_back("body '" + a.name + "' moves " +
                               (a.velocityZ > 0.0 ? "downstream" : "upstream") +
                               " along the axis but no body lies in its path: it will strike "
                               "nothing (check its velocity's sign and the bodies' radii)");
        }
    }
    if (!anyMoving && !scene.bodies.empty()) {
        warnings.push_back("no body moves: nothing will happen (give the projectile a velocity)");
    }
    return warnings;
}

} // namespace hvi::scene
