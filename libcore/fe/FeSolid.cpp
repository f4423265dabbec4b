#include "fe/FeSolid.hpp"

#include "core/Parallel.hpp"
#include "core/Units.hpp"
#include "fe/QuadKinematics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <omp.h>

namespace hvi::fe {

namespace {

QuadState gather(const NodeSet& nodes, const ElementSet& elements, std::size_t i) {
    QuadState q;
    for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(elements.node(i, a));
        const auto k = static_cast<std::size_t>(a);
        q.z[k] = nodes.z[n];
        q.r[k] = nodes.r[n];
        q.vz[k] = nodes.vz[n];
        q.vr[k] = nodes.vr[n];
    }
    return q;
}

double sweptVolume(const QuadGeometry& g, bool axisymmetric) {
    return axisymmetric ? 2.0 * units::kPi * g.centroidR * g.area : g.area;
}

/// Every corner turns the same way (counter-clockwise): a quadrilateral that folded over at
/// a corner has no valid mapping from the reference square, whatever its total area.
bool convex(const QuadState& q) {
    for (std::size_t a = 0; a < 4; ++a) {
        const std::size_t next = (a + 1) % 4, prev = (a + 3) % 4;
        const double cross = (q.z[next] - q.z[a]) * (q.r[prev] - q.r[a]) -
                             (q.r[next] - q.r[a]) * (q.z[prev] - q.z[a]);
        if (!(cross > 0.0)) {
            return false;
        }
    }
    return true;
}

/// The viscous hourglass damping rate c_hg = kappa rho c V / (4 sqrt(A)) [mg/us]; one formula
/// for the start of a run and every assembly, so a woken element's first rate is the one
/// evaluating it all along would have given, to the bit.
double hourglassDamping(double kappa, double rho, double soundSpeed, double volume, double area) {
    return 0.25 * kappa * rho * soundSpeed * volume / std::sqrt(area);
}

} // namespace

FeSolid::FeSolid(FeOptions options, NodeSet nodes, ElementSet elements,
                 std::vector<double> erosionFactor)
    : m_options(options), m_nodes(std::move(nodes)), m_elements(std::move(elements)),
      m_erosionFactor(std::move(erosionFactor)) {
    const std::size_t ne = m_elements.size();
    const std::size_t nn = m_nodes.size();
    m_rates.resize(ne);
    m_elementForce.assign(8 * ne, 0.0);
    m_cornerWeight.assign(ne, 0.0);
    m_hourglassRate.assign(ne, 0.0);
    m_ownStep.assign(ne, kNoLimit);
    m_volumetricRate.assign(ne, 0.0);
    m_volume.assign(ne, 0.0);
    m_erode.assign(ne, 0);
    // Slot = 4 * element + corner, so the gather knows which corner force to take.
    m_nodeCorners = NodeCorners::of(m_elements, nn, false);
    for (std::size_t i = 0; i < ne; ++i) {
        const QuadGeometry g = quadGeometry(gather(m_nodes, m_elements, i));
        m_volume[i] = sweptVolume(g, m_options.axisymmetric);
    }
    m_referenceVolume = m_volume;
    m_referenceDensity = m_elements.rho;
    m_referenceShape.resize(ne);
    for (std::size_t i = 0; i < ne; ++i) {
        m_referenceShape[i] = referenceShape(gather(m_nodes, m_elements, i));
    }
    for (const double factor : m_erosionFactor) {
        m_strainRatioLimit.push_back(stretchRatioLimit(factor));
    }
}

