#include "assess/Pictures.hpp"

#include "assess/RearWallDamageProfile.hpp"
#include "plot/Colormap.hpp"
#include "plot/SectionPicture.hpp"
#include "plot/XyPlot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace hvi::assess {

namespace fs = std::filesystem;
using scene::BodyRole;

std::vector<int> pictureSnapshots(const std::vector<io::SnapshotInfo>& snapshots,
                                  const std::vector<double>& timesUs) {
    std::vector<int> picked;
    if (snapshots.empty()) {
        return picked;
    }
    std::vector<double> times = timesUs;
    if (times.empty()) {
        const double last = snapshots.back().timeUs;
        times = {0.25 * last, 0.5 * last, 0.75 * last, last};
    }
    for (double t : times) {
        const auto nearest =
            std::min_element(snapshots.begin(), snapshots.end(), [&](const auto& a, const auto& b) {
                return std::fabs(a.timeUs - t) < std::fabs(b.timeUs - t);
            });
        picked.push_back(nearest->index);
    }
    std::sort(picked.begin(), picked.end());
    picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
    return picked;
}

namespace {

/// Colour of a body by its role; layers and rings alternate two shades so neighbours differ.
plot::Rgb bodyColor(const ShieldLayout& layout, std::size_t b) {
    const BodyLayout& body = layout.bodies[b];
    const auto position = std::find(layout.core.begin(), layout.core.end(), b);
    const bool odd = position != layout.core.end() && (position - layout.core.begin()) % 2 == 1;
    switch (body.role) {
    case BodyRole::Projectile:
        return {0.84, 0.15, 0.16};
    case BodyRole::Bumper:
        return {0.12, 0.47, 0.71};
    case BodyRole::CoreLayer:
        return odd ? plot::Rgb{0.55, 0.78, 0.35} : plot::Rgb{0.17, 0.63, 0.17};
    case BodyRole::CoreRing:
        return odd ? plot::Rgb{0.74, 0.74, 0.13} : plot::Rgb{0.55, 0.55, 0.05};
    case BodyRole::RearWall:
        return {0.58, 0.40, 0.74};
    case BodyRole::Witness:
        return {1.00, 0.50, 0.05};
    default:
        return plot::categorical(7 + b);
    }
}

std::vector<plot::LegendEntry> bodyLegend(const ShieldLayout& layout) {
    // One entry per role; a role with several bodies says how many.
    std::map<BodyRole, std::vector<std::size_t>> byRole;
    for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
        byRole[layout.bodies[b].role].push_back(b);
    }
    std::vector<plot::LegendEntry> legend;
    for (const auto& [role, bodies] : byRole) {
        std::string label =
            bodies.size() == 1
                ? layout.bodies[bodies.front()].name + " (" + scene::roleName(role) + ")"
                : std::to_string(bodies.size()) + " x " + scene::roleName(role);
        legend.push_back({label, bodyColor(layout, bodies.front())});
    }
    return legend;
}

/// The view: every body's initial extent along z, and the material present in the pictured
/// snapshots (so the debris cloud stays in frame); radially the same span as the z extent's
/// half, at least three projectile radii, at most the domain.
std::array<double, 3> viewOf(const Assessment& a, const std::vector<const io::Snapshot*>& shots) {
    const ShieldLayout& L = a.layout;
    double z0 = 1e300, z1 = -1e300, projectileR = 0.0;
    for (const auto& b : L.bodies) {
        z0 = std::min(z0, b.zFront);
        z1 = std::max(z1, b.zRear);
        if (b.role == BodyRole::Projectile) {
            projectileR = std::max(projectileR, b.rMax);
        }
    }
    for (const auto* s : shots) {
        const auto& p = s->particles;
        for (std::size_t i = 0; i < p.z.size(); ++i) {
            if (p.alive[i]) {
                z0 = std::min(z0, p.z[i]);
                z1 = std::max(z1, p.z[i]);
            }
        }
    }
    if (a.scene.domain.zMin) {
        z0 = std::max(z0, *a.scene.domain.zMin);
    }
    if (a.scene.domain.zMax) {
        z1 = std::min(z1, *a.scene.domain.zMax);
    }
    const double pad = 0.04 * (z1 - z0);
    z0 -= pad;
    z1 += pad;
    double r = std::max(0.5 * (z1 - z0), 3.0 * projectileR);
    if (L.domainRadius > 0.0) {
        r = std::min(r, L.domainRadius);
    }
    return {z0, z1, r};
}

