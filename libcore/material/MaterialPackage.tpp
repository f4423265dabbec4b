// The template definitions of MaterialPackage (material/MaterialPackage.hpp), included by
// the files that instantiate them for their point sets: sph/ParticleMaterial.cpp and
// fe/ElementMaterial.cpp. This folder knows no point set.
#pragma once

#include "material/MaterialPackage.hpp"

#include "core/Lanes.hpp"
#include "core/Parallel.hpp"
#include "material/strength/JaumannRate.hpp"
#include "material/strength/RadialReturn.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace hvi::material {

using material::StressDeviator;

namespace detail {

inline double shearModulusOf(const BodyMaterial& body) {
    return body.strength ? body.spec->shearModulus : 0.0;
}

/// p and cs of point i, one at a time (any EOS).
template <class Points, class Eos>
void pressureAt(Points& ps, std::size_t i, const BodyMaterial& body, const Eos& eos) {
    // Below the cut-off density a point is fragmented: it carries no tension. Where the EOS
    // describes hot expanded states their pressure stays (it falls to zero with the density,
    // so nothing jumps at the cut-off); otherwise the point carries no stress and keeps the
    // sound speed of the cut-off density.
    const bool expanded = ps.rho[i] < body.minDensity;
    const bool keepsGasPressure = eos.describesExpandedStates();
    const double rho = keepsGasPressure ? ps.rho[i] : std::max(ps.rho[i], body.minDensity);
    const material::EosState st = eos.evaluate(rho, ps.e[i]);
    double p = st.pressure;
    double c2 = st.soundSpeedSquared;
    const bool failed = ps.hasStrength() && ps.damage[i] >= 1.0;
    if (expanded) {
        p = keepsGasPressure ? std::max(p, 0.0) : 0.0;
    } else if (failed && p < 0.0) {
        p = 0.0; // failed material takes no tension
    }
    // A point below the cut-off carries no deviator (applyPlasticity): with a gas pressure
    // its waves are the gas's alone.
    const double shear = shearModulusOf(body);
    if (shear > 0.0 && !failed && !(expanded && keepsGasPressure)) {
        c2 += (4.0 / 3.0) * shear / rho;
    }
    ps.p[i] = p;
    ps.cs[i] = std::sqrt(std::max(c2, 0.0));
}

#if HVI_HAVE_LANES4
/// An EOS that evaluates four points at once where it describes no expanded state.
template <class Eos>
concept LaneEos = requires(const Eos& eos, Lanes4 x) { eos.evaluateSolid(x, x); };

/// The four values x[at[0..3]] as one vector, built in registers (a vector loaded from four
/// scalar stores just made cannot be forwarded from them and waits for them to retire).
inline Lanes4 gather4(const double* x, const std::size_t* at) {
    return Lanes4(_mm256_set_pd(x[at[3]], x[at[2]], x[at[1]], x[at[0]]));
}

/// pressureAt for the points of `index(k)`, k in [first, last), four at a time: the EOS, its
/// cut-off rules (as lane masks) and the square root in AVX lanes (the same IEEE operations
/// as pressureAt, so the same bits). For an EOS without expanded states.
template <class Points, class Eos, class Index>
void pressureOfLanes(Points& ps, const BodyMaterial& body, const Eos& eos, std::ptrdiff_t first,
                     std::ptrdiff_t last, const Index& index) {
    const std::ptrdiff_t blocks = (last - first) / 4;
    const double shear = shearModulusOf(body);
    const Lanes4 fourThirdsShear((4.0 / 3.0) * shear);
    const Lanes4 cutOff(body.minDensity);
    const bool hasS = ps.hasStrength();
#pragma omp parallel for schedule(static) if (last - first > static_cast<std::ptrdiff_t>(kParallelMinItems))
    for (std::ptrdiff_t blk = 0; blk < blocks; ++blk) {
        std::size_t at[4];
        for (std::size_t j = 0; j < 4; ++j) {
            at[j] = index(first + 4 * blk + static_cast<std::ptrdiff_t>(j));
        }
        const Lanes4 rhoRaw = gather4(ps.rho.data(), at);
        const Lanes4 rho = maxOf(rhoRaw, cutOff); // std::max(rho, cut-off), as pressureAt
        const EosStateOf<Lanes4> st = eos.evaluateSolid(rho, gather4(ps.e.data(), at));
        // pressureAt's rules without a gas pressure: no pressure below the cut-off, no tension
        // in failed material, the shear wave where the material is intact.
        const __m256d zero = _mm256_setzero_pd();
        const __m256d failed =
            hasS ? _mm256_cmp_pd(gather4(ps.damage.data(), at).v, _mm256_set1_pd(1.0), _CMP_GE_OQ)
                 : zero;
        const __m256d expanded = _mm256_cmp_pd(rhoRaw.v, cutOff.v, _CMP_LT_OQ);
        const __m256d tension = _mm256_cmp_pd(st.pressure.v, zero, _CMP_LT_OQ);
        const Lanes4 p(_mm256_blendv_pd(st.pressure.v, zero,
                                        _mm256_or_pd(expanded, _mm256_and_pd(failed, tension))));
        Lanes4 c2 = st.soundSpeedSquared;
        if (shear > 0.0) {
            c2 = Lanes4(_mm256_blendv_pd((c2 + fourThirdsShear / rho).v, c2.v, failed));
        }
        alignas(32) double pOut[4], csOut[4];
        _mm256_store_pd(pOut, p.v);
        _mm256_store_pd(csOut, sqrtOf(maxOf(c2, Lanes4(0.0))).v);
        for (std::size_t j = 0; j < 4; ++j) {
            if (ps.alive[at[j]]) {
                ps.p[at[j]] = pOut[j];
                ps.cs[at[j]] = csOut[j];
            }
        }
    }
    for (std::ptrdiff_t k = first + 4 * blocks; k < last; ++k) {
        const std::size_t i = index(k);
        if (ps.alive[i]) {
            pressureAt(ps, i, body, eos);
        }
    }
}
#endif

/// p and cs of points [first, last) of `items` (or of the index range itself when `items` is
/// null) for one body, with its EOS chosen once.
template <class Points, class Eos>
void pressureOf(Points& ps, const BodyMaterial& body, const Eos& eos, std::ptrdiff_t first,
                std::ptrdiff_t last, const int32_t* items) {
    const auto index = [items](std::ptrdiff_t k) {
        return items ? static_cast<std::size_t>(items[k]) : static_cast<std::size_t>(k);
    };
#if HVI_HAVE_LANES4
    if constexpr (LaneEos<Eos>) {
        if (!eos.describesExpandedStates()) {
            pressureOfLanes(ps, body, eos, first, last, index);
            return;
        }
    }
#endif
    parallelFor(static_cast<std::size_t>(last - first), [&](std::size_t slot) {
        const std::size_t i = index(first + static_cast<std::ptrdiff_t>(slot));
        if (ps.alive[i]) {
            pressureAt(ps, i, body, eos);
        }
    });
}

} // namespace detail

