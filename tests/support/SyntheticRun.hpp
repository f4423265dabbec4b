// Small run files with known answers, for the hvi-assess tests: a scene document, its particle
// lattice made by the solver's own generator (sph::fillBody, so the lattice is the one a real
// run starts from), snapshots that are copies of that lattice edited by the test (holes cut,
// layers failed, debris moved), a short history, and one of the three endings of a run
// (finished, interrupted, killed outright). Written with io::RunFileWriter.
#pragma once

#include "SceneRun.hpp"
#include "TestPaths.hpp"
#include "io/RunFileWriter.hpp"
#include "sph/ParticleGenerator.hpp"
#include "sph/ParticleSet.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::test {

/// The fields of a particle set as the run file stores them. Damage and plastic strain are
/// written (zero) even for a strengthless set, so tests can set them.
inline io::ParticleFields fieldsOf(const sph::ParticleSet& ps) {
    io::ParticleFields f;
    const std::size_t n = ps.size();
    f.z = ps.z;
    f.r = ps.r;
    f.vz = ps.vz;
    f.vr = ps.vr;
    f.mass = ps.mass;
    f.density = ps.rho;
    f.pressure = ps.p;
    f.internalEnergy = ps.e;
    f.smoothingLength = ps.h;
    f.damage = ps.damage;
    f.damage.resize(n, 0.0); // zero when the set has no strength arrays
    f.plasticStrain = ps.plasticStrain;
    f.plasticStrain.resize(n, 0.0);
    if (ps.hasStrength()) {
        f.stressDeviator.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i) {
            f.stressDeviator[3 * i] = ps.szz[i];
            f.stressDeviator[3 * i + 1] = ps.srr[i];
            f.stressDeviator[3 * i + 2] = ps.srz[i];
        }
    }
    f.bodyId = ps.body;
    f.alive = ps.alive;
    return f;
}

/// A plate body (role, z front, thickness, outer radius) for a test scene.
inline nlohmann::json plateBody(const std::string& name, const std::string& role, double zFront,
                                double thickness, double outerRadius, double innerRadius = 0.0) {
    return {{"name", name},
            {"role", role},
            {"material", "Al6061-T6"},
            {"shape",
             {{"type", "plate"},
              {"z_front_mm", zFront},
              {"thickness_mm", thickness},
              {"inner_radius_mm", innerRadius},
              {"outer_radius_mm", outerRadius}}}};
}

/// A spherical projectile of radius `radius` just in front of z = 0, moving at `speed`.
inline nlohmann::json projectileBody(double radius, double speed) {
    return {{"name", "projectile"},
            {"role", "projectile"},
            {"material", "Al6061-T6"},
            {"shape", {{"type", "sphere"}, {"center_z_mm", -radius - 0.05}, {"radius_mm", radius}}},
            {"velocity", {{"z_km_s", speed}}}};
}

enum class Ending { Complete, Partial, Killed };

/// A structured mesh of quadrilaterals (one per lattice cell) for an FE plate or rectangle,
/// appended to `fe`: nodes at the cell corners with lumped ring masses, elements
/// counter-clockwise in (z, r).
inline void appendMesh(const scene::Body& body, std::int32_t bodyIndex, double rho0,
                       io::FeFields& fe) {
    const auto& s = body.shape;
    const double z0 = s.boundZMin(), z1 = s.boundZMax(), r0 = s.boundRMin(), r1 = s.boundRMax();
    const long nz = std::max(1L, std::lround((z1 - z0) / body.spacing));
    const long nr = std::max(1L, std::lround((r1 - r0) / body.spacing));
    const double dz = (z1 - z0) / static_cast<double>(nz), dr = (r1 - r0) / static_cast<double>(nr);
    const auto first = static_cast<std::int32_t>(fe.nodes.z.size());
    auto node = [&](long iz, long ir) {
        return first + static_cast<std::int32_t>(iz * (nr + 1) + ir);
    };
    for (long iz = 0; iz <= nz; ++iz) {
        for (long ir = 0; ir <= nr; ++ir) {
            fe.nodes.z.push_back(z0 + static_cast<double>(iz) * dz);
            fe.nodes.r.push_back(r0 + static_cast<double>(ir) * dr);
            fe.nodes.vz.push_back(0.0);
            fe.nodes.vr.push_back(0.0);
            fe.nodes.mass.push_back(0.0);
        }
    }
    for (long iz = 0; iz < nz; ++iz) {
        for (long ir = 0; ir < nr; ++ir) {
            const std::int32_t corners[4] = {node(iz, ir), node(iz + 1, ir), node(iz + 1, ir + 1),
                                             node(iz, ir + 1)};
            const double rc = r0 + (static_cast<double>(ir) + 0.5) * dr;
            const double m = 2.0 * 3.14159265358979323846 * rc * rho0 * dz * dr;
            for (auto c : corners) {
                fe.elements.connectivity.push_back(c);
                fe.nodes.mass[static_cast<std::size_t>(c)] += 0.25 * m;
            }
            fe.elements.alive.push_back(1);
            fe.elements.damage.push_back(0.0);
            fe.elements.plasticStrain.push_back(0.0);
            fe.elements.geometricStrain.push_back(0.0);
            fe.elements.pressure.push_back(0.0);
            fe.elements.density.push_back(rho0);
            fe.elements.bodyId.push_back(bodyIndex);
        }
    }
}