void FeSolid::selectEvaluated() {
    // An element whose nodes are all at rest and whose material is in its reference state
    // (no pressure, no viscosity, no deviator) has zero strain rate and exerts no force:
    // skipping it is exact. Its material leaves the reference state only through an update,
    // which needs a moving node first; so an element wakes when one of its nodes first moves,
    // and stays awake (evaluating an element that came to rest again is exact too). The list
    // changes only when elements wake or erode, so it is kept and merged, not rebuilt.
    const auto& el = m_elements;
    const auto& nd = m_nodes;
    const std::size_t ne = el.size();
    m_woken.clear();
    if (m_fullSelection) {
        // A start or a resume: the state decides.
        m_fullSelection = false;
        m_elementAwake.assign(ne, 0);
        m_nodeAwake.assign(nd.size(), 0);
        m_nodeMarked.assign(nd.size(), 0);
        m_gatherNodes.clear();
        m_evaluated.clear();
        const bool strength = el.hasStrength();
        for (std::size_t i = 0; i < ne; ++i) {
            m_elementAwake[i] =
                !m_options.skipDormant || el.p[i] != 0.0 || el.q[i] != 0.0 ||
                (strength && (el.szz[i] != 0.0 || el.srr[i] != 0.0 || el.srz[i] != 0.0));
            if (m_elementAwake[i]) {
                m_woken.push_back(static_cast<int32_t>(i));
            }
        }
    }
    for (std::size_t n = 0; n < nd.size(); ++n) {
        if (m_nodeAwake[n] || (nd.vz[n] == 0.0 && nd.vr[n] == 0.0)) {
            continue;
        }
        m_nodeAwake[n] = 1;
        for (int64_t k = m_nodeCorners.offset[n]; k < m_nodeCorners.offset[n + 1]; ++k) {
            const auto e = m_nodeCorners.corners[static_cast<std::size_t>(k)] / 4;
            if (!m_elementAwake[static_cast<std::size_t>(e)]) {
                m_elementAwake[static_cast<std::size_t>(e)] = 1;
                m_woken.push_back(e);
            }
        }
    }
    if (m_woken.empty() && !m_erodedSinceSelection) {
        return;
    }
    std::sort(m_woken.begin(), m_woken.end());
    // Merge the alive elements of the kept list and the woken ones (both ascending).
    m_merged.clear();
    std::size_t k = 0;
    for (const int32_t e : m_evaluated) {
        for (; k < m_woken.size() && m_woken[k] < e; ++k) {
            admit(m_woken[k]);
        }
        if (el.alive[static_cast<std::size_t>(e)]) {
            m_merged.push_back(e);
        }
    }
    for (; k < m_woken.size(); ++k) {
        admit(m_woken[k]);
    }
    m_evaluated.swap(m_merged);
    // The gathered nodes are those of the listed elements: an element that erodes writes
    // zero corner forces in that same update, so a node whose elements have all left the
    // list already holds its final (zero) force. After an erosion the set is rebuilt, so it
    // does not keep growing with the eroded debris of a perforation.
    if (m_erodedSinceSelection) {
        m_erodedSinceSelection = false;
        for (const int32_t n : m_gatherNodes) {
            m_nodeMarked[static_cast<std::size_t>(n)] = 0;
        }
        m_gatherNodes.clear();
        for (const int32_t e : m_evaluated) {
            gatherNodesOf(static_cast<std::size_t>(e));
        }
    } else {
        for (const int32_t e : m_woken) {
            if (el.alive[static_cast<std::size_t>(e)]) {
                gatherNodesOf(static_cast<std::size_t>(e));
            }
        }
    }
}

void FeSolid::admit(int32_t element) {
    if (m_elements.alive[static_cast<std::size_t>(element)]) {
        m_merged.push_back(element);
    }
}

void FeSolid::gatherNodesOf(std::size_t element) {
    for (int a = 0; a < 4; ++a) {
        const int32_t n = m_elements.node(element, a);
        if (!m_nodeMarked[static_cast<std::size_t>(n)]) {
            m_nodeMarked[static_cast<std::size_t>(n)] = 1;
            m_gatherNodes.push_back(n);
        }
    }
}

