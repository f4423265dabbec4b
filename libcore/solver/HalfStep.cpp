#include "solver/HalfStep.hpp"

#include "io/CheckpointFields.hpp"

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

void HalfStep::Lanes::kick(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                           double halfDt) const {
    kickEach(items, alive, [halfDt](std::size_t) { return halfDt; });
}

void HalfStep::Lanes::predict(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                              double halfDt) const {
    predictEach(items, alive, [halfDt](std::size_t) { return halfDt; });
}

void HalfStep::reset(const sph::ParticleSet& ps) {
    forEachField(ps.hasStrength(), [&](std::size_t f, const sph::IntegratedField& field) {
        m_half[f] = ps.*field.state;
    });
}

void HalfStep::save(io::CheckpointState& s, const std::string& prefix) const {
    for (std::size_t f = 0; f < kFields; ++f) {
        if (!m_half[f].empty()) {
            s.doubles[prefix + std::to_string(f)] = m_half[f];
        }
    }
}

void HalfStep::restore(const io::CheckpointState& s, const std::string& prefix) {
    for (std::size_t f = 0; f < kFields; ++f) {
        if (!m_half[f].empty()) {
            io::takeArray(s, prefix + std::to_string(f), m_half[f]);
        }
    }
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
