#include "sph/ParticleSet.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <array>

namespace hvi::sph {

void ParticleSet::add(double zMm, double rMm, double vzKmS, double vrKmS, double massMg,
                      double hMm, double rhoGcc, double eMJkg, int32_t bodyIndex) {
    z.push_back(zMm);
    r.push_back(rMm);
    vz.push_back(vzKmS);
    vr.push_back(vrKmS);
    mass.push_back(massMg);
    h.push_back(hMm);
    rho.push_back(rhoGcc);
    e.push_back(eMJkg);
    p.push_back(0.0);
    cs.push_back(0.0);
    body.push_back(bodyIndex);
    alive.push_back(1);
    if (hasStrength()) {
        for (const auto& f : kParticleStrengthFields) {
            (this->*f.member).push_back(0.0);
        }
    }
}

void ParticleSet::enableStrength() {
    m_withStrength = true;
    for (const auto& f : kParticleStrengthFields) {
        (this->*f.member).assign(size(), 0.0);
    }
}

void ParticleRates::resize(std::size_t n, bool withStrength) {
    az.resize(n);
    ar.resize(n);
    drho.resize(n);
    de.resize(n);
    dh.resize(n);
    strainRate.resize(n);
    dvzDz.resize(n);
    dvzDr.resize(n);
    dvrDz.resize(n);
    dvrDr.resize(n);
    hoopRate.resize(n);
    if (withStrength) {
        dszz.resize(n);
        dsrr.resize(n);
        dsrz.resize(n);
    }
}

namespace {
std::array<std::vector<double>*, 14> rateFields(ParticleRates& rt) {
    return {&rt.az,    &rt.ar,    &rt.drho,  &rt.de,    &rt.dh,       &rt.dszz,       &rt.dsrr,
            &rt.dsrz,  &rt.dvzDz, &rt.dvzDr, &rt.dvrDz, &rt.dvrDr,    &rt.hoopRate,   &rt.strainRate};
}
} // namespace

void ParticleRates::zero(const std::vector<int32_t>& items) {
    const auto fields = rateFields(*this);
    // One array per thread at a time, as zero(): each thread streams through its own field.
#pragma omp parallel for schedule(static) if (items.size() > kParallelMinItems)
    for (std::size_t f = 0; f < fields.size(); ++f) {
        auto* field = fields[f]->data();
        if (fields[f]->empty()) {
            continue;
        }
        for (const int32_t i : items) {
            field[i] = 0.0;
        }
    }
}

void ParticleRates::zero() {
    const auto fields = rateFields(*this);
    // Every step, over every particle: worth both cores (one array per thread at a time).
#pragma omp parallel for schedule(static) if (az.size() > kParallelMinItems)
    for (std::size_t f = 0; f < fields.size(); ++f) {
        std::fill(fields[f]->begin(), fields[f]->end(), 0.0);
    }
}

} // namespace hvi::sph
