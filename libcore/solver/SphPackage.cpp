#include "solver/SphPackage.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "io/CheckpointFields.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

namespace hvi::solver {

namespace {

constexpr double kAxisClearance = 0.1; ///< particles are kept at r >= 0.1 h (Spheral's eta_min)

sph::HydroOptions hydroOptionsOf(const scene::Scene& scene,
                                 const std::vector<material::MaterialSpec>& specs) {
    sph::HydroOptions hydro;
    hydro.axisymmetric = scene.geometry == scene::Geometry::Axisymmetric;
    hydro.kernel = sph::kernelTypeFromName(scene.sph.kernel);
    hydro.avAlpha = scene.sph.avAlpha;
    hydro.avBeta = scene.sph.avBeta;
    hydro.artificialStress = scene.sph.artificialStress;
    hydro.spacingOverH = 1.0 / scene.sph.smoothingLengthFactor;
    hydro.keepPairWork = scene.sph.compatibleEnergyUpdate;
    // Solids (an equation of state with a reference state) take the pairwise density rate
    // at a density contrast; a gas keeps the corrected one (sph/SphHydro.hpp, Continuity).
    for (const auto& spec : specs) {
        hydro.pairwiseContinuityAtContrast.push_back(
            std::holds_alternative<material::IdealGas>(spec.eos) ? 0 : 1);
    }
    return hydro;
}

/// Calls fn(i) for every alive particle of the evolving set (the others are at rest, see
/// solver/EvolvingSet.hpp), threaded when the set is large.
template <class Fn>
void forEachEvolving(const ParticleState& points, Fn&& fn) {
    const auto& alive = points.set.alive;
    const auto& evolving = points.evolving.items();
    const std::size_t count = evolving.size();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (alive[i]) {
            fn(i);
        }
    }
}

} // namespace

SphPackage::SphPackage(const scene::Scene& scene, ParticleState& points,
                       const std::vector<sph::BodyFill>& fills,
                       const std::vector<material::MaterialSpec>& specs,
                       std::vector<material::BodyMaterial> bodies, bool skipDormant)
    : m_scene(scene), m_points(points), m_fills(fills), m_specs(specs),
      m_materials(std::move(bodies)), m_hydro(hydroOptionsOf(scene, specs)) {
    m_searchOptions.axisymmetric = scene.geometry == scene::Geometry::Axisymmetric;
    m_searchOptions.kernelSupport = sph::kKernelSupport;
    m_searchOptions.skipDormant = skipDormant;
}

void SphPackage::kick(double dt) {
    const HalfStep::Lanes lanes = m_points.lanes();
    const double half = 0.5 * dt;
    lanes.kick(m_points.evolving.items(), m_points.set.alive, half);
    if (m_hydro.options().keepPairWork) {
        payPairWork(Kick::First, half);
    }
}

void SphPackage::payPairWork(Kick which, double halfDt) {
    auto& ps = m_points.set;
    const std::vector<double>& vzHalf = m_points.half.vz();
    const std::vector<double>& vrHalf = m_points.half.vr();
    std::vector<double>& eHalf = m_points.half.e();
    // Every particle that ever moved, the deleted ones too (a pair of the last evaluation may
    // still name one); the others are at rest, their zeros set once.
    m_meanVz.resize(ps.size(), 0.0);
    m_meanVr.resize(ps.size(), 0.0);
    const auto& evolving = m_points.evolving.items();
    const std::size_t count = evolving.size();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        m_meanVz[i] = 0.5 * (ps.vz[i] + vzHalf[i]);
        m_meanVr[i] = 0.5 * (ps.vr[i] + vrHalf[i]);
    }
    const sph::PairWork& work = m_hydro.pairWork();
    const std::size_t slots = work.slots();
#pragma omp parallel for schedule(static) if (slots > kParallelMinHeavyItems)
    for (std::size_t a = 0; a < slots; ++a) {
        const auto i = static_cast<std::size_t>(work.particle(a));
        if (!ps.alive[i]) {
            continue;
        }
        const double heat = halfDt * work.heating(a, m_meanVz, m_meanVr);
        if (which == Kick::First) {
            eHalf[i] = ps.e[i] + heat;
        } else {
            ps.e[i] = eHalf[i] + heat;
        }
    }
}

