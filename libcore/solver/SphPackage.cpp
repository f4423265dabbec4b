#include "solver/SphPackage.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "io/CheckpointFields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
      m_materials(std::move(bodies)), m_hydro(hydroOptionsOf(scene, specs)),
      m_binned(scene.sph.timeBins) {
    m_searchOptions.axisymmetric = scene.geometry == scene::Geometry::Axisymmetric;
    m_searchOptions.kernelSupport = sph::kKernelSupport;
    m_searchOptions.skipDormant = skipDormant;
}

void SphPackage::kick(double dt) {
    const HalfStep::Lanes lanes = m_points.lanes();
    if (m_binned) {
        m_bins.beginStep(m_points.evolving.items(), m_points.set.alive, m_scene.run.cfl, dt);
        lanes.kickEach(m_bins.opening(), m_points.set.alive,
                       [this](std::size_t i) { return m_bins.openingHalf(i); });
        return;
    }
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
    if (m_binned) {
        // An interval that ends otherwise than planned first takes its half step to its
        // actual midpoint (solver/TimeBins.hpp).
        lanes.shiftEach(m_bins.shortened(), ps.alive,
                        [this](std::size_t i) { return m_bins.closingCorrection(i); });
        lanes.predictEach(m_points.evolving.items(), ps.alive,
                          [this](std::size_t i) { return m_bins.predictionOffset(i); });
        return;
    }
    lanes.predict(m_points.evolving.items(), ps.alive, half);
}

void SphPackage::evaluate(double dt) {
    clampSmoothingLengths();
    m_materials.updatePressure(m_points.set, m_points.evolving.items());
    computeRates(dt);
}

void SphPackage::kickAgain(double dt) {
    auto& ps = m_points.set;
    const HalfStep::Lanes lanes = m_points.lanes();
    const auto& bodies = m_materials.bodies();
    const double half = 0.5 * dt;
    if (m_binned) {
        lanes.predictEach(m_evaluated, ps.alive,
                          [this](std::size_t i) { return m_bins.closingHalf(i); });
    } else {
        lanes.predict(m_points.evolving.items(), ps.alive, half);
    }
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
    if (m_binned) {
        m_materials.applyPlasticity(m_points.set, m_points.rates, m_evaluatedActive,
                                    m_bins.intervals());
    } else {
        m_materials.applyPlasticity(m_points.set, m_points.rates, m_neighbours.active, dt);
    }
    m_materials.updatePressure(m_points.set, m_points.evolving.items());
    if (m_binned) {
        m_bins.endStep(m_points.evolving.items(), m_points.set.alive, dt);
    }
}

void SphPackage::prepare(double dtGuess) {
    auto& ps = m_points.set;
    m_points.rates.resize(ps.size(), ps.hasStrength());
    m_points.rates.zero();
    m_materials.updatePressure(ps);
    resetHalfStep();
    computeRates(dtGuess);
}

void SphPackage::computeRates(double dt) {
    auto& ps = m_points.set;
    const Stopwatch search;
    sph::updateNeighbourList(ps, m_searchOptions, m_neighbours);
    bookSection("neighbour search", search.seconds());
    const Stopwatch pairs;
    if (m_binned) {
        computeBinnedRates(dt);
    } else {
        // Only particles that have evolved can hold non-zero rates: the evaluation writes the
        // rates of the active particles, and every active particle joins the evolving set.
        m_points.rates.zero(m_points.evolving.items());
        m_hydro.evaluate(ps, m_neighbours, m_points.rates,
                         m_packAll ? nullptr : &m_points.evolving.items());
        m_materials.addStressRates(ps, m_neighbours.active, m_points.rates);
    }
    m_packAll = false;
    bookSection("pair loops", pairs.seconds());
    m_points.evolving.include(m_neighbours.active);
}