template <class Points>
void MaterialPackage::updatePressure(Points& ps) const {
    for (const auto& body : m_bodies) {
        std::visit(
            [&](const auto& eos) {
                detail::pressureOf(ps, body, eos, static_cast<std::ptrdiff_t>(body.first),
                                   static_cast<std::ptrdiff_t>(body.first + body.count), nullptr);
            },
            body.spec->eos);
    }
}

template <class Points>
void MaterialPackage::updatePressure(Points& ps, std::span<const int32_t> items) const {
    for (const auto& body : m_bodies) {
        if (body.count == 0) {
            continue;
        }
        // The body's slice of the sorted list.
        const auto lo =
            std::lower_bound(items.begin(), items.end(), static_cast<int32_t>(body.first));
        const auto hi =
            std::lower_bound(lo, items.end(), static_cast<int32_t>(body.first + body.count));
        std::visit(
            [&](const auto& eos) {
                detail::pressureOf(ps, body, eos, lo - items.begin(), hi - items.begin(),
                                   items.data());
            },
            body.spec->eos);
    }
}

template <class Points, class Rates>
void MaterialPackage::addStressRates(const Points& ps, std::span<const int32_t> active,
                                     Rates& rates) const {
    if (!ps.hasStrength()) {
        return;
    }
    parallelFor(active.size(), [&](std::size_t a) {
        const int32_t i = active[a];
        const BodyMaterial& body = m_bodies[static_cast<std::size_t>(ps.body[i])];
        if (!body.strength || ps.damage[i] >= 1.0 || ps.rho[i] < body.minDensity) {
            rates.dszz[i] = rates.dsrr[i] = rates.dsrz[i] = 0.0;
            return;
        }
        const StressDeviator s{ps.szz[i], ps.srr[i], ps.srz[i]};
        const material::VelocityGradient2D l{rates.dvzDz[i], rates.dvzDr[i], rates.dvrDz[i],
                                             rates.dvrDr[i]};
        const StressDeviator ds =
            material::jaumannRate(s, l, rates.hoopRate[i], body.spec->shearModulus);
        rates.dszz[i] = ds.zz;
        rates.dsrr[i] = ds.rr;
        rates.dsrz[i] = ds.rz;
    });
}

