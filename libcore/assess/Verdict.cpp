#include "assess/Verdict.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::assess {

using nlohmann::json;

namespace {

/// A number, or null when absent or not finite (JSON has no NaN).
json num(std::optional<double> v) {
    return v && std::isfinite(*v) ? json(*v) : json(nullptr);
}

json bodyNames(const Assessment& a, const std::vector<std::size_t>& bodies) {
    json names = json::array();
    for (auto b : bodies) {
        names.push_back(a.layout.bodies[b].name);
    }
    return names;
}

/// How the verdict was reached; null without a rear wall.
json rearWallJson(const Assessment& a) {
    if (!a.layout.rearWall) {
        return nullptr;
    }
    const BodyLayout& w = a.layout.bodies[*a.layout.rearWall];
    const auto reason = a.runFacts.find("stop_reason");
    const json perforationRadius =
        a.rearWallPerforated.value_or(false) ? json(a.perforationRadiusMm) : json(nullptr);
    return {{"body", w.name},
            {"thickness_mm", w.thickness()},
            {"perforated", a.rearWallPerforated.value_or(false)},
            {"first_perforated_time_us", num(a.perforationTimeUs)},
            {"through_thickness_failure", a.throughThicknessFailure},
            {"material_crossed", a.materialCrossed},
            {"damage_grade", std::string(toString(*a.grade))},
            {"first_failed_time_us", num(a.failureTimeUs)},
            {"detached_spall", a.detachedSpall},
            {"spall_mass_mg", a.spallMassMg},
            {"spall_radius_mm", a.detachedSpall ? json(a.spallRadiusMm) : json(nullptr)},
            {"bulge_mm", a.bulgeMm},
            {"at_rest", a.atRest},
            {"end_wall_speed_km_s", a.last().rearWall->wallMaxSpeedKmS},
            {"end_approaching_items", a.last().rearWall->approachingItems},
            {"end_approaching_speed_km_s", a.last().rearWall->approachingMaxSpeedKmS},
            {"open_columns", a.openColumns},
            {"open_radius_mm", a.openRadiusMm},
            {"perforation_radius_mm", perforationRadius},
            {"axis_confined", a.axisConfined},
            {"solver_stop_rule_fired",
             a.hasRunFacts && reason != a.runFacts.end() && *reason == "rear_wall_perforated"}};
}

} // namespace