void SphPackage::computeBinnedRates(double dt) {
    auto& ps = m_points.set;
    const auto& active = m_neighbours.active;
    // The active particles whose interval ends (or that evolve from this step on), and every
    // particle whose interval ends: those take new rates, the others keep theirs.
    m_dueSlots.clear();
    m_evaluatedActive.clear();
    m_evaluated = m_bins.closing();
    for (std::size_t a = 0; a < active.size(); ++a) {
        const auto i = static_cast<std::size_t>(active[a]);
        if (!m_bins.evaluated(i)) {
            continue;
        }
        m_dueSlots.push_back(static_cast<int32_t>(a));
        m_evaluatedActive.push_back(active[a]);
        if (!m_bins.begun(i)) {
            // New to the evolving set in this step (set moving by contact, or woken).
            m_bins.admit(i, dt);
            m_evaluated.push_back(active[a]);
        }
    }
    m_points.rates.zero(m_evaluated);
    m_hydro.evaluate(ps, m_neighbours, m_points.rates,
                     m_packAll ? nullptr : &m_points.evolving.items(), &m_dueSlots);
    m_materials.addStressRates(ps, m_evaluatedActive, m_points.rates);
    // Each evaluated particle's vote, and its bin's bound on its neighbours' (the wake-up).
    const double cfl = m_scene.run.cfl;
    const std::vector<double>& steps = m_hydro.particleSteps();
    const auto& nl = m_neighbours;
    parallelFor(m_dueSlots.size(), [&](std::size_t s) {
        const auto a = static_cast<std::size_t>(m_dueSlots[s]);
        const auto i = static_cast<std::size_t>(active[a]);
        m_bins.setVote(i, steps[a]);
        const int level = TimeBins::levelFor(cfl, steps[a], dt, TimeBins::kMaxLevel);
        if (level + TimeBins::kWakeLevels >= TimeBins::kMaxLevel) {
            return; // no neighbour's bin can be beyond its bound
        }
        // Its neighbours inside the support only: the list reaches a skin further, by an
        // amount that depends on when it was built (a resumed run rebuilds it).
        const int32_t row = nl.row[a];
        for (int64_t k = nl.offset[row]; k < nl.offset[row + 1]; ++k) {
            const auto x = static_cast<std::size_t>(nl.neighbours[k]);
            const auto j = static_cast<std::size_t>(nl.source[x]);
            const double dz = ps.z[i] - ps.z[j], dr = ps.r[i] - nl.sign[x] * ps.r[j];
            const double support = sph::kKernelSupport * 0.5 * (ps.h[i] + ps.h[j]);
            if (dz * dz + dr * dr < support * support) {
                m_bins.wakeNeighbour(j, level);
            }
        }
    });
    // The scene's step: the smallest vote of the active particles, the stale ones of those in
    // the course of an interval included (ties to the lowest index, at any thread count).
    m_binVote = std::numeric_limits<double>::infinity();
    m_binLimiter = -1;
    for (const int32_t i : active) {
        const double v = m_bins.vote(static_cast<std::size_t>(i));
        if (v < m_binVote) {
            m_binVote = v;
            m_binLimiter = i;
        }
    }
}

void SphPackage::resetHalfStep() {
    m_points.half.reset(m_points.set);
    m_points.evolving.clear(m_points.set.size());
    if (m_binned) {
        m_bins.reset(m_points.set.size());
    }
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
    if (m_binned) {
        // Particles in the course of an interval: their half step and where they stand in it.
        m_points.half.save(s, "half_");
        m_bins.save(s, "bins_");
    }
    s.extra["particle_count"] = ps.size();
    s.extra["sph_dt_us"] = stableTimeStep();
    s.extra["sph_dt_particle"] = limitingParticle();
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
    computeRates(0.0); // the neighbour lists; the rates themselves come from the checkpoint
    io::takeFields(s, "rate_", m_points.rates, sph::kRateFields);
    if (ps.hasStrength()) {
        io::takeFields(s, "rate_", m_points.rates, sph::kStrengthRateFields);
    }
    if (m_hydro.options().keepPairWork) {
        m_hydro.pairWork().restore(s, "pair_work_");
    }
    if (m_binned) {
        m_points.half.restore(s, "half_");
        m_bins.restore(s, "bins_");
        m_binVote = io::timeStepOf(s, "sph_dt_us");
        m_binLimiter = s.extra.at("sph_dt_particle").get<int32_t>();
    }
    m_hydro.restoreStableTimeStep(io::timeStepOf(s, "sph_dt_us"),
                                  s.extra.at("sph_dt_particle").get<int32_t>());
}

} // namespace hvi::solver
