#include "assess/Assessment.hpp"

#include "assess/CoreDamageWidth.hpp"
#include "sph/ParticleSet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hvi::assess {

namespace {

std::string fmt(const char* format, double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

/// What a metric may assume of a snapshot and the reader does not check: body ids and node
/// indices in range, positions and masses finite.
void checkSnapshot(const io::Snapshot& s, std::size_t bodyCount, const std::string& label) {
    const std::string& g = s.info.group;
    const auto& p = s.particles;
    for (std::size_t i = 0; i < p.bodyId.size(); ++i) {
        if (p.bodyId[i] < 0 || static_cast<std::size_t>(p.bodyId[i]) >= bodyCount) {
            throw InputError(
                label, g + "/BodyId",
                "particle " + std::to_string(i) + " has body id " + std::to_string(p.bodyId[i]),
                "an index into the " + std::to_string(bodyCount) + " bodies of /scene");
        }
        if (p.alive[i] && !(std::isfinite(p.z[i]) && std::isfinite(p.r[i]) &&
                            std::isfinite(p.mass[i]) && std::isfinite(p.density[i]))) {
            throw InputError(label, g,
                             "particle " + std::to_string(i) +
                                 " has a non-finite "
                                 "position, mass or density",
                             "finite values for every alive particle");
        }
    }
    if (s.fe) {
        const auto& el = s.fe->elements;
        const auto nodes = static_cast<std::int64_t>(s.fe->nodes.z.size());
        for (std::size_t k = 0; k < el.connectivity.size(); ++k) {
            if (el.connectivity[k] < 0 || el.connectivity[k] >= nodes) {
                throw InputError(label, g + "/Elements/Connectivity",
                                 "element " + std::to_string(k / 4) + " refers to node " +
                                     std::to_string(el.connectivity[k]),
                                 "node indices below " + std::to_string(nodes));
            }
        }
        for (std::size_t k = 0; k < el.bodyId.size(); ++k) {
            if (el.bodyId[k] < 0 || static_cast<std::size_t>(el.bodyId[k]) >= bodyCount) {
                throw InputError(label, g + "/Elements/BodyId",
                                 "element " + std::to_string(k) + " has body id " +
                                     std::to_string(el.bodyId[k]),
                                 "an index into the bodies of /scene");
            }
        }
    }
}

/// A string-valued run fact, or `fallback` when absent or not a string.
std::string stringFact(const nlohmann::json& facts, const char* key, const std::string& fallback) {
    const auto it = facts.find(key);
    return it != facts.end() && it->is_string() ? it->get<std::string>() : fallback;
}

/// Whether every sign of failure so far lies in the axis band.
struct AxisBand {
    bool perforation = true; ///< every perforated snapshot
    bool spall = true;       ///< every detached spall
};

/// The rear wall's metrics of one snapshot into the run's: worst grade, first failure, the
/// perforation's extent (docs/metrics.md, "Over time").
void combineRearWall(Assessment& a, SnapshotMetrics& m, AxisBand& band) {
    if (!m.rearWall) {
        return;
    }
    const BodyLayout& wall = a.layout.bodies[*a.layout.rearWall];
    m.grade = damageGrade(*m.rearWall, wall.spacing, a.criteria);
    if (!a.grade || m.grade > *a.grade) {
        a.grade = m.grade;
    }
    if (isFailure(m.grade) && !a.failureTimeUs) {
        a.failureTimeUs = m.timeUs;
    }
    if (m.rearWall->detachedSpall) {
        a.spallRadiusMm = std::max(a.spallRadiusMm, m.rearWall->spallRadiusMm);
        a.spallMassMg = std::max(a.spallMassMg, m.rearWall->spallMassMg);
        band.spall &= m.rearWall->spallAxisConfined;
    }
    a.bulgeMm = std::max(a.bulgeMm, m.rearWall->bulgeMm);
    if (!a.rearWallPerforated) {
        a.rearWallPerforated = false;
    }
    if (m.rearWall->perforated && !*a.rearWallPerforated) {
        a.rearWallPerforated = true;
        a.perforationTimeUs = m.timeUs;
    }
    a.throughThicknessFailure |= m.rearWall->throughThicknessFailure;
    a.materialCrossed |= m.rearWall->materialCrossed;
    a.detachedSpall |= m.rearWall->detachedSpall;
    a.openColumns = std::max(a.openColumns, m.rearWall->openColumns);
    a.openRadiusMm = std::max(a.openRadiusMm, m.rearWall->openRadiusMm);
    if (m.rearWall->perforated) {
        a.perforationRadiusMm = std::max(a.perforationRadiusMm, m.rearWall->perforationRadiusMm);
        band.perforation &= m.rearWall->axisConfined;
    }
}

void combinePenetration(Assessment& a, const SnapshotMetrics& m) {
    if (m.penetration) {
        if (!a.penetrationDepthMm || m.penetration->depthMm > *a.penetrationDepthMm) {
            a.penetrationDepthMm = m.penetration->depthMm;
            a.deepestBody = m.penetration->deepestBody;
        }
        for (auto b : m.penetration->reachedBodies) {
            if (std::find(a.reachedBodies.begin(), a.reachedBodies.end(), b) ==
                a.reachedBodies.end()) {
                a.reachedBodies.push_back(b);
            }
        }
        for (auto b : m.penetration->perforatedLayers) {
            if (std::find(a.perforatedLayers.begin(), a.perforatedLayers.end(), b) ==
                a.perforatedLayers.end()) {
                a.perforatedLayers.push_back(b);
            }
        }
    }
}

/// Particle, node and element counts of the last snapshot.
void countFinalItems(Assessment& a, const io::Snapshot& snap) {
    for (std::size_t i = 0; i < snap.particles.z.size(); ++i) {
        if (sph::isUnusedSlot(snap.particles.alive[i], snap.particles.mass[i])) {
            continue;
        }
        ++a.particles;
        if (snap.particles.alive[i]) {
            ++a.aliveParticles;
        } else {
            ++a.deletedParticles;
            a.deletedMassMg += snap.particles.mass[i];
        }
    }
    if (snap.fe) {
        a.nodes = snap.fe->nodes.z.size();
        a.elements = snap.fe->elements.alive.size();
        a.aliveElements = static_cast<std::size_t>(
            std::count(snap.fe->elements.alive.begin(), snap.fe->elements.alive.end(), 1));
    }
}

/// The verdict from the worst grade, the axis-band flag and the state at the end.
void finishRearWall(Assessment& a, const AxisBand& band) {
    a.axisConfined = a.rearWallPerforated.value_or(false) && band.perforation;
    if (a.grade) {
        a.failed = isFailure(*a.grade);
        // Every sign of failure lies in the axis band: the perforation (if any) in every
        // perforated snapshot, and every detached spall.
        a.axisBandOnly = *a.failed && a.layout.axisymmetric &&
                         (!a.rearWallPerforated.value_or(false) || a.axisConfined) && band.spall;
        const RearWallPerforation& end = *a.last().rearWall;
        a.atRest = end.wallMaxSpeedKmS <= a.criteria.restSpeedKmS &&
                   end.approachingItems <
                       static_cast<std::size_t>(std::max(1, a.criteria.minCrossingItems));
    }
    a.solverStopUnconfirmed = a.hasRunFacts && a.rearWallPerforated && !*a.rearWallPerforated &&
                              stringFact(a.runFacts, "stop_reason", "") == "rear_wall_perforated";
}

/// Warnings about how far the verdict can be trusted, from the whole assessment.
void addEndWarnings(Assessment& a) {
    if (a.energy.rows == 0) {
        a.warnings.push_back("/history is empty: no energy error");
    } else if (!a.energy.maxError) {
        a.warnings.push_back("/history/EnergyError is not finite at t = " +
                             fmt("%.4g", a.energy.maxErrorTimeUs.value_or(0.0)) +
                             " us: the run blew up");
    }
    if (a.solverStopUnconfirmed) {
        a.warnings.push_back("the solver stopped on its rear-wall perforation rule (any "
                             "material behind the rear face) but the assessment finds no "
                             "perforation (docs/metrics.md): the verdict follows the damage "
                             "grade, and an NP is provisional (the run ended with material "
                             "behind the wall); rerun with run.stop_on_rear_wall_perforation "
                             "false");
    }
    if (a.axisConfined) {
        a.warnings.push_back(
            "the rear wall is perforated only within " + fmt("%.3g", a.perforationRadiusMm) +
            " mm of the axis (" + fmt("%.3g", a.criteria.axisBandSpacings) +
            " spacings): in 2D axisymmetry material on the axis cannot move off it, and the "
            "verdict rests on the first element columns there (docs/metrics.md)");
    }
    if (a.failed && !*a.failed && !a.complete) {
        a.warnings.push_back("NP is provisional: the run did not finish");
    }
    if (a.failed && !*a.failed && !a.atRest) {
        const RearWallPerforation& end = *a.last().rearWall;
        a.warnings.push_back(
            "NP is provisional: the run ended (" + stringFact(a.runFacts, "stop_reason", a.status) +
            ") with the rear wall still moving at " + fmt("%.3g", end.wallMaxSpeedKmS) +
            " km/s and " + std::to_string(end.approachingItems) +
            " items move toward it at up to " + fmt("%.3g", end.approachingMaxSpeedKmS) +
            " km/s (at rest: below " + fmt("%.3g", a.criteria.restSpeedKmS) +
            " km/s); rerun with a later --end-time-us");
    }
    if (a.axisBandOnly && !a.axisConfined) {
        a.warnings.push_back("the rear wall's detached spall lies only within " +
                             fmt("%.3g", a.spallRadiusMm) +
                             " mm of the axis: the verdict rests on the axis band "
                             "(docs/metrics.md)");
    }
    if (a.last().hole && a.last().hole->reachesEdge) {
        a.warnings.push_back("the bumper hole reaches the edge of the bumper as simulated: "
                             "the hole diameter is a lower bound");
    }
}

} // namespace

Assessment assessRun(const io::RunFileReader& reader, const AssessOptions& options) {
    Assessment a;
    const std::string label = reader.path().string();
    a.runFile = label;
    a.snapshots = reader.snapshots();
    if (a.snapshots.empty()) {
        throw InputError(label, "/snapshots", "holds no snapshot",
                         "at least one snapshot (the run wrote none before it stopped?)");
    }
    a.scene = sceneOfRun(reader);
    a.history = reader.readHistory();

    // The run's own facts, and whether it finished.
    a.hasRunFacts = reader.hasRunFacts();
    if (a.hasRunFacts) {
        a.runFacts = reader.runFacts();
        a.status = stringFact(a.runFacts, "status", "complete");
        a.complete = a.status == "complete";
        if (!a.complete) {
            a.warnings.push_back(
                "the run is partial (/run@status \"" + a.status + "\", stop reason \"" +
                stringFact(a.runFacts, "stop_reason", "unknown") + "\"): the verdict covers its " +
                std::to_string(a.snapshots.size()) +
                " snapshots up to t = " + fmt("%.4g", a.snapshots.back().timeUs) + " us only");
        }
    } else {
        a.status = "unfinished";
        a.complete = false;
        a.warnings.push_back("no /run group: the run was killed or is still running; the "
                             "verdict covers its " +
                             std::to_string(a.snapshots.size()) + " snapshots up to t = " +
                             fmt("%.4g", a.snapshots.back().timeUs) + " us only");
    }
    try {
        a.code = reader.code();
    } catch (const InputError&) {
        a.code = nullptr;
        a.warnings.push_back("no /Code group: the solver version that wrote the run is unknown");
    }

    a.first = reader.readSnapshot(a.snapshots.front().index);
    const std::size_t bodyCount = a.scene.bodies.size();
    checkSnapshot(a.first, bodyCount, label);
    a.layout = shieldLayout(a.scene, a.first);
    a.criteria = options.criteria;
    if (a.criteria.failedDensityRatio < 0.0) {
        a.criteria.failedDensityRatio = a.layout.minDensityRatio;
    }
    if (a.criteria.restSpeedKmS < 0.0) {
        a.criteria.restSpeedKmS = a.layout.stopDebrisSpeedKmS;
    }
    if (!a.layout.rearWall) {
        a.warnings.push_back("the scene has no body with role \"rear_wall\": no P/NP verdict");
    }
    std::size_t targets = 0;
    for (std::size_t b = 0; b < a.layout.bodies.size(); ++b) {
        targets += a.layout.isTarget(b) ? 1 : 0;
    }
    // A single wall (the rear wall the only target) has no bumper by design.
    const bool singleWall = a.layout.rearWall && targets == 1;
    if (!a.layout.bumper && !singleWall) {
        a.warnings.push_back("the scene has no body with role \"bumper\": no hole diameter; "
                             "depths are measured from the front of the first target body");
    }
    for (std::size_t i = 0; i < a.first.particles.mass.size(); ++i) {
        a.initialMassMg += a.first.particles.mass[i];
    }
    if (a.first.fe) {
        for (double m : a.first.fe->nodes.mass) {
            a.initialMassMg += m;
        }
    }

    AxisBand band;
    for (const auto& info : a.snapshots) {
        io::Snapshot snap =
            info.index == a.first.info.index ? a.first : reader.readSnapshot(info.index);
        checkSnapshot(snap, bodyCount, label);
        const MaterialItems items = materialItems(snap, a.first);
        if (!items.hasReference && a.referencePositions) {
            a.referencePositions = false;
            a.warnings.push_back(info.group +
                                 " does not keep the item slots of the first "
                                 "snapshot: metrics use current positions and the scene's "
                                 "geometry instead of initial positions");
        }
        SnapshotMetrics m;
        m.index = info.index;
        m.timeUs = info.timeUs;
        m.hole = bumperHole(items, a.layout, a.criteria);
        m.rearWall = rearWallPerforation(items, a.layout, a.criteria);
        m.penetration = penetrationDepth(items, a.layout, a.criteria);
        m.coreDamageWidthMm = coreDamageWidthMm(items, a.layout, a.criteria);
        m.debris = debrisCloud(items, a.layout, a.criteria);

        // Combine over time.
        combineRearWall(a, m, band);
        combinePenetration(a, m);
        if (m.coreDamageWidthMm) {
            a.coreDamageWidthMm = std::max(a.coreDamageWidthMm.value_or(0.0), *m.coreDamageWidthMm);
        }
        if (m.debris.items > 0) {
            a.debrisDepthMm = std::max(a.debrisDepthMm.value_or(m.debris.leadingEdgeDepthMm),
                                       m.debris.leadingEdgeDepthMm);
        }
        if (&info == &a.snapshots.back()) {
            countFinalItems(a, snap);
        }
        a.series.push_back(std::move(m));
        if (options.keepSnapshots.count(info.index)) {
            a.kept.push_back(std::move(snap));
        }
    }
    finishRearWall(a, band);
    std::sort(a.reachedBodies.begin(), a.reachedBodies.end());
    std::sort(a.perforatedLayers.begin(), a.perforatedLayers.end());

    a.energy = energyBudget(a.history);
    addEndWarnings(a);
    return a;
}

} // namespace hvi::assess
