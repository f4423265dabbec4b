// Honeycomb core -> concentric rings; the method and its conventions are in the header.
#include "geometry/HoneycombRings.hpp"

#include "core/Units.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hvi::geometry {

namespace {

constexpr double kSqrt3 = 1.73205080756887729353;

/// Above this many candidate crossings the input is surely a unit mistake.
constexpr double kMaxRings = 100000.0;

/// |n·d| below this: the ray is parallel to the wall family (cos of 90° ± 1e-9 rad). Angles
/// like 30° computed through cos/sin leave ~1e-17 here, far below.
constexpr double kParallel = 1e-9;

/// Points closer than this × D coincide (a node hit seen by two families; equidistance
/// from two cell centres). Rounding along a ray of 1000 cells is ~1e-13 D.
constexpr double kGeometryTolerance = 1e-9;

struct Vec2 {
    double x;
    double y;
};

double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}

/// A wall family: its unit normal, and the lattice step (di, dk) between the two cells that
/// one of its walls separates (centre(i+di, k+dk) − centre(i, k) = D · normal).
struct WallFamily {
    Vec2 normal;
    long long di;
    long long dk;
};

constexpr std::array<WallFamily, 3> kFamilies = {{
    {{1.0, 0.0}, 1, 0},            // 0: ribbon walls, parallel to L (y)
    {{0.5, 0.5 * kSqrt3}, 0, 1},   // 1: slanted, normal at 60°
    {{-0.5, 0.5 * kSqrt3}, -1, 1}, // 2: slanted, normal at 120°
}};

/// The regular hexagonal tiling of cell size D (across flats), cell (0, 0) at the origin.
class HexTiling {
public:
    explicit HexTiling(double cellSizeMm) : m_d(cellSizeMm) {}

    Vec2 centre(long long i, long long k) const {
        return {m_d * (static_cast<double>(i) + 0.5 * static_cast<double>(k)),
                m_d * 0.5 * kSqrt3 * static_cast<double>(k)};
    }

    /// The lattice indices of the cell centre nearest to p.
    std::array<long long, 2> nearestCell(Vec2 p) const {
        const auto near = nearestCells(p);
        return {near.cells[0][0], near.cells[0][1]};
    }

    /// Whether p lies on a wall of `family` (the Voronoi test of the header): among the cell
    /// centres nearest to p (ties within tolerance), two differ by the family's lattice step.
    bool onWall(Vec2 p, const WallFamily& family) const {
        const auto near = nearestCells(p);
        for (int a = 0; a < near.count; ++a) {
            for (int b = 0; b < near.count; ++b) {
                if (near.cells[b][0] - near.cells[a][0] == family.di &&
                    near.cells[b][1] - near.cells[a][1] == family.dk) {
                    return true;
                }
            }
        }
        return false;
    }

private:
    struct NearCells {
        std::array<std::array<long long, 2>, 16> cells; // nearest first
        int count = 0;
    };

    /// The centres at the smallest distance from p, within tolerance. The nearest centre is
    /// a corner of the lattice parallelogram holding p (its two triangles are equilateral,
    /// hence acute); the 4 × 4 block around it also catches ties across its edges.
    NearCells nearestCells(Vec2 p) const {
        const double kFrac = p.y / (0.5 * kSqrt3 * m_d);
        const double iFrac = p.x / m_d - 0.5 * kFrac;
        const auto i0 = static_cast<long long>(std::floor(iFrac));
        const auto k0 = static_cast<long long>(std::floor(kFrac));
        std::array<std::array<long long, 2>, 16> cells{};
        std::array<double, 16> dist{};
        int n = 0;
        double best = std::numeric_limits<double>::infinity();
        int bestIndex = 0;
        for (long long di = -1; di <= 2; ++di) {
            for (long long dk = -1; dk <= 2; ++dk) {
                const Vec2 c = centre(i0 + di, k0 + dk);
                cells[n] = {i0 + di, k0 + dk};
                dist[n] = std::hypot(p.x - c.x, p.y - c.y);
                if (dist[n] < best) {
                    best = dist[n];
                    bestIndex = n;
                }
                ++n;
            }
        }
        NearCells near;
        near.cells[near.count++] = cells[bestIndex];
        for (int m = 0; m < n; ++m) {
            if (m != bestIndex && dist[m] <= best + kGeometryTolerance * m_d) {
                near.cells[near.count++] = cells[m];
            }
        }
        return near;
    }

