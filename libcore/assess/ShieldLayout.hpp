// What hvi-assess needs to know about the shield in a run: each body's role, its initial
// (z, r) extent, its particle spacing or element size and its reference density, and which
// bodies are the bumper, the core and the rear wall.
//
// Geometry comes from the scene stored in the run file (/scene, parsed and validated like an
// input: a run file whose scene does not parse is a bad run file). Reference densities come
// from the first snapshot (mass-weighted mean per body), so they are the densities the run
// actually started from whatever material library it used.
//
// Lengths mm, densities g/cm3 (docs/conventions.md).
#pragma once

#include "io/RunFileReader.hpp"
#include "scene/Scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hvi::assess {

struct BodyLayout {
    std::string name;
    scene::BodyRole role = scene::BodyRole::Other;
    bool fe = false;
    double zFront = 0.0, zRear = 0.0; ///< initial axial extent [mm]
    double rMin = 0.0, rMax = 0.0;    ///< initial radial extent [mm]
    double spacing = 0.0;             ///< particle spacing or element size [mm]
    double referenceDensity = 0.0;    ///< [g/cm3], from the first snapshot

    double thickness() const { return zRear - zFront; }
    double radialThickness() const { return rMax - rMin; }
    /// Whether the body is thinner across r than along z (a honeycomb ring wall).
    bool thinInR() const { return radialThickness() < thickness(); }
};

struct ShieldLayout {
    std::string sceneId;
    bool axisymmetric = true;
    std::vector<BodyLayout> bodies;
    std::optional<std::size_t> bumper;   ///< the frontmost body with role "bumper"
    std::optional<std::size_t> rearWall; ///< the rearmost body with role "rear_wall"
    std::vector<std::size_t> core;       ///< core_layer and core_ring bodies, front to back
    double minDensityRatio = 0.5;        ///< the scene's sph.min_density_ratio
    double particleSpacing = 0.0;        ///< the scene's sph.particle_spacing_mm
    double smoothingLengthFactor = 0.0;  ///< the scene's sph.smoothing_length_factor
    std::optional<double> elementSize;   ///< fe.element_size_mm when the scene has FE bodies
    double endTimeUs = 0.0;
    double stopDebrisSpeedKmS = 0.0; ///< the scene's run.stop_debris_speed_km_s
    double domainRadius = 0.0;

    /// The z from which depths are measured: the bumper's rear face, or (no bumper) the front
    /// face of the frontmost body that is not a projectile.
    double depthOriginZ() const;
    bool isTarget(std::size_t body) const; ///< any body but a projectile
};

/// Builds the layout from the run's parsed scene and its first snapshot (whose body ids must
/// already be checked against the scene).
ShieldLayout shieldLayout(const scene::Scene& scene, const io::Snapshot& first);

/// Parses /scene of a run file (validated as hvi-run validated it, with the scene's own
/// materials laid over the built-in library). Throws InputError at "/scene..." otherwise.
scene::Scene sceneOfRun(const io::RunFileReader& reader);

} // namespace hvi::assess
