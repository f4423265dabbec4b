// Shared scene parts; the frame and the two rules are documented in the header.
#include "geometry/SceneBuilder.hpp"

#include "core/Units.hpp"
#include "io/JsonInput.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hvi::geometry {

using nlohmann::json;

namespace {

/// Rounds up to a whole number, treating values within 1e-9 above a whole number as that
/// number (35.0000000001 from rounding must stay 35).
double roundUpWhole(double value) {
    return std::ceil(value - 1e-9);
}

/// "0.254" — the numbers in reasons and warnings.
std::string num(double value) {
    return formatNumber(value);
}

void requirePositive(double value, const char* what) {
    if (!(std::isfinite(value) && value > 0.0)) {
        throw std::invalid_argument(std::string("SceneBuilder: ") + what +
                                    " must be finite and > 0, got " + num(value));
    }
}

/// Footprint radius of the debris cone on the rear wall [mm] (header).
double coneFootprintMm(const ThreatSpec& threat, const PanelFrame& frame) {
    return 0.5 * threat.diameterMm + (frame.frontFacesheetMm + frame.coreThicknessMm) *
                                         std::tan(units::degToRad(kDebrisHalfAngleDeg));
}

/// Bodies thinner than 3 spacings cannot be represented (as in the reductions' warnings).
void checkResolution(std::vector<GeometryWarning>& warnings, const std::string& what,
                     double thicknessMm, double spacingMm) {
    if (thicknessMm < 3.0 * spacingMm) {
        warnings.push_back({WarningKind::UnderResolved,
                            what + " thickness " + num(thicknessMm) +
                                " mm is less than 3 particle spacings at " + num(spacingMm) +
                                " mm; resolving it needs a particle spacing <= " +
                                num(thicknessMm / 3.0) + " mm (thickness/3)"});
    }
}

} // namespace

std::string_view toString(Discretization discretization) {
    return discretization == Discretization::Fe ? "fe" : "sph";
}

std::optional<Discretization> parseDiscretization(std::string_view text) {
    if (text == "fe") {
        return Discretization::Fe;
    }
    if (text == "sph") {
        return Discretization::Sph;
    }
    return std::nullopt;
}

RuleValue domainRadiusRule(const ThreatSpec& threat, const PanelFrame& frame) {
    const double footprint = coneFootprintMm(threat, frame);
    const double fromCone = kDomainMarginFactor * footprint;
    const double floor = kMinDomainDiameters * threat.diameterMm;
    const double radius = roundUpWhole(std::max(fromCone, floor));
    RuleValue rule;
    rule.value = radius;
    rule.reason =
        "rule R = max(" + num(kDomainMarginFactor) + " x (d/2 + (t_front + S) tan " +
        num(kDebrisHalfAngleDeg) + " deg), " + num(kMinDomainDiameters) +
        " d), rounded up to whole mm: the debris cloud spreads in a cone of half-angle ~" +
        num(kDebrisHalfAngleDeg) +
        " deg (source study HITF04150: 30.5 mm damage width across a 50.8 mm core), whose "
        "footprint on the rear wall is d/2 + (t_front + S) tan " +
        num(kDebrisHalfAngleDeg) + " deg; the domain is " + num(kDomainMarginFactor) +
        " times wider so the cut plate edge and its release wave stay clear of the damage, "
        "and at least " +
        num(kMinDomainDiameters) +
        " projectile diameters for thin cores. Here d = " + num(threat.diameterMm) +
        " mm, t_front + S = " + num(frame.frontFacesheetMm + frame.coreThicknessMm) +
        " mm: footprint " + num(footprint) + " mm, " + num(kDomainMarginFactor) + " x footprint " +
        num(fromCone) + " mm, " + num(kMinDomainDiameters) + " d " + num(floor) +
        " mm -> R = " + num(radius) + " mm";
    return rule;
}

RuleValue endTimeRule(const ThreatSpec& threat, const PanelFrame& frame, double particleSpacingMm) {
    const double pathMm =
        particleSpacingMm + frame.frontFacesheetMm + frame.coreThicknessMm + frame.rearFacesheetMm;
    const double crossingUs = pathMm / threat.velocityKmS; // mm / (km/s) = µs
    const double endTime = roundUpWhole(kEndTimeCrossingFactor * crossingUs + kEndTimeMarginUs);
    RuleValue rule;
    rule.value = endTime;
    rule.reason = "rule T = " + num(kEndTimeCrossingFactor) + " L/V + " + num(kEndTimeMarginUs) +
                  " us, rounded up to whole us, L = projectile nose to rear face of the rear "
                  "wall: L/V is the leading debris' crossing time at the impact speed, the "
                  "factor " +
                  num(kEndTimeCrossingFactor) +
                  " lets a cloud that a core slows to a tenth of the impact speed on average "
                  "arrive (the source study's foam panel HITF03147-2: a fifth on the way to "
                  "its rear facesheet, still pushing it at the former 5 L/V + 5 us), the " +
                  num(kEndTimeMarginUs) +
                  " us margin lets the rear wall respond to rest; hvi-run's stop rules end the "
                  "run earlier when nothing more happens. Here L = " +
                  num(pathMm) + " mm, V = " + num(threat.velocityKmS) +
                  " km/s, L/V = " + num(crossingUs) + " us -> T = " + num(endTime) + " us";
    return rule;
}

