#include "solver/StopRules.hpp"

#include "assess/Criteria.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hvi::solver {

namespace {
constexpr double kMinusInf = -std::numeric_limits<double>::infinity();
} // namespace

StopRules::StopRules(const scene::Scene& scene, std::vector<double> spacing)
    : m_bodies(scene.bodies), m_run(scene.run), m_spacing(std::move(spacing)),
      m_penetrated(scene.bodies.size(), 0) {
    m_minSpacing = std::numeric_limits<double>::infinity();
    for (const double s : m_spacing) {
        m_minSpacing = std::min(m_minSpacing, s);
    }
}

bool StopRules::penetratedNow(std::size_t b, const sph::ParticleSet& ps,
                              const fe::NodeSet* nodes) const {
    const auto& body = m_bodies[b];
    const double spacing = m_spacing[b];
    const double rear = body.shape.boundZMax() + 0.5 * spacing;
    const double rLo = body.shape.boundRMin(), rHi = body.shape.boundRMax();
    // An FE body: the rear of its meshed material per radial bin (-inf where none is left).
    std::vector<double> rearOf;
    const bool fe = body.discretization == scene::Discretization::Fe;
    if (fe) {
        rearOf.assign(static_cast<std::size_t>((rHi - rLo) / spacing) + 2, kMinusInf);
        for (std::size_t k = 0; k < nodes->size(); ++k) {
            if (static_cast<std::size_t>(nodes->body[k]) == b && nodes->elementCount[k] > 0) {
                const double bin = std::floor((nodes->r[k] - rLo) / spacing);
                if (bin >= 0.0 && bin < static_cast<double>(rearOf.size())) {
                    auto& slot = rearOf[static_cast<std::size_t>(bin)];
                    slot = std::max(slot, nodes->z[k] + 0.5 * spacing);
                }
            }
        }
    }
    auto behind = [&](double z, double r) {
        if (r < rLo || r > rHi) {
            return false;
        }
        if (!fe) {
            return z > rear;
        }
        // Where the body still has meshed material the wall holds there, whatever lone free
        // node got past it.
        const auto bin = static_cast<std::size_t>((r - rLo) / spacing);
        return bin < rearOf.size() && !std::isfinite(rearOf[bin]) && z > rear;
    };
    // FE bodies: so that a lone free node slipping through a one-element crater on the axis
    // ends no run early.
    const auto needed =
        fe ? static_cast<std::size_t>(assess::Criteria{}.minCrossingItems) : std::size_t{1};
    std::size_t crossing = 0;
    for (std::size_t i = 0; i < ps.size() && crossing < needed; ++i) {
        if (ps.alive[i] && static_cast<std::size_t>(ps.body[i]) != b && behind(ps.z[i], ps.r[i])) {
            ++crossing;
        }
    }
    for (std::size_t k = 0; nodes && crossing < needed && k < nodes->size(); ++k) {
        if (nodes->alive[k] && static_cast<std::size_t>(nodes->body[k]) != b &&
            behind(nodes->z[k], nodes->r[k])) {
            ++crossing;
        }
    }
    return crossing >= needed;
}

void StopRules::update(double time, const sph::ParticleSet& ps, const fe::NodeSet* nodes) {
    const double moving = m_run.stopDebrisSpeed;
    double fastest = 0.0;
    // Progress of the material moving forward (faster than the stop speed): its foremost
    // item, and its centre of mass. Either advancing by a spacing counts, so neither a lone
    // slow item stalled ahead of the cloud (against a layer) nor a few fast stray items hide
    // a debris cloud that is still crossing a gap.
    double front = kMinusInf;
    double movingMass = 0.0, movingMoment = 0.0;
    auto account = [&](double vz, double z, double mass) {
        fastest = std::max(fastest, vz);
        if (vz > moving) {
            front = std::max(front, z);
            movingMass += mass;
            movingMoment += mass * z;
        }
    };
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.alive[i]) {
            account(ps.vz[i], ps.z[i], ps.mass[i]);
        }
    }
    for (std::size_t k = 0; nodes && k < nodes->size(); ++k) {
        if (nodes->alive[k]) {
            account(nodes->vz[k], nodes->z[k], nodes->mass[k]);
        }
    }
    m_debrisSpeed = fastest;
    const double centre = movingMass > 0.0 ? movingMoment / movingMass : kMinusInf;
    bool newPenetration = false;
    for (std::size_t b = 0; b < m_bodies.size(); ++b) {
        if (m_penetrated[b] || m_bodies[b].role == scene::BodyRole::Projectile) {
            continue;
        }
        if (penetratedNow(b, ps, nodes)) {
            m_penetrated[b] = 1;
            newPenetration = true;
        }
    }
    // Progress is an advance of at least what the stop speed carries material in the rule's
    // window (or a spacing, if less): a layer still bulging at the stop speed under the debris
    // pressing on it is progress. With a spacing alone (0.16 km/s for 0.04 mm in 0.25 us)
    // HITF03147-3 stopped at 8.9 us with the debris still pushing its rear facesheet at
    // 0.7 km/s, which tore at 12.2 us.
    const double window = m_run.stopNoNewPenetration;
    const double advance =
        window > 0.0 && moving > 0.0 ? std::min(m_minSpacing, moving * window) : m_minSpacing;
    if (newPenetration || front > m_progressFront + advance ||
        centre > m_progressCentre + advance) {
        m_lastProgressTime = time;
        m_progressFront = std::max(front, m_progressFront);
        m_progressCentre = std::max(centre, m_progressCentre);
    }
    // The wall check is a pass over every point: made only once progress has stalled for
    // half the window (the clock advances after this call, so not the whole window).
    m_rearWallActive = window > 0.0 && time - m_lastProgressTime > 0.5 * window &&
                       rearWallActive(moving, ps, nodes);
}

