#include "solver/HalfStep.hpp"

#include "core/Parallel.hpp"

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

/// to[i] := from[i] + halfDt * rate[i] for the alive points of `items`, field by field, in
/// one parallel region (the fields' loops need no barrier between them).
void stepFields(std::size_t count, double* const* to, const double* const* from,
                const double* const* rate, std::span<const int32_t> items,
                const std::vector<uint8_t>& alive, double halfDt) {
    const std::size_t n = items.size();
    const int32_t* idx = items.data();
    const uint8_t* live = alive.data();
#pragma omp parallel if (n > kParallelMinItems)
    for (std::size_t f = 0; f < count; ++f) {
        double* out = to[f];
        const double* in = from[f];
        const double* d = rate[f];
#pragma omp for schedule(static) nowait
        for (std::size_t a = 0; a < n; ++a) {
            const auto i = static_cast<std::size_t>(idx[a]);
            if (live[i]) {
                out[i] = in[i] + halfDt * d[i];
            }
        }
    }
}

} // namespace

void HalfStep::Lanes::kick(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                           double halfDt) const {
    stepFields(count, half.data(), state.data(), rate.data(), items, alive, halfDt);
}

void HalfStep::Lanes::predict(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                              double halfDt) const {
    stepFields(count, state.data(), half.data(), rate.data(), items, alive, halfDt);
}

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