/// The one step of the global time loop, for every element alike.
struct FeSolid::SameStep {
    double dt;
    double of(std::size_t /*element*/) const { return dt; }
    void meanVelocities(std::size_t /*element*/, QuadState& /*corners*/) const {}
    void plasticity(const material::MaterialPackage& materials, ElementSet& el,
                    const ElementRates& rates, std::span<const int32_t> tile) const {
        materials.applyPlasticity(el, rates, tile, dt);
    }
};

/// Each element's own interval (time-step bins): over it, the corners moved from their
/// start to their current positions, so the strain increment is that of their mean
/// velocities at the interval's mid-geometry (the central difference over the interval).
struct FeSolid::OwnInterval {
    const Intervals& steps;
    double of(std::size_t i) const { return (*steps.interval)[i]; }
    void meanVelocities(std::size_t i, QuadState& q) const {
        const double interval = of(i);
        if (interval == steps.baseStep) {
            return; // one base step: the drift's own velocities, as the global loop
        }
        const double* x0 = steps.start->data() + 8 * i;
        for (std::size_t a = 0; a < 4; ++a) {
            q.vz[a] = (q.z[a] - x0[2 * a]) / interval;
            q.vr[a] = (q.r[a] - x0[2 * a + 1]) / interval;
        }
    }
    void plasticity(const material::MaterialPackage& materials, ElementSet& el,
                    const ElementRates& rates, std::span<const int32_t> tile) const {
        materials.applyPlasticity(el, rates, tile, *steps.interval);
    }
};

template <class Steps>
void FeSolid::updateList(std::span<const int32_t> list, const Steps& steps,
                         const material::MaterialPackage& materials,
                         std::vector<StepVote>& votes) {
    // Every element is updated independently, so the list is cut into tiles that each go
    // through the whole update (kinematics, deviator, energy, equation of state, forces)
    // while their data is still in cache, instead of one pass over the list per stage.
    const std::size_t count = list.size();
    const std::size_t tiles = (count + kTileSize - 1) / kTileSize;
    votes.assign(static_cast<std::size_t>(omp_get_max_threads()), StepVote{});
#pragma omp parallel if (count > kParallelMinItems)
    {
        StepVote local;
#pragma omp for schedule(static)
        for (std::size_t t = 0; t < tiles; ++t) {
            const std::size_t first = t * kTileSize;
            updateTile(list.subspan(first, std::min(kTileSize, count - first)), steps, materials,
                       local);
        }
        votes[static_cast<std::size_t>(omp_get_thread_num())] = local;
    }
    // 5: erosion (inverted, folded, crushed or strained in step 1, or failed), in ascending
    // order whatever the thread count.
    for (const int32_t e : list) {
        if (m_erode[static_cast<std::size_t>(e)]) {
            erode(static_cast<std::size_t>(e));
        }
    }
    m_updatedCount = count;
}

void FeSolid::update(double dt, const material::MaterialPackage& materials) {
    selectEvaluated();
    m_erodedNow.clear();
    zeroForcesIfFull();
    std::vector<StepVote> votes;
    updateList(m_evaluated, SameStep{dt}, materials, votes);
    finishAssembly(votes);
}

std::span<const int32_t> FeSolid::wake() {
    selectEvaluated();
    m_wokenAlive.clear();
    for (const int32_t e : m_woken) {
        if (m_elements.alive[static_cast<std::size_t>(e)]) {
            m_wokenAlive.push_back(e);
        }
    }
    return m_wokenAlive;
}

void FeSolid::updateElements(std::span<const int32_t> elements, const Intervals& steps,
                             const material::MaterialPackage& materials) {
    m_erodedNow.clear();
    std::vector<StepVote> votes;
    updateList(elements, OwnInterval{steps}, materials, votes);
    // The scene's step: the smallest vote of the evaluated elements, the stale ones of those
    // in the course of an interval included (ties to the lowest index, at any thread count).
    StepVote vote;
    vote.offer(m_referenceDt, -1);
    for (const int32_t e : m_evaluated) {
        const auto i = static_cast<std::size_t>(e);
        if (m_elements.alive[i] && m_ownStep[i] < kNoLimit) {
            vote.offer(m_ownStep[i], e);
        }
    }
    m_stableDt = vote.dt;
    m_limitingElement = vote.element;
}

