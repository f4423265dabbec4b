// The scene of one impact simulation, as read from scene.json (schemas/scene.schema.json):
// bodies with shapes, materials and discretisations, and the numerical controls.
//
// Lengths mm, times us, velocities km/s (docs/conventions.md). Parsing validates the file
// against the schema first (every structural problem with its JSON pointer), then checks
// what a schema cannot: unique names, known materials, bodies that do not overlap the axis
// wrongly, non-empty geometry.
#pragma once

#include "core/Error.hpp"
#include "scene/Defaults.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace hvi::scene {

enum class Geometry { Axisymmetric, Planar };
enum class ShapeKind { Sphere, Plate, Rectangle };
enum class Discretization { Sph, Fe };
enum class BodyRole { Projectile, Bumper, CoreLayer, CoreRing, RearWall, Witness, Other };

struct Shape {
    ShapeKind kind = ShapeKind::Plate;
    // Sphere.
    double centerZ = 0.0, radius = 0.0;
    // Plate (annulus): z from zFront to zFront + thickness, r from innerRadius to outerRadius.
    double zFront = 0.0, thickness = 0.0, innerRadius = 0.0, outerRadius = 0.0;
    // Rectangle in (z, r).
    double zMin = 0.0, zMax = 0.0, rMin = 0.0, rMax = 0.0;

    /// Axis-aligned bounds in (z, r).
    double boundZMin() const;
    double boundZMax() const;
    double boundRMin() const;
    double boundRMax() const;
};

struct Body {
    std::string name;
    BodyRole role = BodyRole::Other;
    Shape shape;
    std::string material;
    Discretization discretization = Discretization::Sph;
    double velocityZ = 0.0, velocityR = 0.0; ///< [km/s]
    double spacing = 0.0;                    ///< particle spacing or element size [mm]
    double erosionFactor = 0.0;              ///< FE only [-]
    bool strength = true;
};

struct SphControls {
    double particleSpacing = kDefaultParticleSpacingMm;
    std::string kernel = "cubic_spline";
    double smoothingLengthFactor = 1.3;
    double avAlpha = 1.0, avBeta = 2.0;
    double minDensityRatio = 0.5;
    double runawaySpeedFactor = 2.0;
    double artificialStress = 0.0; ///< epsilon of Monaghan's artificial stress (0: off) [-]
    /// The half kicks pay each pair's work with their mean velocities (sph/PairWork.hpp).
    bool compatibleEnergyUpdate = false;
    /// Each particle steps at its own power-of-two multiple of the scene's step
    /// (solver/TimeBins.hpp).
    bool timeBins = false;
};

struct FeControls {
    double elementSize = 0.0;
    double erosionFactor = kDefaultErosionFactor;
    double hourglassCoefficient = 0.1;
    double bulkViscosityLinear = 0.06, bulkViscosityQuadratic = 1.5;
    /// Eroded elements become SPH particles (true) or leave free nodes (false).
    bool erodedToParticles = true;
    /// Geometric strain for erosion: the current strain (true) or the integral of the
    /// strain rate (false).
    bool instantaneousErosionStrain = true;
    /// Each element steps over its own power-of-two multiple of the scene's step
    /// (solver/FePackage.hpp).
    bool timeBins = false;
};

struct RunControls {
    double endTime = 10.0; ///< [us]
    double cfl = 0.3;
    double stopDebrisSpeed = 0.1;       ///< [km/s], 0 = off
    double stopNoNewPenetration = 0.25; ///< [us], 0 = off
    bool stopOnRearWallPerforation = true;
    long maxSteps = 100000000;
};

struct OutputControls {
    double snapshotEvery = 0.5; ///< [us]
    int historyEverySteps = 10;
};

struct Domain {
    double radius = 0.0; ///< [mm], 0 = derived from the bodies
    std::string radiusReason;
    std::optional<double> zMin, zMax;
};

struct Scene {
    std::string id = "scene";
    std::string description;
    Geometry geometry = Geometry::Axisymmetric;
    Domain domain;
    nlohmann::json materials = nlohmann::json::object(); ///< user material definitions
    std::vector<Body> bodies;
    SphControls sph;
    FeControls fe;
    RunControls run;
    OutputControls output;
    nlohmann::json resolved; ///< the input with defaults filled in (for the run file)

    bool hasFeBodies() const;
    /// Largest initial speed of any body [km/s] (reference for the runaway rule).
    double maxInitialSpeed() const;
};

/// Validates and converts a scene document. `file` names it in error messages.
/// `knownMaterials` are the library names (scene-defined materials are added to them).
Scene parseScene(const nlohmann::json& document, const std::string& file,
                 const std::vector<std::string>& knownMaterials);

std::string roleName(BodyRole role);

} // namespace hvi::scene