std::string timeTag(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t%.3fus", t);
    return buf;
}

std::string timeStamp(double t) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "t = %.3f \xc2\xb5s", t); // micro sign, UTF-8
    return buf;
}

enum class Colouring { Body, Damage };

plot::SectionPicture sectionOf(const Assessment& a, const io::Snapshot& s, Colouring colouring,
                               const std::array<double, 3>& view, const PictureOptions& o) {
    const ShieldLayout& L = a.layout;
    plot::SectionPicture pic;
    pic.widthPx = o.widthPx;
    pic.heightPx = o.heightPx;
    pic.zMin = view[0];
    pic.zMax = view[1];
    pic.rMax = view[2];
    pic.mirror = L.axisymmetric;
    pic.timeStamp = timeStamp(s.info.timeUs);
    const bool hasDamage = !s.particles.damage.empty() || (s.fe && !s.fe->elements.damage.empty());
    if (colouring == Colouring::Body) {
        pic.title = a.layout.sceneId + ": material";
        pic.legend = bodyLegend(L);
    } else {
        pic.title = a.layout.sceneId + ": damage D" +
                    (hasDamage ? std::string() : std::string(" (no damage field in this run)"));
        pic.colorBar = plot::ColorBar{"damage D [-]", 0.0, 1.0, &plot::viridis};
    }
    const auto& p = s.particles;
    pic.markers.reserve(p.z.size());
    for (std::size_t i = 0; i < p.z.size(); ++i) {
        if (!p.alive[i]) {
            continue;
        }
        const auto b = static_cast<std::size_t>(p.bodyId[i]);
        const double d = p.damage.empty() ? 0.0 : p.damage[i];
        pic.markers.push_back({p.z[i], p.r[i], L.bodies[b].spacing,
                               colouring == Colouring::Body ? bodyColor(L, b) : plot::viridis(d)});
    }
    if (s.fe) {
        const auto& el = s.fe->elements;
        const auto& nd = s.fe->nodes;
        for (std::size_t e = 0; e < el.alive.size(); ++e) {
            if (!el.alive[e]) {
                continue;
            }
            plot::SectionQuad q;
            for (std::size_t k = 0; k < 4; ++k) {
                const auto n = static_cast<std::size_t>(el.connectivity[4 * e + k]);
                q.z[k] = nd.z[n];
                q.r[k] = nd.r[n];
            }
            const auto b = static_cast<std::size_t>(el.bodyId[e]);
            q.color = colouring == Colouring::Body
                          ? bodyColor(L, b)
                          : plot::viridis(el.damage.empty() ? 0.0 : el.damage[e]);
            pic.quads.push_back(q);
        }
    }
    return pic;
}

plot::Series line(const std::string& label, const std::vector<double>& x,
                  const std::vector<double>& y, plot::Rgb color) {
    plot::Series s;
    s.label = label;
    s.x = x;
    s.y = y;
    s.color = color;
    s.width = 1.8;
    return s;
}

} // namespace