void FeSolid::gatherImpulses(std::span<const int32_t> elements, std::span<const double> weight) {
    auto& nd = m_nodes;
    if (m_impulseFull) {
        // The first gather (or the first after a resume): any node may hold a force.
        m_impulseFull = false;
        std::fill(nd.fz.begin(), nd.fz.end(), 0.0);
        std::fill(nd.fr.begin(), nd.fr.end(), 0.0);
        m_impulseMarked.assign(nd.size(), 0);
        m_impulseNodes.clear();
    }
    for (const int32_t n : m_impulseNodes) {
        const auto k = static_cast<std::size_t>(n);
        nd.fz[k] = 0.0;
        nd.fr[k] = 0.0;
        m_impulseMarked[k] = 0;
    }
    m_impulseNodes.clear();
    for (std::size_t k = 0; k < elements.size(); ++k) {
        const auto e = static_cast<std::size_t>(elements[k]);
        m_cornerWeight[e] = weight[k];
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(m_elements.node(e, a));
            if (!m_impulseMarked[n]) {
                m_impulseMarked[n] = 1;
                m_impulseNodes.push_back(static_cast<int32_t>(n));
            }
        }
    }
    // Per node over its corners in element order (the weights of unlisted elements are 0).
    const std::size_t count = m_impulseNodes.size();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t g = 0; g < count; ++g) {
        const auto n = static_cast<std::size_t>(m_impulseNodes[g]);
        double fz = 0.0, fr = 0.0;
        for (int64_t k = m_nodeCorners.offset[n]; k < m_nodeCorners.offset[n + 1]; ++k) {
            const auto slot =
                static_cast<std::size_t>(m_nodeCorners.corners[static_cast<std::size_t>(k)]);
            const double w = m_cornerWeight[slot / 4];
            fz += w * m_elementForce[2 * slot];
            fr += w * m_elementForce[2 * slot + 1];
        }
        nd.fz[n] = fz;
        nd.fr[n] = fr;
    }
    for (const int32_t e : elements) {
        m_cornerWeight[static_cast<std::size_t>(e)] = 0.0;
    }
}

void FeSolid::restoreAwake(const std::vector<uint8_t>& awake) {
    m_elementAwake = awake;
    m_fullSelection = false;
    m_erodedSinceSelection = false;
    m_nodeAwake.assign(m_nodes.size(), 0);
    m_nodeMarked.assign(m_nodes.size(), 0);
    m_gatherNodes.clear();
    m_evaluated.clear();
    for (std::size_t i = 0; i < m_elements.size(); ++i) {
        if (m_elementAwake[i] && m_elements.alive[i]) {
            m_evaluated.push_back(static_cast<int32_t>(i));
            gatherNodesOf(i);
        }
    }
    m_impulseFull = true;
}

