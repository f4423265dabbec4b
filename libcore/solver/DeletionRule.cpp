#include "solver/DeletionRule.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hvi::solver {

DeletionRule DeletionRule::of(const scene::Scene& scene) {
    DeletionRule rule;
    const double vMax = scene.maxInitialSpeed();
    rule.runawaySpeed =
        vMax > 0.0 ? scene.sph.runawaySpeedFactor * vMax : std::numeric_limits<double>::infinity();
    double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo, projectileSize = 0.0;
    for (const auto& body : scene.bodies) {
        zLo = std::min(zLo, body.shape.boundZMin());
        zHi = std::max(zHi, body.shape.boundZMax());
        projectileSize = std::max(projectileSize, body.shape.boundZMax() - body.shape.boundZMin());
    }
    rule.zMin = scene.domain.zMin.value_or(zLo - 2.0 * projectileSize);
    rule.zMax = scene.domain.zMax.value_or(zHi + 5.0);
    rule.rMax = scene.domain.radius;
    return rule;
}

namespace {

[[noreturn]] void nonFinite(const char* kind, std::size_t index, int32_t body,
                            const scene::Scene& scene, RunClock clock, const char* hint) {
    throw RuntimeFailure("non-finite state at t = " + std::to_string(clock.time) + " us, step " +
                         std::to_string(clock.step) + ", " + kind + " " + std::to_string(index) +
                         " of body '" + scene.bodies[static_cast<std::size_t>(body)].name + "' (" +
                         hint + ")");
}

/// |v|^2 of particle i [km^2/s^2] and whether its state is finite.
struct ParticleCheck {
    double v2 = 0.0;
    bool finite = true;
};

ParticleCheck checkParticle(const sph::ParticleSet& ps, std::size_t i) {
    const double v2 = ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i];
    return {v2, std::isfinite(v2) && std::isfinite(ps.e[i]) && std::isfinite(ps.rho[i]) &&
                    std::isfinite(ps.z[i]) && std::isfinite(ps.r[i])};
}

} // namespace

std::size_t deleteParticles(sph::ParticleSet& ps, const std::vector<int32_t>* items,
                            const DeletionRule& rule, const scene::Scene& scene, RunClock clock,
                            Ledger& ledger) {
    std::size_t deleted = 0;
    const std::size_t n = items ? items->size() : ps.size();
    auto particleOf = [&](std::size_t a) {
        return items ? static_cast<std::size_t>((*items)[a]) : a;
    };
    // Deletions are rare: a threaded scan finds the first item that asks for one (or is not
    // finite), and the booking, whose sums are order-dependent, runs from there in order.
    std::size_t first = n;
#pragma omp parallel for schedule(static) if (n > kParallelMinItems) reduction(min : first)
    for (std::size_t a = 0; a < n; ++a) {
        const std::size_t i = particleOf(a);
        if (!ps.alive[i]) {
            continue;
        }
        const ParticleCheck c = checkParticle(ps, i);
        if (!c.finite || rule.reason(ps.z[i], ps.r[i], c.v2)) {
            first = std::min(first, a);
        }
    }
    for (std::size_t a = first; a < n; ++a) {
        const std::size_t i = particleOf(a);
        if (!ps.alive[i]) {
            continue;
        }
        const ParticleCheck c = checkParticle(ps, i);
        if (!c.finite) {
            nonFinite("particle", i, ps.body[i], scene, clock,
                      "try a smaller cfl or a larger min_density_ratio");
        }
        if (const auto why = rule.reason(ps.z[i], ps.r[i], c.v2)) {
            ps.alive[i] = 0;
            ledger.remove(ps.mass[i], ps.vz[i], 0.5 * c.v2 + ps.e[i], *why);
            ++deleted;
        }
    }
    return deleted;
}

void deleteFreeNodes(fe::NodeSet& nd, const DeletionRule& rule, const scene::Scene& scene,
                     RunClock clock, Ledger& ledger) {
    for (std::size_t k = 0; k < nd.size(); ++k) {
        if (!nd.alive[k]) {
            continue;
        }
        const double v2 = nd.vz[k] * nd.vz[k] + nd.vr[k] * nd.vr[k];
        if (!std::isfinite(v2) || !std::isfinite(nd.z[k]) || !std::isfinite(nd.r[k])) {
            nonFinite("node", k, nd.body[k], scene, clock,
                      "try a smaller cfl or a larger fe.hourglass_coefficient");
        }
        if (nd.elementCount[k] > 0) {
            continue;
        }
        if (const auto why = rule.reason(nd.z[k], nd.r[k], v2)) {
            nd.alive[k] = 0;
            ledger.remove(nd.mass[k], nd.vz[k], 0.5 * v2, *why);
        }
    }
}

} // namespace hvi::solver