std::string indexedBodyName(const std::string& stem, std::size_t index, std::size_t largest) {
    const std::size_t width = std::max<std::size_t>(2, std::to_string(largest).size());
    std::string digits = std::to_string(index);
    if (digits.size() < width) {
        digits.insert(0, width - digits.size(), '0');
    }
    return stem + "_" + digits;
}

json SceneBody::toJson() const {
    json shapeJson;
    if (shape == Shape::Sphere) {
        shapeJson = {{"type", "sphere"}, {"center_z_mm", centerZMm}, {"radius_mm", radiusMm}};
    } else {
        shapeJson = {{"type", "plate"},
                     {"z_front_mm", zFrontMm},
                     {"thickness_mm", thicknessMm},
                     {"inner_radius_mm", innerRadiusMm},
                     {"outer_radius_mm", outerRadiusMm}};
    }
    return {{"name", name},
            {"role", role},
            {"shape", shapeJson},
            {"material", material},
            {"discretization", toString(discretization)},
            {"velocity", {{"z_km_s", velocityZKmS}, {"r_km_s", 0.0}}},
            {"strength", true}};
}

SceneBuilder::SceneBuilder(ThreatSpec threat, PanelFrame frame, SceneNumerics numerics)
    : m_threat(std::move(threat)), m_frame(std::move(frame)), m_numerics(numerics) {
    requirePositive(m_threat.diameterMm, "threat diameter");
    requirePositive(m_threat.velocityKmS, "threat velocity");
    if (m_frame.bumper) {
        requirePositive(m_frame.frontFacesheetMm, "front facesheet thickness");
        requirePositive(m_frame.coreThicknessMm, "core thickness");
    } else {
        m_frame.frontFacesheetMm = 0.0;
        m_frame.coreThicknessMm = 0.0;
    }
    requirePositive(m_frame.rearFacesheetMm, "rear facesheet thickness");
    requirePositive(m_numerics.particleSpacingMm, "particle spacing");
    requirePositive(m_numerics.erosionFactor, "erosion factor");
    if (std::isnan(m_numerics.domainRadiusMm)) {
        m_domainRadius = domainRadiusRule(m_threat, m_frame);
    } else {
        requirePositive(m_numerics.domainRadiusMm, "domain radius");
        m_domainRadius = {m_numerics.domainRadiusMm, "given in the input (domain_radius_mm)"};
    }
    if (std::isnan(m_numerics.endTimeUs)) {
        m_endTime = endTimeRule(m_threat, m_frame, m_numerics.particleSpacingMm);
    } else {
        requirePositive(m_numerics.endTimeUs, "end time");
        m_endTime = {m_numerics.endTimeUs, "given in the input (end_time_us)"};
    }
}

void SceneBuilder::addCoreBody(std::string name, std::string role, std::string material,
                               double zFrontCoreMm, double thicknessMm, double innerRadiusMm,
                               double outerRadiusMm) {
    requirePositive(thicknessMm, "core body thickness");
    requirePositive(outerRadiusMm - innerRadiusMm, "core body radial extent");
    if (!(innerRadiusMm >= 0.0) || !std::isfinite(zFrontCoreMm)) {
        throw std::invalid_argument("SceneBuilder: core body '" + name +
                                    "' needs a finite z and an inner radius >= 0");
    }
    SceneBody body;
    body.name = std::move(name);
    body.role = std::move(role);
    body.shape = SceneBody::Shape::Plate;
    body.zFrontMm = m_frame.frontFacesheetMm + zFrontCoreMm;
    body.thicknessMm = thicknessMm;
    body.innerRadiusMm = innerRadiusMm;
    body.outerRadiusMm = outerRadiusMm;
    body.material = std::move(material);
    body.discretization = m_numerics.coreDiscretization;
    m_core.push_back(std::move(body));
}