template <class Steps>
void FeSolid::updateTile(std::span<const int32_t> tile, const Steps& steps,
                         const material::MaterialPackage& materials, StepVote& vote) {
    auto& el = m_elements;
    const auto& nd = m_nodes;
    const bool axi = m_options.axisymmetric;
    const bool strength = el.hasStrength();
    const double cq = m_options.bulkQuadratic, cl = m_options.bulkLinear;
    std::array<StepStart, kTileSize> start;

    // 1-2: kinematics at mid-step, density from the end-of-step swept volume, bulk viscosity,
    // geometric strain.
    for (std::size_t k = 0; k < tile.size(); ++k) {
        const auto i = static_cast<std::size_t>(tile[k]);
        StepStart& s0 = start[k];
        const double dt = steps.of(i);
        QuadState end = gather(nd, el, i);
        steps.meanVelocities(i, end);
        QuadState mid = end;
        for (std::size_t a = 0; a < 4; ++a) {
            mid.z[a] -= 0.5 * dt * end.vz[a];
            mid.r[a] -= 0.5 * dt * end.vr[a];
        }
        const QuadGeometry gMid = quadGeometry(mid);
        const QuadGeometry gEnd = quadGeometry(end);
        s0.energy = el.e[i];
        s0.pressure = el.p[i];
        if (strength) {
            s0.szz = el.szz[i];
            s0.srr = el.srr[i];
            s0.srz = el.srz[i];
        }
        if (!(gEnd.area > 0.0) || !(gMid.area > 0.0) || !convex(end)) {
            m_erode[i] = 1; // inverted or folded: erode (its state is left as it was)
            s0.volumeChange = 0.0;
            s0.hourglassWork = 0.0;
            m_volumetricRate[i] = 0.0;
            continue;
        }
        const QuadVelocityGradient l = velocityGradient(mid, gMid);
        const double hoop =
            axi ? 0.25 * (end.vr[0] + end.vr[1] + end.vr[2] + end.vr[3]) / gMid.meanR : 0.0;
        m_rates.dvzDz[i] = l.zz;
        m_rates.dvzDr[i] = l.zr;
        m_rates.dvrDz[i] = l.rz;
        m_rates.dvrDr[i] = l.rr;
        m_rates.hoopRate[i] = hoop;
        const double trace = l.zz + l.rr + hoop;
        const double mean = trace / 3.0;
        const double ezz = l.zz - mean, err = l.rr - mean, ett = hoop - mean;
        const double ezr = 0.5 * (l.zr + l.rz);
        const double rate =
            std::sqrt((2.0 / 3.0) * (ezz * ezz + err * err + ett * ett + 2.0 * ezr * ezr));
        m_rates.strainRate[i] = rate;
        m_volumetricRate[i] = trace;
        const auto body = static_cast<std::size_t>(el.body[i]);
        bool strained = false;
        if (m_options.instantaneousErosionStrain) {
            // The logarithms only where a cheap bound cannot rule erosion out (the stored
            // strain of the others is refreshed for output by erosionStrain()).
            const Stretch stretch = stretchOf(end, m_referenceShape[i], axi);
            if (!strainCertainlyBelow(stretch, m_strainRatioLimit[body])) {
                el.geometricStrain[i] = equivalentLogStrain(stretch);
                strained = el.geometricStrain[i] > m_erosionFactor[body];
            }
        } else {
            el.geometricStrain[i] += dt * rate;
            strained = el.geometricStrain[i] > m_erosionFactor[body];
        }
        // Crushed past its equation of state's range (material::densityCeiling, 2.25 rho0 for
        // Al 6061-T6, where no shock state of these impacts reaches): a collapsing element,
        // which the geometric strain misses when its distortion is an hourglass mode (the
        // one-point deformation gradient does not see it). Its Mie-Grueneisen pressure there
        // is meaningless (1e4 GPa were seen in a foam layer, and an energy error of -108 %).
        // rho = m / V, written as rho0 V0 / V (m = rho0 V0 by construction) so that an element
        // at its reference volume has its reference density exactly: evaluating an undisturbed
        // element then changes nothing, not even in the last bit.
        const double volume = sweptVolume(gEnd, axi);
        const double density = m_referenceDensity[i] * (m_referenceVolume[i] / volume);
        const bool crushed = density > materials.bodies()[body].maxDensity;
        if (crushed || strained) {
            // Eroded on the strain of this step, before its material update: an element this
            // distorted is close to inversion, and its end-of-step state would be meaningless.
            m_erode[i] = 1;
            s0.volumeChange = 0.0;
            s0.hourglassWork = 0.0;
            continue;
        }
        // Work of the hourglass force over the step, returned to the element as heat.
        const auto gamma = hourglassBase(end, gEnd);
        double qz = 0.0, qr = 0.0;
        for (std::size_t a = 0; a < 4; ++a) {
            qz += gamma[a] * end.vz[a];
            qr += gamma[a] * end.vr[a];
        }
        s0.hourglassWork = dt * m_hourglassRate[i] * (qz * qz + qr * qr);

        s0.volumeChange = volume - m_volume[i];
        m_volume[i] = volume;
        el.rho[i] = density;
        const double length = std::sqrt(gEnd.area);
        el.q[i] = trace < 0.0
                      ? el.rho[i] * length * (cq * length * trace * trace - cl * el.cs[i] * trace)
                      : 0.0;
    }

    // 3: deviator (Jaumann rate over the step, then radial return and damage).
    if (strength) {
        materials.addStressRates(el, tile, m_rates);
        for (const int32_t element : tile) {
            const auto i = static_cast<std::size_t>(element);
            const double dt = steps.of(i);
            el.szz[i] += dt * m_rates.dszz[i];
            el.srr[i] += dt * m_rates.dsrr[i];
            el.srz[i] += dt * m_rates.dsrz[i];
        }
        steps.plasticity(materials, el, m_rates, tile);
    }

    updateEnergy(tile, start.data(), steps, materials);

    // 6: forces at the end-of-step geometry (an element about to erode holds none).
    for (const int32_t element : tile) {
        elementForces(static_cast<std::size_t>(element), vote);
    }
}