std::vector<std::string> writePictures(const Assessment& a, const std::vector<int>& indices,
                                       const PictureOptions& o) {
    std::error_code ec;
    fs::create_directories(o.directory, ec);
    if (!fs::is_directory(o.directory)) {
        throw RuntimeFailure("cannot create the picture directory " + o.directory +
                             (ec ? ": " + ec.message() : std::string()));
    }
    std::vector<const io::Snapshot*> shots;
    for (int index : indices) {
        for (const auto& s : a.kept) {
            if (s.info.index == index) {
                shots.push_back(&s);
            }
        }
    }
    const auto view = o.view ? *o.view : viewOf(a, shots);
    std::vector<std::string> written;
    const fs::path dir(o.directory);
    for (const auto* s : shots) {
        const std::string tag = timeTag(s->info.timeUs);
        for (auto colouring : {Colouring::Body, Colouring::Damage}) {
            const auto path =
                (dir / ((colouring == Colouring::Body ? "material_" : "damage_") + tag + ".png"))
                    .string();
            plot::writeSectionPicture(sectionOf(a, *s, colouring, view, o), path);
            written.push_back(path);
        }
    }

    // Rear-wall damage profile at the last snapshot.
    const io::Snapshot* lastShot = nullptr;
    for (const auto& s : a.kept) {
        if (s.info.index == a.snapshots.back().index) {
            lastShot = &s;
        }
    }
    if (lastShot && a.layout.rearWall) {
        const auto items = materialItems(*lastShot, a.first);
        const auto profile = rearWallDamageProfile(items, a.layout, a.criteria);
        plot::XyPlot p;
        p.width = o.widthPx;
        p.height = o.heightPx;
        p.title = a.layout.sceneId + ": rear wall '" + a.layout.bodies[*a.layout.rearWall].name +
                  "' damage profile, " + timeStamp(lastShot->info.timeUs);
        p.xLabel = "initial radius r [mm]";
        p.yLabel = "fraction [-]";
        p.yMin = 0.0;
        p.yMax = 1.05;
        p.series.push_back(line("failed fraction of the thickness", profile->radiusMm,
                                profile->failedFraction, {0.84, 0.15, 0.16}));
        p.series.push_back(
            line("mean damage D", profile->radiusMm, profile->meanDamage, {0.12, 0.47, 0.71}));
        const auto path = (dir / "rear_wall_damage.png").string();
        plot::writePlot(p, path);
        written.push_back(path);
    }

    // Histories.
    const auto& h = a.history;
    if (!h.timeUs.empty()) {
        std::vector<double> withDeleted(h.timeUs.size());
        for (std::size_t k = 0; k < withDeleted.size(); ++k) {
            withDeleted[k] = h.totalEnergy[k] + h.deletedEnergy[k];
        }
        plot::XyPlot energy;
        energy.width = o.widthPx;
        energy.height = o.heightPx;
        energy.title = a.layout.sceneId + ": energy";
        energy.xLabel = "time [us]";
        energy.yLabel = "energy [J]";
        energy.series.push_back(line("kinetic", h.timeUs, h.kineticEnergy, {0.84, 0.15, 0.16}));
        energy.series.push_back(line("internal", h.timeUs, h.internalEnergy, {0.12, 0.47, 0.71}));
        energy.series.push_back(line("total", h.timeUs, h.totalEnergy, {0.2, 0.2, 0.2}));
        energy.series.push_back(line("total + deleted", h.timeUs, withDeleted, {0.17, 0.63, 0.17}));
        const auto energyPath = (dir / "energy.png").string();
        plot::writePlot(energy, energyPath);
        written.push_back(energyPath);

        plot::XyPlot error;
        error.width = o.widthPx;
        error.height = o.heightPx;
        error.title = a.layout.sceneId + ": relative energy error (E + E_deleted - E0) / |E0|";
        error.xLabel = "time [us]";
        error.yLabel = "energy error [-]";
        error.series.push_back(line("energy error", h.timeUs, h.energyError, {0.84, 0.15, 0.16}));
        const auto errorPath = (dir / "energy_error.png").string();
        plot::writePlot(error, errorPath);
        written.push_back(errorPath);

        plot::XyPlot momentum;
        momentum.width = o.widthPx;
        momentum.height = o.heightPx;
        momentum.title = a.layout.sceneId + ": axial momentum of the material in the calculation";
        momentum.xLabel = "time [us]";
        momentum.yLabel = "momentum z [mg km/s]";
        momentum.series.push_back(line("momentum z", h.timeUs, h.momentumZ, {0.58, 0.40, 0.74}));
        const auto momentumPath = (dir / "momentum.png").string();
        plot::writePlot(momentum, momentumPath);
        written.push_back(momentumPath);
    }
    return written;
}

} // namespace hvi::assess