bool StopRules::rearWallActive(double speed, const sph::ParticleSet& ps,
                               const fe::NodeSet* nodes) const {
    double zRear = kMinusInf;
    double rLo = std::numeric_limits<double>::infinity(), rHi = -rLo;
    std::vector<uint8_t> isWall(m_bodies.size(), 0);
    for (std::size_t b = 0; b < m_bodies.size(); ++b) {
        const auto& body = m_bodies[b];
        if (body.role == scene::BodyRole::RearWall) {
            isWall[b] = 1;
            zRear = std::max(zRear, body.shape.boundZMax() + 0.5 * m_spacing[b]);
            rLo = std::min(rLo, body.shape.boundRMin());
            rHi = std::max(rHi, body.shape.boundRMax());
        }
    }
    if (!std::isfinite(zRear) || speed <= 0.0) {
        return false;
    }
    // The wall itself: its meshed nodes moving either way, or its particles moving outward
    // no further than a wall thickness behind its rear face (a bulge or spall leaving; spall
    // that has flown further, and ejecta thrown back off its front, which move away from
    // the wall for good, are no longer the wall). Other bodies: what is in front of its rear
    // face, within its radial extent, moving toward it.
    auto approaching = [&](std::int32_t body, double z, double r, double vz) {
        return !isWall[static_cast<std::size_t>(body)] && vz > speed && z < zRear && r >= rLo &&
               r <= rHi;
    };
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        const auto b = static_cast<std::size_t>(ps.body[i]);
        const auto& shape = m_bodies[b].shape;
        const bool wallMoving = isWall[b] && ps.vz[i] > speed &&
                                ps.z[i] < zRear + shape.boundZMax() - shape.boundZMin();
        if (wallMoving || approaching(ps.body[i], ps.z[i], ps.r[i], ps.vz[i])) {
            return true;
        }
    }
    for (std::size_t k = 0; nodes && k < nodes->size(); ++k) {
        if (!nodes->alive[k]) {
            continue;
        }
        const bool wallMoving = isWall[static_cast<std::size_t>(nodes->body[k])] &&
                                nodes->elementCount[k] > 0 && std::fabs(nodes->vz[k]) > speed;
        if (wallMoving || approaching(nodes->body[k], nodes->z[k], nodes->r[k], nodes->vz[k])) {
            return true;
        }
    }
    return false;
}

bool StopRules::awaitsRearWallConfirmation() const {
    if (!m_run.stopOnRearWallPerforation || m_rearWallConfirmed) {
        return false;
    }
    for (std::size_t b = 0; b < m_bodies.size(); ++b) {
        if (m_penetrated[b] && m_bodies[b].role == scene::BodyRole::RearWall) {
            return true;
        }
    }
    return false;
}

std::optional<std::string> StopRules::reason(double time, long step) const {
    if (time >= m_run.endTime * (1.0 - 1e-12)) {
        return "end_time";
    }
    if (step >= m_run.maxSteps) {
        return "max_steps";
    }
    bool anyPenetrated = false;
    for (std::size_t b = 0; b < m_bodies.size(); ++b) {
        anyPenetrated = anyPenetrated || m_penetrated[b];
        if (m_run.stopOnRearWallPerforation && m_penetrated[b] && m_rearWallConfirmed &&
            m_bodies[b].role == scene::BodyRole::RearWall) {
            return "rear_wall_perforated";
        }
    }
    if (m_run.stopDebrisSpeed > 0.0 && step > 0 && m_debrisSpeed < m_run.stopDebrisSpeed) {
        return "debris_stopped";
    }
    // Not while material still moves toward or in the rear wall: the wall may yet fail.
    if (m_run.stopNoNewPenetration > 0.0 && anyPenetrated && !m_rearWallActive &&
        time - m_lastProgressTime > m_run.stopNoNewPenetration) {
        return "no_new_penetration";
    }
    return std::nullopt;
}

} // namespace hvi::solver