    double m_d;
};

struct Crossing {
    double distanceMm;
    int family;
};

/// Every wall crossing of the ray origin + s·dir, 0 ≤ s ≤ maxDistance, unmerged.
std::vector<Crossing> rayCrossings(const HexTiling& tiling, double cellSizeMm, Vec2 origin,
                                   Vec2 dir, double maxDistanceMm) {
    std::vector<Crossing> crossings;
    const double half = 0.5 * cellSizeMm;
    const double tol = kGeometryTolerance * cellSizeMm;
    for (int j = 0; j < 3; ++j) {
        const WallFamily& family = kFamilies[static_cast<std::size_t>(j)];
        const double a = dot(family.normal, dir);
        if (std::fabs(a) < kParallel) {
            continue;
        }
        // The family's walls lie on the lines normal·x = m·D/2.
        const double b = dot(family.normal, origin);
        const double end = b + a * maxDistanceMm;
        const auto mFirst = static_cast<long long>(std::floor(std::min(b, end) / half)) - 1;
        const auto mLast = static_cast<long long>(std::ceil(std::max(b, end) / half)) + 1;
        for (long long m = mFirst; m <= mLast; ++m) {
            double s = (static_cast<double>(m) * half - b) / a;
            if (s < -tol || s > maxDistanceMm + tol) {
                continue;
            }
            s = std::max(s, 0.0);
            const Vec2 p{origin.x + s * dir.x, origin.y + s * dir.y};
            if (tiling.onWall(p, family)) {
                crossings.push_back({s, j});
            }
        }
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& l, const Crossing& r) { return l.distanceMm < r.distanceMm; });
    return crossings;
}

/// Crossings merged into rings: coincident crossings (a node) become one ring with the mean
/// thickness of the families seen there.
std::vector<HoneycombRing> mergeIntoRings(const std::vector<Crossing>& crossings,
                                          const std::array<double, 3>& wallThicknessMm,
                                          double cellSizeMm, double heightMm) {
    std::vector<HoneycombRing> rings;
    const double tol = kGeometryTolerance * cellSizeMm;
    for (std::size_t first = 0; first < crossings.size();) {
        std::array<bool, 3> seen{};
        std::size_t last = first;
        while (last < crossings.size() &&
               crossings[last].distanceMm - crossings[first].distanceMm <= tol) {
            seen[static_cast<std::size_t>(crossings[last].family)] = true;
            ++last;
        }
        double sum = 0.0;
        int families = 0;
        for (std::size_t j = 0; j < 3; ++j) {
            if (seen[j]) {
                sum += wallThicknessMm[j];
                ++families;
            }
        }
        const double radius = crossings[first].distanceMm;
        const double thickness = sum / families;
        rings.push_back({radius, std::max(0.0, radius - 0.5 * thickness), radius + 0.5 * thickness,
                         thickness, 0.0, heightMm, families >= 2});
        first = last;
    }
    return rings;
}