template <class Steps>
void FeSolid::updateEnergy(std::span<const int32_t> tile, const StepStart* start,
                           const Steps& steps, const material::MaterialPackage& materials) {
    auto& el = m_elements;
    const bool strength = el.hasStrength();
    // A predictor with the start pressure, then the correction -(p_pred - p_start) dV / 2m.
    for (std::size_t k = 0; k < tile.size(); ++k) {
        const auto i = static_cast<std::size_t>(tile[k]);
        const StepStart& s0 = start[k];
        if (m_erode[i]) {
            continue;
        }
        const double dV = s0.volumeChange;
        double deviatoricWork = 0.0;
        if (strength) {
            const double szz = 0.5 * (el.szz[i] + s0.szz);
            const double srr = 0.5 * (el.srr[i] + s0.srr);
            const double srz = 0.5 * (el.srz[i] + s0.srz);
            const double stt = -(szz + srr);
            const double power = szz * m_rates.dvzDz[i] + srr * m_rates.dvrDr[i] +
                                 stt * m_rates.hoopRate[i] +
                                 srz * (m_rates.dvzDr[i] + m_rates.dvrDz[i]);
            const double meanVolume = m_volume[i] - 0.5 * dV;
            deviatoricWork = steps.of(i) * power * meanVolume;
        }
        el.e[i] = s0.energy +
                  (-(s0.pressure + el.q[i]) * dV + deviatoricWork + s0.hourglassWork) / el.mass[i];
    }
    materials.updatePressure(el, tile);
    for (std::size_t k = 0; k < tile.size(); ++k) {
        const auto i = static_cast<std::size_t>(tile[k]);
        const StepStart& s0 = start[k];
        if (m_erode[i]) {
            continue;
        }
        el.e[i] -= 0.5 * (el.p[i] - s0.pressure) * s0.volumeChange / el.mass[i];
        // Failed completely: no deviator, no tension, and expanded below the stress cut-off.
        const auto b = static_cast<std::size_t>(el.body[i]);
        if (strength && el.damage[i] >= 1.0 && el.rho[i] < materials.bodies()[b].minDensity) {
            m_erode[i] = 1;
        }
    }
    materials.updatePressure(el, tile);
}

void FeSolid::erode(std::size_t i) {
    auto& el = m_elements;
    el.alive[i] = 0;
    el.p[i] = 0.0; // as a restored run has it (pressure is not checkpointed; dead points get none)
    m_erode[i] = 0;
    if (!m_options.erodedBecomeParticles) {
        m_erodedEnergy += el.mass[i] * el.e[i];
    }
    m_erodedNow.push_back(static_cast<int32_t>(i));
    ++m_erodedCount;
    m_erodedSinceSelection = true;
    for (int a = 0; a < 4; ++a) {
        --m_nodes.elementCount[static_cast<std::size_t>(el.node(i, a))];
    }
}