struct SyntheticRun {
    nlohmann::json sceneDoc;
    scene::Scene scene;
    io::ParticleFields initial;
    io::FeFields initialFe; ///< empty unless the scene has FE bodies
    std::vector<double> times;
    std::vector<io::ParticleFields> snapshots;
    std::vector<io::FeFields> feSnapshots; ///< one per snapshot (empty without FE bodies)
    std::vector<io::HistoryRow> history;
    std::string materialsText = "{}"; ///< the run file's /materials (the models the run used)

    /// Builds the lattice (SPH bodies) or mesh (FE bodies) of every body of `doc` and makes
    /// it snapshot 0 at t = 0.
    explicit SyntheticRun(nlohmann::json doc) : sceneDoc(std::move(doc)) {
        scene = makeScene(sceneDoc);
        sph::ParticleSet ps;
        const double rho0 = 2.703;
        for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
            if (scene.bodies[b].discretization == scene::Discretization::Fe) {
                appendMesh(scene.bodies[b], static_cast<std::int32_t>(b), rho0, initialFe);
                continue;
            }
            sph::fillBody(scene.bodies[b], static_cast<std::int32_t>(b), rho0, 0.0, 1.3,
                          scene.geometry == scene::Geometry::Axisymmetric, ps);
        }
        initial = fieldsOf(ps);
        times.push_back(0.0);
        snapshots.push_back(initial);
        feSnapshots.push_back(initialFe);
        // A quiet history: energy conserved to 1e-4, with one worse row in the middle.
        for (int k = 0; k < 5; ++k) {
            io::HistoryRow row{};
            row.timeUs = 0.5 * k;
            row.dtUs = 0.001;
            row.step = 500 * k;
            row.kineticEnergy = 10.0 - k;
            row.internalEnergy = 1.0 * k;
            row.totalEnergy = 10.0;
            row.energyError = k == 2 ? -3.0e-3 : 1.0e-4 * k;
            row.mass = 100.0;
            row.momentumZ = 50.0;
            row.aliveCount = static_cast<std::int64_t>(initial.z.size());
            history.push_back(row);
        }
    }

    /// Appends a copy of the initial lattice at time t and returns it for editing.
    io::ParticleFields& addSnapshot(double t) {
        times.push_back(t);
        snapshots.push_back(initial);
        feSnapshots.push_back(initialFe);
        return snapshots.back();
    }

    /// Index of body `name` in the scene.
    std::int32_t body(const std::string& name) const {
        for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
            if (scene.bodies[b].name == name) {
                return static_cast<std::int32_t>(b);
            }
        }
        throw std::runtime_error("no body " + name);
    }

    /// Applies `edit(i)` to every particle i of body `name` in `snap`.
    void forBody(const io::ParticleFields& snap, const std::string& name,
                 const std::function<void(std::size_t)>& edit) const {
        const auto b = body(name);
        for (std::size_t i = 0; i < snap.z.size(); ++i) {
            if (snap.bodyId[i] == b) {
                edit(i);
            }
        }
    }

    /// Writes the run file at `path` (replacing any) and returns the path.
    std::filesystem::path write(const std::filesystem::path& path, Ending ending = Ending::Complete,
                                const nlohmann::json& facts = {{"wall_time_s", 12.5},
                                                               {"threads", 2},
                                                               {"stop_reason", "end_time"},
                                                               {"steps", 2000}}) const {
        std::filesystem::remove(path);
        io::RunFileWriter writer(path, sceneDoc.dump(), materialsText,
                                 {{"tool", "test"}, {"input_file", "synthetic"}});
        for (std::size_t k = 0; k < snapshots.size(); ++k) {
            const io::FeFieldsView mesh = io::viewOf(feSnapshots[k]);
            const bool hasMesh = !feSnapshots[k].elements.alive.empty();
            writer.writeSnapshot(times[k], static_cast<long>(100 * k), io::viewOf(snapshots[k]),
                                 hasMesh ? &mesh : nullptr);
        }
        for (const auto& row : history) {
            writer.appendHistory(row);
        }
        switch (ending) {
        case Ending::Complete:
            writer.finish(facts);
            break;
        case Ending::Partial:
            writer.abandon(facts);
            break;
        case Ending::Killed:
            writer.flush();
            std::filesystem::copy_file(writer.tempPath(), path);
            break; // the writer deletes its temporary: only the copy without /run remains
        }
        return path;
    }
};

} // namespace hvi::test