template <class Points, class Rates>
void MaterialPackage::applyPlasticity(Points& ps, const Rates& rates,
                                      std::span<const int32_t> active, double dt) const {
    plasticity(ps, rates, active, [dt](std::size_t) { return dt; });
}

template <class Points, class Rates>
void MaterialPackage::applyPlasticity(Points& ps, const Rates& rates,
                                      std::span<const int32_t> active,
                                      const std::vector<double>& steps) const {
    plasticity(ps, rates, active, [&steps](std::size_t i) { return steps[i]; });
}

template <class Points, class Rates, class StepOf>
void MaterialPackage::plasticity(Points& ps, const Rates& rates, std::span<const int32_t> active,
                                 StepOf&& stepOf) const {
    if (!ps.hasStrength()) {
        return;
    }
    parallelFor(active.size(), [&](std::size_t a) {
        const int32_t i = active[a];
        const BodyMaterial& body = m_bodies[static_cast<std::size_t>(ps.body[i])];
        if (!body.strength) {
            return;
        }
        StressDeviator s{ps.szz[i], ps.srr[i], ps.srz[i]};
        if (ps.damage[i] >= 1.0 || ps.rho[i] < body.minDensity) {
            s = StressDeviator{};
        } else {
            const material::MaterialSpec& spec = *body.spec;
            const double tStar = spec.thermal ? spec.thermal->homologousFromEnergy(ps.e[i]) : 0.0;
            const double rate = rates.strainRate[i];
            const double dEps = std::visit(
                [&](const auto& model) -> double {
                    using M = std::decay_t<decltype(model)>;
                    if constexpr (std::is_same_v<M, material::NoStrength>) {
                        return material::radialReturn(s, 0.0, spec.shearModulus);
                    } else {
                        // Under the flow stress's floor the point is elastic, which is what
                        // the radial return would find: the flow stress is not needed.
                        const double floor = model.flowStressFloor(tStar);
                        if (floor > 0.0 && ps.plasticStrain[i] >= 0.0 && rate >= 0.0 &&
                            s.vonMises() <= floor) {
                            return 0.0;
                        }
                        return material::radialReturn(
                            s, model.flowStress(ps.plasticStrain[i], rate, tStar),
                            spec.shearModulus);
                    }
                },
                spec.strength);
            if (dEps > 0.0) {
                std::visit(
                    [&](const auto& model) {
                        using F = std::decay_t<decltype(model)>;
                        if constexpr (!std::is_same_v<F, material::NoFailure>) {
                            ps.damage[i] = model.damageAfter(ps.damage[i], ps.tensionOnset[i],
                                                             ps.plasticStrain[i], dEps, ps.p[i],
                                                             s.vonMises(), rate, tStar);
                        }
                    },
                    spec.failure);
            }
            ps.plasticStrain[i] += dEps;
            if (spec.spall) {
                ps.damage[i] = spec.spall->damageAfter(ps.damage[i], s, ps.p[i], rate,
                                                    stepOf(static_cast<std::size_t>(i)));
            }
            if (ps.damage[i] >= 1.0) {
                s = StressDeviator{};
            }
        }
        ps.szz[i] = s.zz;
        ps.srr[i] = s.rr;
        ps.srz[i] = s.rz;
    });
}

} // namespace hvi::material
