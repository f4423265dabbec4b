#include "solver/StateView.hpp"

namespace hvi::solver {

/// The particle fields of the run file, viewed from the solver's arrays. The deviator is
/// interleaved (zz, rr, rz) per particle in the file, so it is copied into `deviator`.
io::ParticleFieldsView particleFieldsOf(const sph::ParticleSet& ps, std::vector<double>& deviator) {
    io::ParticleFieldsView v;
    v.z = ps.z;
    v.r = ps.r;
    v.vz = ps.vz;
    v.vr = ps.vr;
    v.mass = ps.mass;
    v.density = ps.rho;
    v.pressure = ps.p;
    v.internalEnergy = ps.e;
    v.smoothingLength = ps.h;
    v.bodyId = ps.body;
    v.alive = ps.alive;
    if (ps.hasStrength()) {
        deviator.resize(3 * ps.size());
        for (std::size_t i = 0; i < ps.size(); ++i) {
            deviator[3 * i] = ps.szz[i];
            deviator[3 * i + 1] = ps.srr[i];
            deviator[3 * i + 2] = ps.srz[i];
        }
        v.damage = ps.damage;
        v.plasticStrain = ps.plasticStrain;
        v.stressDeviator = deviator;
    }
    return v;
}

/// The FE node and element fields, viewed from the FE package's arrays (the element state
/// arrays that a strengthless scene lacks stay empty and are left out) and the erosion strain
/// of the current shapes (fe.erosionStrain()).
io::FeFieldsView feFieldsOf(const fe::FeSolid& fe, const std::vector<double>& erosionStrain) {
    io::FeFieldsView v;
    const auto& nd = fe.nodes();
    const auto& el = fe.elements();
    v.nodes.z = nd.z;
    v.nodes.r = nd.r;
    v.nodes.vz = nd.vz;
    v.nodes.vr = nd.vr;
    v.nodes.mass = nd.mass;
    v.elements.connectivity = el.connectivity;
    v.elements.alive = el.alive;
    v.elements.damage = el.damage;
    v.elements.plasticStrain = el.plasticStrain;
    v.elements.geometricStrain = erosionStrain;
    v.elements.pressure = el.p;
    v.elements.density = el.rho;
    v.elements.bodyId = el.body;
    return v;
}

} // namespace hvi::solver
