// The particles' half-step state of the kick-drift-kick leapfrog (solver/Simulation.hpp): one
// array per integrated field (sph::kIntegratedFields, and kIntegratedStrengthFields with
// strength), so a field added to those lists is integrated without touching the loops.
//
//   kick:    half := state + dt/2 rate        (first half kick, rates of step n)
//   predict: state := half + dt/2 rate        (the end-of-step prediction, and the second
//                                              half kick with the rates there)
//   hold:    half := state                    (a particle at rest, or one just created)
#pragma once

#include "contact/ContactPoints.hpp"
#include "core/Parallel.hpp"
#include "io/Checkpoint.hpp"
#include "sph/ParticleSet.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hvi::solver {

// contactView() hands contact the first three arrays: they must be vz, vr and e.
static_assert(sph::kIntegratedFields[0].state == &sph::ParticleSet::vz &&
              sph::kIntegratedFields[1].state == &sph::ParticleSet::vr &&
              sph::kIntegratedFields[2].state == &sph::ParticleSet::e);

class HalfStep {
public:
    static constexpr std::size_t kFields =
        sph::kIntegratedFields.size() + sph::kIntegratedStrengthFields.size();

    /// The arrays of one step, as raw pointers (valid until the particle set is resized).
    struct Lanes {
        std::size_t count = 0; ///< fields integrated (without strength, the first five)
        std::array<double*, kFields> state{}, half{};
        std::array<const double*, kFields> rate{};

        void hold(std::size_t i) const {
            for (std::size_t f = 0; f < count; ++f) {
                half[f][i] = state[f][i];
            }
        }

        /// kick and predict (the file comment) for the alive points of an index list, field by
        /// field: three arrays streamed at a time rather than all 24 of a point, since the loops
        /// over the evolving set are bound by memory. Threaded above kParallelMinItems; each value
        /// is computed alike at any thread count.
        void kick(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                  double halfDt) const;
        void predict(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                     double halfDt) const;
        /// The same with a coefficient of each point's own, coef(i) [us], in place of dt/2
        /// (time-step bins, solver/TimeBins.hpp); `shift`: half := half + coef(i) rate.
        template <class Coef>
        void kickEach(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                      Coef&& coef) const {
            stepEach(half.data(), state.data(), items, alive, coef);
        }
        template <class Coef>
        void predictEach(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                         Coef&& coef) const {
            stepEach(state.data(), half.data(), items, alive, coef);
        }
        template <class Coef>
        void shiftEach(std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                       Coef&& coef) const {
            stepEach(half.data(), half.data(), items, alive, coef);
        }

    private:
        /// to[i] := from[i] + coef(i) rate[i] for the alive points of `items`, field by field,
        /// in one parallel region (the fields' loops need no barrier between them).
        template <class Coef>
        void stepEach(double* const* to, const double* const* from,
                      std::span<const int32_t> items, const std::vector<uint8_t>& alive,
                      Coef& coef) const {
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
                        out[i] = in[i] + coef(i) * d[i];
                    }
                }
            }
        }
    };

    /// Every half-step array := the particles' state (the start of a run, or a resume).
    void reset(const sph::ParticleSet& ps);
    /// The half-step arrays into a checkpoint under `prefix`, and back (time-step bins: a
    /// particle in the course of its interval keeps its half step across a resume).
    void save(io::CheckpointState& state, const std::string& prefix) const;
    void restore(const io::CheckpointState& state, const std::string& prefix);
    Lanes lanes(sph::ParticleSet& ps, const sph::ParticleRates& rates);

    std::vector<double>& vz() { return m_half[0]; }
    std::vector<double>& vr() { return m_half[1]; }
    std::vector<double>& e() { return m_half[2]; }
    /// The half-step velocities and energy contact constrains.
    contact::ParticleHalfStep contactView() { return {&m_half[0], &m_half[1], &m_half[2]}; }

private:
    std::array<std::vector<double>, kFields> m_half;
};

} // namespace hvi::solver
