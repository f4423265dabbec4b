#include "solver/HalfStep.hpp"

namespace hvi::solver {

namespace {

template <class Fn>
void forEachField(bool strength, Fn&& fn) {
    std::size_t f = 0;
    for (const auto& field : sph::kIntegratedFields) {
        fn(f++, field);
    }
    if (strength) {
        for (const auto& field : sph::kIntegratedStrengthFields) {
            fn(f++, field);
        }
    }
}

} // namespace

void HalfStep::reset(const sph::ParticleSet& ps) {
    forEachField(ps.hasStrength(), [&](std::size_t f, const sph::IntegratedField& field) {
        m_half[f] = ps.*field.state;
    });
}

HalfStep::Lanes HalfStep::lanes(sph::ParticleSet& ps, const sph::ParticleRates& rates) {
    Lanes lanes;
    forEachField(ps.hasStrength(), [&](std::size_t f, const sph::IntegratedField& field) {
        lanes.state[f] = (ps.*field.state).data();
        lanes.rate[f] = (rates.*field.rate).data();
        lanes.half[f] = m_half[f].data();
        lanes.count = f + 1;
    });
    return lanes;
}

} // namespace hvi::solver
