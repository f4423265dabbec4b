// Assessing one run file: reads every snapshot once, evaluates each metric on each snapshot,
// combines them over time (docs/metrics.md, "Over time") and keeps what the pictures need.
//
//   final state (hole, debris cloud)          -> the last snapshot
//   monotone quantities (perforation, depth,  -> the worst over all snapshots
//     core damage width, deepest debris)
//   energy error                              -> the history (every history row)
//
// All problems with the file are InputErrors naming the HDF5 path (exit 2, nothing written).
#pragma once

#include "assess/BumperHole.hpp"
#include "assess/Criteria.hpp"
#include "assess/DamageGrade.hpp"
#include "assess/DebrisCloud.hpp"
#include "assess/EnergyBudget.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/PenetrationDepth.hpp"
#include "assess/RearWallPerforation.hpp"
#include "assess/ShieldLayout.hpp"
#include "io/RunFileReader.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace hvi::assess {

/// The metrics of one snapshot.
struct SnapshotMetrics {
    int index = 0;
    double timeUs = 0.0;
    std::optional<BumperHole> hole;
    std::optional<RearWallPerforation> rearWall;
    DamageGrade grade = DamageGrade::None; ///< of the rear wall (None without one)
    std::optional<PenetrationDepth> penetration;
    std::optional<double> coreDamageWidthMm;
    DebrisCloud debris;
};

struct AssessOptions {
    Criteria criteria;
    /// Snapshot indices whose full data to keep (for pictures).
    std::set<int> keepSnapshots;
};

struct Assessment {
    std::string runFile;
    scene::Scene scene;
    ShieldLayout layout;
    Criteria criteria; ///< as used (failedDensityRatio resolved from the scene)

    // The run's own facts.
    bool hasRunFacts = false;
    nlohmann::json runFacts = nlohmann::json::object();
    std::string status; ///< "complete", "partial" or "unfinished" (no /run)
    bool complete = false;
    nlohmann::json code = nullptr; ///< /Code attributes (null when absent)

    // Per snapshot, in time order.
    std::vector<io::SnapshotInfo> snapshots;
    std::vector<SnapshotMetrics> series;
    bool referencePositions = true; ///< every snapshot kept the first one's item slots

    // Combined over time.
    std::optional<bool> failed;          ///< the verdict: P when the worst grade fails
    std::optional<DamageGrade> grade;    ///< the worst grade over the snapshots
    std::optional<double> failureTimeUs; ///< first snapshot with a failing grade
    bool axisBandOnly = false;           ///< failed, and every sign of it in the axis band
    double spallRadiusMm = 0.0;          ///< largest detached-spall radius over the snapshots
    double spallMassMg = 0.0;            ///< largest detached-spall mass over the snapshots
    double bulgeMm = 0.0;                ///< largest bulge over the snapshots
    bool atRest = false;                 ///< the wall and what approaches it, at the end
    /// The solver stopped on its own rear-wall perforation rule, which the assessment does not
    /// confirm: the run ended when material was behind the rear face, so an NP is provisional.
    bool solverStopUnconfirmed = false;
    std::optional<bool> rearWallPerforated;
    std::optional<double> perforationTimeUs;
    bool throughThicknessFailure = false, materialCrossed = false, detachedSpall = false;
    std::size_t openColumns = 0;      ///< most rear-wall columns open through (any snapshot)
    double openRadiusMm = 0.0;        ///< outermost open column's outer edge (any snapshot)
    double perforationRadiusMm = 0.0; ///< largest perforation radius over the snapshots
    bool axisConfined = false;        ///< perforated, and within the axis band in every snapshot
    std::optional<double> penetrationDepthMm;
    std::optional<std::size_t> deepestBody;
    std::vector<std::size_t> reachedBodies, perforatedLayers;
    std::optional<double> debrisDepthMm;
    std::optional<double> coreDamageWidthMm;

    // History.
    io::HistoryColumns history;
    EnergyBudget energy;

    // Final snapshot.
    double initialMassMg = 0.0, deletedMassMg = 0.0;
    std::size_t particles = 0, aliveParticles = 0, deletedParticles = 0;
    std::size_t nodes = 0, elements = 0, aliveElements = 0;

    // For pictures: the first snapshot and the kept ones.
    io::Snapshot first;
    std::vector<io::Snapshot> kept;

    std::vector<std::string> warnings;

    const SnapshotMetrics& last() const { return series.back(); }
};

Assessment assessRun(const io::RunFileReader& reader, const AssessOptions& options);

} // namespace hvi::assess
