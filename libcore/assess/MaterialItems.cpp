#include "assess/MaterialItems.hpp"

#include "sph/ParticleSet.hpp"

#include <cstddef>

namespace hvi::assess {

namespace {

/// Centroids of the elements of `fe`: mean of the 4 node positions.
void elementCentroids(const io::FeFields& fe, std::vector<double>& z, std::vector<double>& r) {
    const auto& c = fe.elements.connectivity;
    const std::size_t ne = c.size() / 4;
    z.assign(ne, 0.0);
    r.assign(ne, 0.0);
    for (std::size_t e = 0; e < ne; ++e) {
        for (int k = 0; k < 4; ++k) {
            const auto n = static_cast<std::size_t>(c[4 * e + static_cast<std::size_t>(k)]);
            z[e] += 0.25 * fe.nodes.z[n];
            r[e] += 0.25 * fe.nodes.r[n];
        }
    }
}

} // namespace

MaterialItems materialItems(const io::Snapshot& snapshot, const io::Snapshot& first) {
    MaterialItems items;
    items.timeUs = snapshot.info.timeUs;
    const auto& p = snapshot.particles;
    const std::size_t np = p.z.size();
    const bool particlesMatch = first.particles.z.size() == np;
    const auto& reference = particlesMatch ? first.particles : p;
    for (std::size_t i = 0; i < np; ++i) {
        if (sph::isUnusedSlot(p.alive[i], p.mass[i])) {
            continue;
        }
        items.z.push_back(p.z[i]);
        items.r.push_back(p.r[i]);
        items.z0.push_back(reference.z[i]);
        items.r0.push_back(reference.r[i]);
        items.vz.push_back(p.vz[i]);
        items.vr.push_back(p.vr[i]);
        items.mass.push_back(p.mass[i]);
        items.density.push_back(p.density[i]);
        items.damage.push_back(p.damage.empty() ? 0.0 : p.damage[i]);
        items.body.push_back(p.bodyId[i]);
        items.alive.push_back(p.alive[i]);
    }
    items.particleCount = items.z.size();
    bool elementsMatch = true;

    if (snapshot.fe) {
        const auto& fe = *snapshot.fe;
        const auto& el = fe.elements;
        const std::size_t ne = el.connectivity.size() / 4;
        std::vector<double> ez, er;
        elementCentroids(fe, ez, er);
        std::vector<int> uses(fe.nodes.z.size(), 0);
        for (auto n : el.connectivity) {
            ++uses[static_cast<std::size_t>(n)];
        }
        std::vector<double> ez0 = ez, er0 = er;
        elementsMatch = first.fe && first.fe->elements.connectivity == el.connectivity &&
                        first.fe->nodes.z.size() == fe.nodes.z.size();
        if (elementsMatch) {
            elementCentroids(*first.fe, ez0, er0);
        }
        for (std::size_t e = 0; e < ne; ++e) {
            double vz = 0.0, vr = 0.0, m = 0.0;
            for (int k = 0; k < 4; ++k) {
                const auto n =
                    static_cast<std::size_t>(el.connectivity[4 * e + static_cast<std::size_t>(k)]);
                vz += 0.25 * fe.nodes.vz[n];
                vr += 0.25 * fe.nodes.vr[n];
                m += fe.nodes.mass[n] / uses[n];
            }
            items.z.push_back(ez[e]);
            items.r.push_back(er[e]);
            items.z0.push_back(ez0[e]);
            items.r0.push_back(er0[e]);
            items.vz.push_back(vz);
            items.vr.push_back(vr);
            items.mass.push_back(m);
            items.density.push_back(el.density[e]);
            items.damage.push_back(el.damage.empty() ? 0.0 : el.damage[e]);
            items.body.push_back(el.bodyId[e]);
            items.alive.push_back(el.alive[e]);
        }
    }
    items.hasReference = particlesMatch && elementsMatch;
    return items;
}

} // namespace hvi::assess