json verdictJson(const Assessment& a) {
    const ShieldLayout& L = a.layout;
    const SnapshotMetrics& last = a.last();
    json v;
    v["format"] = "hvi-verdict";
    v["format_version"] = 1;
    v["verdict"] = a.failed ? json(*a.failed ? "P" : "NP") : json(nullptr);
    v["damage_grade"] = a.grade ? json(std::string(toString(*a.grade))) : json(nullptr);
    v["perforation_verdict"] =
        a.rearWallPerforated ? json(*a.rearWallPerforated ? "P" : "NP") : json(nullptr);
    v["rear_wall_perforated"] = a.rearWallPerforated ? json(*a.rearWallPerforated) : json(nullptr);
    v["axis_band_only"] = a.failed ? json(a.axisBandOnly) : json(nullptr);
    // P stands once reached; NP only once the run finished with the wall at rest.
    v["verdict_final"] =
        a.failed ? json(*a.failed || (a.complete && a.atRest && !a.solverStopUnconfirmed))
                 : json(nullptr);
    v["complete"] = a.complete;
    v["run_status"] = a.status;
    const auto stop = a.runFacts.find("stop_reason");
    v["stop_reason"] =
        a.hasRunFacts && stop != a.runFacts.end() && stop->is_string() ? *stop : json(nullptr);
    v["scene_id"] = L.sceneId;
    v["run_file"] = a.runFile;
    v["final_time_us"] = last.timeUs;
    v["end_time_us"] = L.endTimeUs;
    v["snapshot_count"] = a.series.size();
    v["penetration_depth_mm"] = num(a.penetrationDepthMm);
    v["debris_depth_mm"] = num(a.debrisDepthMm);
    v["bumper_hole_diameter_mm"] = last.hole ? json(last.hole->diameterMm) : json(nullptr);
    v["core_damage_width_mm"] = num(a.coreDamageWidthMm);
    v["energy_error"] = num(a.energy.maxError);
    const auto wall = a.runFacts.find("wall_time_s");
    v["wall_time_s"] =
        a.hasRunFacts && wall != a.runFacts.end() && wall->is_number() ? *wall : json(nullptr);

    // Debris cloud.
    const DebrisCloud& d = last.debris;
    const bool cloud = d.items > 0;
    auto cloudNum = [&](double x) { return cloud ? num(x) : json(nullptr); };
    json history = json::array();
    for (const auto& m : a.series) {
        const bool has = m.debris.items > 0;
        history.push_back(
            {{"time_us", m.timeUs},
             {"mass_mg", m.debris.massMg},
             {"leading_edge_z_mm", has ? num(m.debris.leadingEdgeZMm) : json(nullptr)},
             {"leading_edge_speed_km_s", has ? num(m.debris.leadingEdgeSpeedKmS) : json(nullptr)}});
    }
    v["debris_cloud"] = {{"time_us", d.timeUs},
                         {"items", d.items},
                         {"mass_mg", d.massMg},
                         {"leading_edge_z_mm", cloudNum(d.leadingEdgeZMm)},
                         {"leading_edge_depth_mm", cloudNum(d.leadingEdgeDepthMm)},
                         {"leading_edge_speed_km_s", cloudNum(d.leadingEdgeSpeedKmS)},
                         {"max_axial_speed_km_s", cloudNum(d.maxAxialSpeedKmS)},
                         {"radius_mm", cloudNum(d.radiusMm)},
                         {"centre_of_mass_z_mm", cloudNum(d.centreOfMassZMm)},
                         {"centre_of_mass_speed_km_s", cloudNum(d.centreOfMassSpeedKmS)},
                         {"history", history}};

    v["rear_wall"] = rearWallJson(a);

    // Penetration.
    if (a.penetrationDepthMm) {
        v["penetration"] = {
            {"reference_z_mm", L.depthOriginZ()},
            {"depth_mm", *a.penetrationDepthMm},
            {"deepest_body", a.deepestBody ? json(L.bodies[*a.deepestBody].name) : json(nullptr)},
            {"bodies_reached", bodyNames(a, a.reachedBodies)},
            {"core_bodies", L.core.size()},
            {"layers_perforated", bodyNames(a, a.perforatedLayers)},
            {"debris_depth_mm", num(a.debrisDepthMm)}};
    } else {
        v["penetration"] = nullptr;
    }

    // Bumper hole.
    if (last.hole) {
        const BodyLayout& b = L.bodies[*L.bumper];
        json holeHistory = json::array();
        for (const auto& m : a.series) {
            holeHistory.push_back({{"time_us", m.timeUs},
                                   {"diameter_mm", m.hole->diameterMm},
                                   {"failed_zone_diameter_mm", m.hole->failedZoneDiameterMm}});
        }
        v["bumper_hole"] = {{"body", b.name},
                            {"thickness_mm", b.thickness()},
                            {"diameter_mm", last.hole->diameterMm},
                            {"failed_zone_diameter_mm", last.hole->failedZoneDiameterMm},
                            {"bin_width_mm", last.hole->binWidthMm},
                            {"reaches_edge", last.hole->reachesEdge},
                            {"history", holeHistory}};
    } else {
        v["bumper_hole"] = nullptr;
    }

    const EnergyBudget& e = a.energy;
    v["energy"] = {{"history_rows", e.rows},
                   {"max_error", num(e.maxError)},
                   {"max_error_time_us", num(e.maxErrorTimeUs)},
                   {"final_error", num(e.finalError)},
                   {"initial_total_J", num(e.initialTotalEnergyJ)},
                   {"final_total_J", num(e.finalTotalEnergyJ)},
                   {"deleted_J", num(e.deletedEnergyJ)},
                   {"initial_momentum_z_mg_km_s", num(e.initialMomentumZ)},
                   {"final_momentum_z_mg_km_s", num(e.finalMomentumZ)}};

    v["mass"] = {
        {"initial_mg", a.initialMassMg},
        {"deleted_mg", a.deletedMassMg},
        {"deleted_fraction", a.initialMassMg > 0.0 ? a.deletedMassMg / a.initialMassMg : 0.0},
        {"deleted_particles", a.deletedParticles},
        {"eroded_elements", a.elements - a.aliveElements}};

    double minSpacing = L.particleSpacing;
    for (const auto& b : L.bodies) {
        minSpacing = std::min(minSpacing, b.spacing);
    }
    auto across = [&](const std::optional<std::size_t>& b) {
        return b ? json(L.bodies[*b].thickness() / L.bodies[*b].spacing) : json(nullptr);
    };
    v["resolution"] = {{"particle_spacing_mm", L.particleSpacing},
                       {"min_spacing_mm", minSpacing},
                       {"smoothing_length_factor", L.smoothingLengthFactor},
                       {"element_size_mm", num(L.elementSize)},
                       {"bumper_items_across", across(L.bumper)},
                       {"rear_wall_items_across", across(L.rearWall)}};
    v["counts"] = {{"particles", a.particles},
                   {"alive_particles", a.aliveParticles},
                   {"nodes", a.nodes},
                   {"elements", a.elements},
                   {"alive_elements", a.aliveElements}};
    v["run"] = a.hasRunFacts ? a.runFacts : json(nullptr);
    v["solver"] = a.code.is_object() ? a.code : json(nullptr);
    v["criteria"] = a.criteria.toJson();
    v["warnings"] = a.warnings;
    return v;
}

} // namespace hvi::assess