void SphPackage::drift(double dt) {
    auto& ps = m_points.set;
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
    const HalfStep::Lanes lanes = m_points.lanes();
    const std::vector<double>& vzHalf = m_points.half.vz();
    std::vector<double>& vrHalf = m_points.half.vr();
    const double half = 0.5 * dt;
    forEachEvolving(m_points, [&](std::size_t i) {
        ps.z[i] += dt * vzHalf[i];
        ps.r[i] += dt * vrHalf[i];
        if (axi) {
            // Reflect at the axis: no particle ever has r < 0 (Spheral's AxisBoundaryRZ).
            const double rMin = kAxisClearance * ps.h[i];
            if (ps.r[i] < rMin) {
                ps.r[i] = std::max(2.0 * rMin - ps.r[i], rMin);
                vrHalf[i] = std::fabs(vrHalf[i]);
            }
        }
    });
    // The end-of-step prediction with the rates of the start (after the reflection, which
    // turns the half-step v_r it starts from).
    lanes.predict(m_points.evolving.items(), ps.alive, half);
}

void SphPackage::evaluate(double /*dt*/) {
    clampSmoothingLengths();
    m_materials.updatePressure(m_points.set, m_points.evolving.items());
    computeRates();
}

void SphPackage::kickAgain(double dt) {
    auto& ps = m_points.set;
    const HalfStep::Lanes lanes = m_points.lanes();
    const auto& bodies = m_materials.bodies();
    const double half = 0.5 * dt;
    lanes.predict(m_points.evolving.items(), ps.alive, half);
    if (m_hydro.options().keepPairWork) {
        payPairWork(Kick::Second, half);
    }
    forEachEvolving(m_points, [&](std::size_t i) {
        // Density stays within sane bounds: an expanding fragment's density falls under the
        // stress cut-off long before it nears zero, and no particle is compressed beyond its
        // equation of state's range (densityCeiling()).
        const auto& body = bodies[static_cast<std::size_t>(ps.body[i])];
        ps.rho[i] = std::clamp(ps.rho[i], 0.1 * body.minDensity, body.maxDensity);
    });
}

void SphPackage::finish(double dt) {
    clampSmoothingLengths();
    m_materials.applyPlasticity(m_points.set, m_points.rates, m_neighbours.active, dt);
    m_materials.updatePressure(m_points.set, m_points.evolving.items());
}

void SphPackage::prepare(double /*dtGuess*/) {
    auto& ps = m_points.set;
    m_points.rates.resize(ps.size(), ps.hasStrength());
    m_points.rates.zero();
    m_materials.updatePressure(ps);
    resetHalfStep();
    computeRates();
}

void SphPackage::computeRates() {
    auto& ps = m_points.set;
    const Stopwatch search;
    sph::updateNeighbourList(ps, m_searchOptions, m_neighbours);
    bookSection("neighbour search", search.seconds());
    const Stopwatch pairs;
    // Only particles that have evolved can hold non-zero rates: the evaluation writes the
    // rates of the active particles, and every active particle joins the evolving set.
    m_points.rates.zero(m_points.evolving.items());
    m_hydro.evaluate(ps, m_neighbours, m_points.rates,
                     m_packAll ? nullptr : &m_points.evolving.items());
    m_packAll = false;
    m_materials.addStressRates(ps, m_neighbours.active, m_points.rates);
    bookSection("pair loops", pairs.seconds());
    m_points.evolving.include(m_neighbours.active);
}

void SphPackage::resetHalfStep() {
    m_points.half.reset(m_points.set);
    m_points.evolving.clear(m_points.set.size());
    m_packAll = true; // the particle arrays may have been replaced (a resume)
}