void FeSolid::computeForces(const material::MaterialPackage& materials) {
    materials.updatePressure(m_elements);
    // The time step of an undisturbed element (the floor for every dormant element, which
    // does not vote while skipped).
    // Also the hourglass damping rate of every element at this state: an element's first
    // update after it wakes takes the rate of the last assembly, which for a dormant element
    // is this one (what evaluating it every step would have given).
    const auto& el = m_elements;
    StepVote vote;
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (!el.alive[i]) {
            continue;
        }
        const QuadGeometry g = quadGeometry(gather(m_nodes, el, i));
        if (g.area > 0.0 && el.cs[i] > 0.0) {
            vote.offer(g.area / g.maxDiagonal / el.cs[i], static_cast<int32_t>(i));
            m_hourglassRate[i] =
                hourglassDamping(m_options.hourglassCoefficient, el.rho[i], el.cs[i],
                                 sweptVolume(g, m_options.axisymmetric), g.area);
        }
    }
    m_referenceDt = vote.dt;
    selectEvaluated();
    assembleForces();
}

void FeSolid::zeroForcesIfFull() {
    // Only evaluated elements can hold a force: each writes its corner forces (zeros in the
    // update that erodes it, after which it leaves the list), and only the nodes of the listed
    // elements are gathered (every other node's force is, and stays, zero). The first
    // assembly (and the first after a resume) covers all.
    if (m_fullAssembly) {
        std::fill(m_elementForce.begin(), m_elementForce.end(), 0.0);
    }
}

void FeSolid::assembleForces() {
    zeroForcesIfFull();
    const std::size_t count = m_evaluated.size();
    std::vector<StepVote> votes(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel if (count > kParallelMinItems)
    {
        StepVote local;
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < count; ++k) {
            elementForces(static_cast<std::size_t>(m_evaluated[k]), local);
        }
        votes[static_cast<std::size_t>(omp_get_thread_num())] = local;
    }
    finishAssembly(votes);
}

void FeSolid::elementForces(std::size_t i, StepVote& vote) {
    const auto& el = m_elements;
    const bool axi = m_options.axisymmetric;
    const bool strength = el.hasStrength();
    const double cq = m_options.bulkQuadratic, cl = m_options.bulkLinear;
    double* f = &m_elementForce[8 * i];
    if (!el.alive[i] || m_erode[i]) {
        m_hourglassRate[i] = 0.0;
        std::fill_n(f, 8, 0.0);
        m_ownStep[i] = kNoLimit;
        return;
    }
    const QuadState s = gather(m_nodes, el, i);
    const QuadGeometry g = quadGeometry(s);
    if (!(g.area > 0.0)) {
        std::fill_n(f, 8, 0.0); // eroded at the next update
        m_ownStep[i] = kNoLimit;
        return;
    }
    const double volume = sweptVolume(g, axi);
    const double pq = el.p[i] + el.q[i];
    const double szz = strength ? el.szz[i] : 0.0;
    const double srr = strength ? el.srr[i] : 0.0;
    const double srz = strength ? el.srz[i] : 0.0;
    const double sigmaZZ = szz - pq, sigmaRR = srr - pq, sigmaTT = -(szz + srr) - pq;
    const double hoopForce = axi ? volume * sigmaTT / (4.0 * g.meanR) : 0.0;
    // Hourglass control.
    const double chg =
        hourglassDamping(m_options.hourglassCoefficient, el.rho[i], el.cs[i], volume, g.area);
    m_hourglassRate[i] = chg;
    const auto gamma = hourglassBase(s, g);
    double qz = 0.0, qr = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
        qz += gamma[a] * s.vz[a];
        qr += gamma[a] * s.vr[a];
    }
    for (std::size_t a = 0; a < 4; ++a) {
        f[2 * a] = -volume * (sigmaZZ * g.bz[a] + srz * g.br[a]) - chg * qz * gamma[a];
        f[2 * a + 1] =
            -volume * (srz * g.bz[a] + sigmaRR * g.br[a]) - hoopForce - chg * qr * gamma[a];
    }
    // Element time step.
    const double trace = m_volumetricRate[i];
    const double lengthDt = g.area / g.maxDiagonal;
    const double c = el.cs[i];
    const double qSpeed = trace < 0.0 ? cq * lengthDt * std::fabs(trace) + cl * c : 0.0;
    const double denom = qSpeed + std::sqrt(qSpeed * qSpeed + c * c);
    m_ownStep[i] = denom > 0.0 ? lengthDt / denom : kNoLimit;
    if (denom > 0.0) {
        vote.offer(m_ownStep[i], static_cast<int32_t>(i));
    }
}