void validate(const HoneycombCoreSpec& spec, InputChecks& checks) {
    checks.positive("core_thickness_mm", spec.coreThicknessMm,
                    "honeycomb core height between the facesheets [mm], > 0");
    const bool cellOk = checks.positive("cell_size_mm", spec.cellSizeMm,
                                        "hexagonal cell size across flats [mm], > 0");
    if (checks.positive("foil_thickness_mm", spec.foilThicknessMm,
                        "cell wall foil thickness [mm], 0 < value < cell_size_mm/2") &&
        cellOk && spec.foilThicknessMm >= 0.5 * spec.cellSizeMm) {
        checks.add("foil_thickness_mm",
                   "must be < cell_size_mm/2 = " + formatNumber(0.5 * spec.cellSizeMm) + ", got " +
                       formatNumber(spec.foilThicknessMm),
                   "cell wall foil thickness [mm], 0 < value < cell_size_mm/2");
    }
    checks.positive("foil_density_g_cm3", spec.foilDensityGCm3,
                    "density of the foil material [g/cm^3], > 0");
    if (checks.positive("domain_radius_mm", spec.domainRadiusMm,
                        "outer radius of the 2D axisymmetric domain [mm], > 0") &&
        cellOk && 6.0 * spec.domainRadiusMm / spec.cellSizeMm > kMaxRings) {
        checks.add("domain_radius_mm",
                   "gives about " + formatNumber(6.0 * spec.domainRadiusMm / spec.cellSizeMm) +
                       " candidate wall crossings",
                   "at most " + formatNumber(kMaxRings) + " (check the units)");
    }
    checks.inRange("double_wall_fraction", spec.doubleWallFraction, 0.0, true, 1.0, true,
                   "fraction of ribbon walls that are double foil, 0 <= value <= 1");
    if (spec.impactSite == ImpactSite::Offset) {
        checks.finite("impact_offset_x_mm", spec.impactOffsetXMm,
                      "impact point from the cell centre along W [mm], required by "
                      "impact_site \"offset\"");
        checks.finite("impact_offset_y_mm", spec.impactOffsetYMm,
                      "impact point from the cell centre along L [mm], required by "
                      "impact_site \"offset\"");
    } else {
        checks.unused("impact_offset_x_mm", spec.impactOffsetXMm,
                      "only impact_site \"offset\" uses it");
        checks.unused("impact_offset_y_mm", spec.impactOffsetYMm,
                      "only impact_site \"offset\" uses it");
    }
    if (spec.direction == RingDirection::Custom) {
        checks.finite("ring_angle_deg", spec.ringAngleDeg,
                      "ray direction from the W axis [deg], required by ring_direction "
                      "\"custom\"");
    } else {
        checks.unused("ring_angle_deg", spec.ringAngleDeg,
                      "only ring_direction \"custom\" uses it");
    }
    checks.positive("particle_spacing_mm", spec.particleSpacingMm,
                    "SPH particle spacing the rings are checked against [mm], > 0");
}

} // namespace

double honeycombRelativeDensity(double cellSizeMm, double foilThicknessMm,
                                double doubleWallFraction) {
    return 2.0 / 3.0 * (3.0 + doubleWallFraction) * foilThicknessMm / cellSizeMm;
}

