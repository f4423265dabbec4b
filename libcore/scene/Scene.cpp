#include "scene/Scene.hpp"

#include "io/JsonInput.hpp"
#include "scene/BodyLayout.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace hvi::scene {

using nlohmann::json;

double Shape::boundZMin() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return centerZ - radius;
    case ShapeKind::Plate:
        return zFront;
    case ShapeKind::Rectangle:
        return zMin;
    }
    return 0.0;
}
double Shape::boundZMax() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return centerZ + radius;
    case ShapeKind::Plate:
        return zFront + thickness;
    case ShapeKind::Rectangle:
        return zMax;
    }
    return 0.0;
}
double Shape::boundRMin() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return 0.0;
    case ShapeKind::Plate:
        return innerRadius;
    case ShapeKind::Rectangle:
        return rMin;
    }
    return 0.0;
}
double Shape::boundRMax() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return radius;
    case ShapeKind::Plate:
        return outerRadius;
    case ShapeKind::Rectangle:
        return rMax;
    }
    return 0.0;
}

bool Scene::hasFeBodies() const {
    return std::any_of(bodies.begin(), bodies.end(),
                       [](const Body& b) { return b.discretization == Discretization::Fe; });
}

double Scene::maxInitialSpeed() const {
    double v = 0.0;
    for (const auto& b : bodies) {
        v = std::max(v, std::hypot(b.velocityZ, b.velocityR));
    }
    return v;
}

std::string roleName(BodyRole role) {
    switch (role) {
    case BodyRole::Projectile:
        return "projectile";
    case BodyRole::Bumper:
        return "bumper";
    case BodyRole::CoreLayer:
        return "core_layer";
    case BodyRole::CoreRing:
        return "core_ring";
    case BodyRole::RearWall:
        return "rear_wall";
    case BodyRole::Witness:
        return "witness";
    case BodyRole::Other:
        return "other";
    }
    return "other";
}

namespace {

BodyRole parseRole(const std::string& s) {
    static const std::pair<const char*, BodyRole> table[] = {
        {"projectile", BodyRole::Projectile}, {"bumper", BodyRole::Bumper},
        {"core_layer", BodyRole::CoreLayer},  {"core_ring", BodyRole::CoreRing},
        {"rear_wall", BodyRole::RearWall},    {"witness", BodyRole::Witness}};
    for (const auto& [name, role] : table) {
        if (s == name) {
            return role;
        }
    }
    return BodyRole::Other;
}

Shape parseShape(const json& j) {
    Shape s;
    const std::string type = j.at("type");
    if (type == "sphere") {
        s.kind = ShapeKind::Sphere;
        s.centerZ = j.at("center_z_mm");
        s.radius = j.at("radius_mm");
    } else if (type == "plate") {
        s.kind = ShapeKind::Plate;
        s.zFront = j.at("z_front_mm");
        s.thickness = j.at("thickness_mm");
        s.innerRadius = j.value("inner_radius_mm", 0.0);
        s.outerRadius = j.value("outer_radius_mm", 0.0); // 0: the domain radius, set later
    } else {
        s.kind = ShapeKind::Rectangle;
        s.zMin = j.at("z_min_mm");
        s.zMax = j.at("z_max_mm");
        s.rMin = j.at("r_min_mm");
        s.rMax = j.at("r_max_mm");
    }
    return s;
}

} // namespace