void FeSolid::finishAssembly(const std::vector<StepVote>& votes) {
    StepVote vote;
    vote.offer(m_referenceDt, -1);
    for (const auto& v : votes) {
        if (v.element >= 0) {
            vote.offer(v.dt, v.element);
        }
    }
    m_stableDt = vote.dt;
    m_limitingElement = vote.element;
    m_elementSteps.resize(m_evaluated.size());
    for (std::size_t k = 0; k < m_evaluated.size(); ++k) {
        m_elementSteps[k] = m_ownStep[static_cast<std::size_t>(m_evaluated[k])];
    }

    // Gather the corner forces per node in a fixed (element) order.
    auto& nd = m_nodes;
    const std::size_t nn = nd.size();
    const bool all = m_fullAssembly;
    m_fullAssembly = false;
    const std::size_t gatherCount = all ? nn : m_gatherNodes.size();
#pragma omp parallel for schedule(static) if (gatherCount > kParallelMinItems)
    for (std::size_t g = 0; g < gatherCount; ++g) {
        const std::size_t n = all ? g : static_cast<std::size_t>(m_gatherNodes[g]);
        double fz = 0.0, fr = 0.0;
        for (int64_t k = m_nodeCorners.offset[n]; k < m_nodeCorners.offset[n + 1]; ++k) {
            const auto slot =
                static_cast<std::size_t>(m_nodeCorners.corners[static_cast<std::size_t>(k)]);
            fz += m_elementForce[2 * slot];
            fr += m_elementForce[2 * slot + 1];
        }
        nd.fz[n] = fz;
        nd.fr[n] = fr;
    }
}

std::vector<double> FeSolid::erosionStrain() const {
    std::vector<double> strain = m_elements.geometricStrain;
    if (m_options.instantaneousErosionStrain) {
        for (std::size_t i = 0; i < m_elements.size(); ++i) {
            if (m_elements.alive[i]) {
                strain[i] = instantaneousStrain(gather(m_nodes, m_elements, i), m_referenceShape[i],
                                                m_options.axisymmetric);
            }
        }
    }
    return strain;
}

void FeSolid::restoreErosion(double energy, std::size_t count) {
    m_erodedEnergy = energy;
    m_erodedCount = count;
}

void FeSolid::recountNodeElements() {
    m_fullAssembly = true;  // the restored forces are recomputed everywhere
    m_fullSelection = true; // and the awake set follows the restored state
    std::fill(m_nodes.elementCount.begin(), m_nodes.elementCount.end(), 0);
    for (std::size_t i = 0; i < m_elements.size(); ++i) {
        if (m_elements.alive[i]) {
            for (int a = 0; a < 4; ++a) {
                ++m_nodes.elementCount[static_cast<std::size_t>(m_elements.node(i, a))];
            }
        }
    }
    // Volumes follow the restored positions.
    for (std::size_t i = 0; i < m_elements.size(); ++i) {
        const QuadGeometry g = quadGeometry(gather(m_nodes, m_elements, i));
        m_volume[i] = sweptVolume(g, m_options.axisymmetric);
    }
}

} // namespace hvi::fe