std::vector<SceneBody> SceneBuilder::bodies() const {
    std::vector<SceneBody> all;
    SceneBody projectile;
    projectile.name = "projectile";
    projectile.role = "projectile";
    projectile.shape = SceneBody::Shape::Sphere;
    projectile.radiusMm = 0.5 * m_threat.diameterMm;
    projectile.centerZMm = -(projectile.radiusMm + m_numerics.particleSpacingMm);
    projectile.material = m_threat.material;
    projectile.discretization = Discretization::Sph;
    projectile.velocityZKmS = m_threat.velocityKmS;
    all.push_back(projectile);

    if (m_frame.bumper) {
        SceneBody bumper;
        bumper.name = "front_facesheet";
        bumper.role = "bumper";
        bumper.zFrontMm = 0.0;
        bumper.thicknessMm = m_frame.frontFacesheetMm;
        bumper.outerRadiusMm = m_domainRadius.value;
        bumper.material = m_frame.frontFacesheetMaterial;
        bumper.discretization = Discretization::Sph;
        all.push_back(bumper);
    }

    all.insert(all.end(), m_core.begin(), m_core.end());

    SceneBody rear;
    rear.name = m_frame.bumper ? "rear_facesheet" : "wall";
    rear.role = "rear_wall";
    rear.zFrontMm = m_frame.frontFacesheetMm + m_frame.coreThicknessMm;
    rear.thicknessMm = m_frame.rearFacesheetMm;
    rear.outerRadiusMm = m_domainRadius.value;
    rear.material = m_frame.rearFacesheetMaterial;
    rear.discretization = m_numerics.rearWallDiscretization;
    all.push_back(rear);
    return all;
}

std::vector<MeshRectangle> SceneBuilder::feRectangles() const {
    std::vector<MeshRectangle> rectangles;
    for (const auto& body : bodies()) {
        if (body.discretization != Discretization::Fe || body.shape != SceneBody::Shape::Plate) {
            continue;
        }
        rectangles.push_back({body.name, body.zFrontMm, body.zFrontMm + body.thicknessMm,
                              body.innerRadiusMm, body.outerRadiusMm,
                              m_numerics.particleSpacingMm});
    }
    return rectangles;
}

std::vector<GeometryWarning> SceneBuilder::warnings() const {
    std::vector<GeometryWarning> out;
    if (m_frame.bumper) {
        checkResolution(out, "front facesheet", m_frame.frontFacesheetMm,
                        m_numerics.particleSpacingMm);
    }
    checkResolution(out, "rear facesheet", m_frame.rearFacesheetMm, m_numerics.particleSpacingMm);
    const double across = m_threat.diameterMm / m_numerics.particleSpacingMm;
    if (across < kMinProjectileSpacings) {
        out.push_back({WarningKind::UnderResolved,
                       "projectile diameter " + num(m_threat.diameterMm) + " mm is " +
                           num(std::round(10.0 * across) / 10.0) + " particle spacings across at " +
                           num(m_numerics.particleSpacingMm) + " mm, fewer than " +
                           num(kMinProjectileSpacings) +
                           ": its energy and verdict are not to be trusted; resolving it needs a "
                           "particle spacing <= " +
                           num(m_threat.diameterMm / kMinProjectileSpacings) + " mm"});
    }
    const double footprint = coneFootprintMm(m_threat, m_frame);
    if (m_domainRadius.value < footprint) {
        out.push_back({WarningKind::UnderResolved,
                       "domain radius " + num(m_domainRadius.value) +
                           " mm is inside the expected debris-cloud footprint on the rear wall (" +
                           num(footprint) +
                           " mm): material leaving the domain is deleted and the verdict may be "
                           "wrong; the rule would give " +
                           num(domainRadiusRule(m_threat, m_frame).value) + " mm"});
    }
    return out;
}

json SceneBuilder::sceneJson(const std::string& id, const std::string& description, json summary,
                             json provenance) const {
    json bodiesJson = json::array();
    for (const auto& body : bodies()) {
        bodiesJson.push_back(body.toJson());
    }
    summary["domain_radius_mm"] = m_domainRadius.value;
    summary["domain_radius_reason"] = m_domainRadius.reason;
    summary["end_time_us"] = m_endTime.value;
    summary["end_time_reason"] = m_endTime.reason;
    json scene = {
        {"id", id},
        {"description", description},
        {"geometry", "axisymmetric"},
        {"domain", {{"radius_mm", m_domainRadius.value}, {"radius_reason", m_domainRadius.reason}}},
        {"bodies", bodiesJson},
        {"sph", {{"particle_spacing_mm", m_numerics.particleSpacingMm}}},
        {"fe", {{"erosion_factor", m_numerics.erosionFactor}}},
        {"run", {{"end_time_us", m_endTime.value}}},
        {"summary", std::move(summary)},
        {"provenance", std::move(provenance)},
    };
    return io::withSchemaDefaults(scene, "scene");
}

} // namespace hvi::geometry