namespace {

/// The numerical blocks: sph, fe, run, output and domain.
void parseControls(const json& doc, Scene& scene) {
    const json& sph = doc.at("sph");
    scene.sph.particleSpacing = sph.at("particle_spacing_mm");
    scene.sph.kernel = sph.at("kernel");
    scene.sph.smoothingLengthFactor = sph.at("smoothing_length_factor");
    scene.sph.avAlpha = sph.at("av_alpha");
    scene.sph.avBeta = sph.at("av_beta");
    scene.sph.minDensityRatio = sph.at("min_density_ratio");
    scene.sph.runawaySpeedFactor = sph.at("runaway_speed_factor");
    scene.sph.artificialStress = sph.at("artificial_stress");
    scene.sph.compatibleEnergyUpdate = sph.at("energy_update") == "compatible";
    scene.sph.timeBins = sph.at("time_stepping") == "bins";

    const json& fe = doc.at("fe");
    scene.fe.elementSize = fe.value("element_size_mm", scene.sph.particleSpacing);
    scene.fe.erosionFactor = fe.at("erosion_factor");
    scene.fe.hourglassCoefficient = fe.at("hourglass_coefficient");
    scene.fe.bulkViscosityLinear = fe.at("bulk_viscosity_linear");
    scene.fe.bulkViscosityQuadratic = fe.at("bulk_viscosity_quadratic");
    scene.fe.erodedToParticles = fe.at("eroded_material") == "particles";
    scene.fe.instantaneousErosionStrain = fe.at("erosion_strain") == "instantaneous";
    scene.fe.timeBins = fe.at("time_stepping") == "bins";

    const json& run = doc.at("run");
    scene.run.endTime = run.at("end_time_us");
    scene.run.cfl = run.at("cfl");
    scene.run.stopDebrisSpeed = run.at("stop_debris_speed_km_s");
    scene.run.stopNoNewPenetration = run.at("stop_no_new_penetration_us");
    scene.run.stopOnRearWallPerforation = run.at("stop_on_rear_wall_perforation");
    scene.run.maxSteps = run.at("max_steps");

    const json& out = doc.at("output");
    scene.output.snapshotEvery = out.at("snapshot_every_us");
    scene.output.historyEverySteps = out.at("history_every_steps");

    const json& domain = doc.at("domain");
    scene.domain.radius = domain.value("radius_mm", 0.0);
    scene.domain.radiusReason = domain.value("radius_reason", "");
    if (domain.contains("z_min_mm")) {
        scene.domain.zMin = domain.at("z_min_mm").get<double>();
    }
    if (domain.contains("z_max_mm")) {
        scene.domain.zMax = domain.at("z_max_mm").get<double>();
    }
}

Body parseBody(const json& jb, const Scene& scene) {
    Body b;
    b.name = jb.at("name");
    b.role = parseRole(jb.at("role"));
    b.shape = parseShape(jb.at("shape"));
    b.material = jb.at("material");
    b.discretization = jb.at("discretization") == "fe" ? Discretization::Fe : Discretization::Sph;
    b.velocityZ = jb.at("velocity").at("z_km_s");
    b.velocityR = jb.at("velocity").at("r_km_s");
    b.spacing =
        jb.value("spacing_mm", b.discretization == Discretization::Fe ? scene.fe.elementSize
                                                                      : scene.sph.particleSpacing);
    b.erosionFactor = jb.value("erosion_factor", scene.fe.erosionFactor);
    b.strength = jb.at("strength");
    return b;
}

/// What is wrong with body b on its own (its shape, material, resolution and velocity).
void checkBody(const Body& b, const Scene& scene, const std::set<std::string>& materials,
               const std::string& file, const std::string& ptr, std::vector<InputIssue>& issues) {
    if (!materials.count(b.material)) {
        std::string known;
        for (const auto& m : materials) {
            known += (known.empty() ? "" : ", ") + m;
        }
        issues.push_back({file, ptr + "/material", "unknown material '" + b.material + "'",
                          "one of: " + known + "; or define it under /materials"});
    }
    if (b.shape.kind == ShapeKind::Plate && b.shape.outerRadius > 0.0 &&
        b.shape.outerRadius <= b.shape.innerRadius) {
        issues.push_back({file, ptr + "/shape/outer_radius_mm",
                          "outer radius not larger than the inner radius",
                          "outer_radius_mm > inner_radius_mm"});
    }
    if (b.shape.kind == ShapeKind::Rectangle &&
        (b.shape.zMax <= b.shape.zMin || b.shape.rMax <= b.shape.rMin)) {
        issues.push_back({file, ptr + "/shape", "empty rectangle",
                          "z_max_mm > z_min_mm and r_max_mm > r_min_mm"});
    }
    // An SPH body needs two rows of points; an FE body is meshed with at least one element
    // through any thickness (geometry::GmshMesher::divisions rounds up), so a foam layer
    // thinner than the spacing is a thin mesh, not an unresolved body.
    if (b.discretization == Discretization::Sph && b.shape.kind != ShapeKind::Sphere &&
        b.spacing * 2.0 > b.shape.boundZMax() - b.shape.boundZMin()) {
        issues.push_back({file, ptr + "/shape",
                          "thinner than two particle spacings (" + std::to_string(b.spacing) +
                              " mm): it cannot be resolved",
                          "a thicker body or a smaller spacing_mm"});
    }
    // In axisymmetry a part of a shield or its projectile that reaches the axis cannot move
    // radially as a whole (issue #25, item 9). A body of role "other" may: a converging flow
    // such as the cylindrical Noh problem starts that way.
    if (scene.geometry == Geometry::Axisymmetric && b.role != BodyRole::Other &&
        b.velocityR != 0.0 && b.shape.boundRMin() <= 0.0) {
        issues.push_back({file, ptr + "/velocity/r_km_s",
                          "a radial velocity on a body that reaches the axis",
                          "0 in axisymmetric geometry (or a body off the axis)"});
    }
}

/// The domain radius: given, or the widest body plus a margin of 10 % (plates with no outer
/// radius need it); plates with no outer radius then reach it.
void settleDomainRadius(Scene& scene, const std::string& file, std::vector<InputIssue>& issues) {
    double widest = 0.0;
    for (const auto& b : scene.bodies) {
        widest = std::max(widest, b.shape.boundRMax());
    }
    if (scene.domain.radius <= 0.0) {
        if (widest <= 0.0) {
            issues.push_back({file, "/domain/radius_mm",
                              "no domain radius and no body with an outer radius",
                              "domain.radius_mm [mm] or plates with outer_radius_mm"});
        }
        scene.domain.radius = 1.1 * widest;
        scene.domain.radiusReason = "10 % beyond the widest body (no radius given)";
    }
    for (auto& b : scene.bodies) {
        if (b.shape.kind == ShapeKind::Plate && b.shape.outerRadius <= 0.0) {
            b.shape.outerRadius = scene.domain.radius;
        }
    }
}

} // namespace

