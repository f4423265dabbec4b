#include "scene/PointBudget.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace hvi::scene {

std::vector<double> estimatedPoints(const Scene& scene) {
    std::vector<double> points;
    for (const Body& body : scene.bodies) {
        const Shape& s = body.shape;
        const double area = std::max(0.0, s.boundZMax() - s.boundZMin()) *
                            std::max(0.0, s.boundRMax() - s.boundRMin());
        const double perArea = area / (body.spacing * body.spacing);
        points.push_back(body.discretization == Discretization::Fe ? 2.0 * perArea : perArea);
    }
    return points;
}

double availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        std::istringstream fields(line);
        std::string key;
        double kib = 0.0;
        if (fields >> key >> kib && key == "MemAvailable:") {
            return kib * 1024.0;
        }
    }
    return std::numeric_limits<double>::infinity();
}

void requirePointBudget(const Scene& scene, const std::string& file, double limitBytes) {
    const std::vector<double> points = estimatedPoints(scene);
    if (points.empty()) {
        return;
    }
    double total = 0.0;
    for (double p : points) {
        total += p;
    }
    const double bytes = total * kBytesPerPoint;
    if (!(bytes > limitBytes)) {
        return;
    }
    const auto largest =
        static_cast<std::size_t>(std::max_element(points.begin(), points.end()) - points.begin());
    const Body& body = scene.bodies[largest];
    char text[256];
    std::snprintf(text, sizeof text,
                  "body '%s' alone makes about %.3g points at %.3g mm, the scene %.3g, which would "
                  "take about %.3g GB; %.3g GB is available",
                  body.name.c_str(), points[largest], body.spacing, total, bytes / 1e9,
                  limitBytes / 1e9);
    throw InputError(file, "/bodies/" + std::to_string(largest), text,
                     "a larger particle_spacing_mm or element_size_mm (--resolution-mm), or a "
                     "smaller body or domain");
}

} // namespace hvi::scene