void SphPackage::clampSmoothingLengths() {
    // At most twice the initial value, which keeps the cells of the neighbour search from
    // growing with an expanding debris cloud; at least the smoothing length of the densest
    // state the equation of state allows (h ~ rho^-1/2 in the (z, r) plane: h0 sqrt(rho0 /
    // rho_max), 0.67 h0 for Al), and never under a quarter of h0. Without the first lower
    // bound, particles squeezed against an FE surface shrank h to the quarter while their
    // density stopped at the ceiling, and set a time step ten times below the others'.
    auto& ps = m_points.set;
    const auto& evolving = m_points.evolving.items();
    const auto& bodies = m_materials.bodies();
    for (std::size_t b = 0; b < m_fills.size(); ++b) {
        const auto& fill = m_fills[b];
        if (fill.count == 0) {
            continue;
        }
        const double hRef = m_scene.sph.smoothingLengthFactor * fill.spacing;
        const double densest = std::sqrt(m_specs[b].referenceDensity / bodies[b].maxDensity);
        const double hLow = std::max(0.25, densest) * hRef, hHigh = 2.0 * hRef;
        // The fill's slice of the (sorted) evolving set: nothing else has moved.
        const auto lo =
            std::lower_bound(evolving.begin(), evolving.end(), static_cast<int32_t>(fill.first));
        const auto hi =
            std::lower_bound(lo, evolving.end(), static_cast<int32_t>(fill.first + fill.count));
        for (auto it = lo; it != hi; ++it) {
            const auto i = static_cast<std::size_t>(*it);
            ps.h[i] = std::clamp(ps.h[i], hLow, hHigh);
        }
    }
}

void SphPackage::save(io::CheckpointState& s) const {
    const auto& ps = m_points.set;
    io::putFields(s, "", ps, sph::kParticleStateFields);
    if (ps.hasStrength()) {
        io::putFields(s, "", ps, sph::kParticleStrengthFields);
    }
    s.ints["body"] = ps.body;
    io::putFlags(s, "alive", ps.alive);
    // The rates of the last step: the next step's first kick uses them, and they belong to
    // the step's predicted state, so they cannot be recomputed from the final one.
    const auto& rt = m_points.rates;
    io::putFields(s, "rate_", rt, sph::kRateFields);
    if (ps.hasStrength()) {
        io::putFields(s, "rate_", rt, sph::kStrengthRateFields);
    }
    if (m_hydro.options().keepPairWork) {
        m_hydro.pairWork().save(s, "pair_work_");
    }
    s.extra["particle_count"] = ps.size();
    s.extra["sph_dt_us"] = m_hydro.stableTimeStep();
    s.extra["sph_dt_particle"] = m_hydro.limitingParticle();
}

void SphPackage::restore(const io::CheckpointState& s) {
    auto& ps = m_points.set;
    const auto count = s.extra.value("particle_count", std::size_t{0});
    if (count != ps.size()) {
        throw InputError("<checkpoint>", "/particle_count",
                         "the checkpoint holds " + std::to_string(count) +
                             " particles, the scene makes " + std::to_string(ps.size()),
                         "a checkpoint of the same scene and resolution");
    }
    io::takeFields(s, "", ps, sph::kParticleStateFields);
    if (ps.hasStrength()) {
        io::takeFields(s, "", ps, sph::kParticleStrengthFields);
    }
    io::takeFlags(s, "alive", ps.alive);
    m_points.rates.resize(ps.size(), ps.hasStrength());
    m_materials.updatePressure(ps);
    // Which particles evolved before the checkpoint is not stored: all of them evolve from
    // here (exact, only slower by the dormant ones until the end of the run).
    resetHalfStep();
    m_points.evolving.fill(ps.size());
    computeRates(); // the neighbour lists; the rates themselves come from the checkpoint
    io::takeFields(s, "rate_", m_points.rates, sph::kRateFields);
    if (ps.hasStrength()) {
        io::takeFields(s, "rate_", m_points.rates, sph::kStrengthRateFields);
    }
    if (m_hydro.options().keepPairWork) {
        m_hydro.pairWork().restore(s, "pair_work_");
    }
    m_hydro.restoreStableTimeStep(io::timeStepOf(s, "sph_dt_us"),
                                  s.extra.at("sph_dt_particle").get<int32_t>());
}

} // namespace hvi::solver