Scene parseScene(const json& document, const std::string& file,
                 const std::vector<std::string>& knownMaterials) {
    io::requireFiniteNumbers(document, file);
    io::validateAgainstSchema(document, "scene", file);
    const json doc = io::withSchemaDefaults(document, "scene");

    Scene scene;
    scene.resolved = doc;
    scene.id = doc.at("id");
    scene.description = doc.value("description", "");
    scene.geometry = doc.at("geometry") == "planar" ? Geometry::Planar : Geometry::Axisymmetric;
    scene.materials = doc.at("materials");
    parseControls(doc, scene);

    std::set<std::string> materials(knownMaterials.begin(), knownMaterials.end());
    for (const auto& [name, def] : scene.materials.items()) {
        materials.insert(name);
    }
    std::vector<InputIssue> issues;
    if (scene.sph.timeBins && scene.sph.compatibleEnergyUpdate) {
        // The compatible update pays each pair's work at one step for both particles.
        issues.push_back({file, "/sph/time_stepping",
                          "time-step bins do not combine with energy_update 'compatible'",
                          "\"time_stepping\": \"global\", or \"energy_update\": \"trapezoid\""});
    }
    std::set<std::string> names;
    const json& bodies = doc.at("bodies");
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        const std::string ptr = "/bodies/" + std::to_string(k);
        const Body b = parseBody(bodies[k], scene);
        if (!names.insert(b.name).second) {
            issues.push_back({file, ptr + "/name", "duplicate body name '" + b.name + "'",
                              "names unique within the scene"});
        }
        checkBody(b, scene, materials, file, ptr, issues);
        scene.bodies.push_back(b);
    }
    settleDomainRadius(scene, file, issues);
    if (issues.empty()) { // overlaps and the domain, once every shape is sound
        issues = bodyLayoutIssues(scene, file);
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
    return scene;
}

} // namespace hvi::scene