HoneycombRings buildHoneycombRings(const HoneycombCoreSpec& spec, const std::string& file,
                                   const std::string& pointerPrefix) {
    InputChecks checks(file, pointerPrefix);
    validate(spec, checks);
    checks.throwIfAny();

    HoneycombRings out;
    out.direction = spec.direction;
    switch (spec.direction) {
    case RingDirection::Apothem:
        out.angleDeg = 0.0;
        break;
    case RingDirection::Vertex:
        out.angleDeg = 30.0;
        break;
    case RingDirection::Custom:
        out.angleDeg = spec.ringAngleDeg;
        break;
    }
    switch (spec.impactSite) {
    case ImpactSite::CellCentre:
        break;
    case ImpactSite::CellWall:
        out.impactXMm = 0.5 * spec.cellSizeMm;
        break;
    case ImpactSite::Offset:
        out.impactXMm = spec.impactOffsetXMm;
        out.impactYMm = spec.impactOffsetYMm;
        break;
    }

    const double d = spec.cellSizeMm;
    const double t = spec.foilThicknessMm;
    const double h = spec.coreThicknessMm;
    const double radius = spec.domainRadiusMm;
    const std::array<double, 3> wallThickness = {(1.0 + spec.doubleWallFraction) * t, t, t};

    // The tiling is periodic: move the impact point into cell (0, 0) so that a large offset
    // costs no precision.
    const HexTiling tiling(d);
    Vec2 origin{out.impactXMm, out.impactYMm};
    const auto cell = tiling.nearestCell(origin);
    const Vec2 shift = tiling.centre(cell[0], cell[1]);
    origin = {origin.x - shift.x, origin.y - shift.y};
    const double angle = units::degToRad(out.angleDeg);
    const Vec2 dir{std::cos(angle), std::sin(angle)};

    const auto all =
        mergeIntoRings(rayCrossings(tiling, d, origin, dir, radius), wallThickness, d, h);
    const double fitTolerance = kGeometryTolerance * d;
    for (const auto& ring : all) {
        if (ring.outerRadiusMm > radius + fitTolerance) {
            break;
        }
        out.rings.push_back(ring);
    }
    const bool hasRing = std::any_of(out.rings.begin(), out.rings.end(),
                                     [](const HoneycombRing& r) { return r.radiusMm > 0.0; });
    if (!hasRing) {
        // Any ray meets a wall within 2 cell sizes (the longest chord of a hexagon is 2l).
        const auto further = mergeIntoRings(rayCrossings(tiling, d, origin, dir, radius + 3.0 * d),
                                            wallThickness, d, h);
        const auto firstRing =
            std::find_if(further.begin(), further.end(),
                         [](const HoneycombRing& r) { return r.radiusMm > 0.0; });
        const double needed = firstRing != further.end() ? firstRing->outerRadiusMm : 3.0 * d;
        checks.add("domain_radius_mm",
                   "holds no ring: the first wall crossing ends at r = " + formatNumber(needed) +
                       " mm, got " + formatNumber(radius),
                   "domain radius [mm] >= " + formatNumber(needed));
        checks.throwIfAny();
    }

    out.relativeDensity = honeycombRelativeDensity(d, t, spec.doubleWallFraction);
    out.coreDensityGCm3 = spec.foilDensityGCm3 * out.relativeDensity;
    out.realArealMassGCm2 = out.coreDensityGCm3 * units::mmToCm(h);
    double annulusOverR2 = 0.0; // Σ (r_out² − r_in²) / R²
    double thinnest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < out.rings.size(); ++i) {
        const auto& ring = out.rings[i];
        annulusOverR2 +=
            (ring.outerRadiusMm * ring.outerRadiusMm - ring.innerRadiusMm * ring.innerRadiusMm) /
            (radius * radius);
        thinnest = std::min(thinnest, ring.thicknessMm);
        if (i > 0 && ring.innerRadiusMm < out.rings[i - 1].outerRadiusMm) {
            out.warnings.push_back(
                {WarningKind::Overlap, "rings at r = " + formatNumber(out.rings[i - 1].radiusMm) +
                                           " and " + formatNumber(ring.radiusMm) + " mm overlap"});
        }
    }
    out.reducedArealMassGCm2 = spec.foilDensityGCm3 * units::mmToCm(h) * annulusOverR2;
    out.massRatio = out.reducedArealMassGCm2 / out.realArealMassGCm2;

    if (thinnest < 3.0 * spec.particleSpacingMm) {
        out.warnings.push_back(
            {WarningKind::UnderResolved,
             "ring thickness " + formatNumber(thinnest) + " mm is less than 3 particle " +
                 "spacings at " + formatNumber(spec.particleSpacingMm) +
                 " mm; resolving it needs a particle spacing <= " + formatNumber(thinnest / 3.0) +
                 " mm (thickness/3)"});
    }
    return out;
}

std::string_view toString(RingDirection direction) {
    switch (direction) {
    case RingDirection::Apothem:
        return "apothem";
    case RingDirection::Vertex:
        return "vertex";
    case RingDirection::Custom:
        return "custom";
    }
    return "?";
}

std::string_view toString(ImpactSite site) {
    switch (site) {
    case ImpactSite::CellCentre:
        return "cell_centre";
    case ImpactSite::CellWall:
        return "cell_wall";
    case ImpactSite::Offset:
        return "offset";
    }
    return "?";
}

std::optional<RingDirection> parseRingDirection(std::string_view text) {
    for (auto direction : {RingDirection::Apothem, RingDirection::Vertex, RingDirection::Custom}) {
        if (text == toString(direction)) {
            return direction;
        }
    }
    return std::nullopt;
}

std::optional<ImpactSite> parseImpactSite(std::string_view text) {
    for (auto site : {ImpactSite::CellCentre, ImpactSite::CellWall, ImpactSite::Offset}) {
        if (text == toString(site)) {
            return site;
        }
    }
    return std::nullopt;
}

} // namespace hvi::geometry
