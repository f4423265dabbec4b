// Honeycomb core -> rings: the HITF04150 golden (with stated assumptions), the relative
// density against Gibson & Ashby's general formula, ring radii in the documented directions,
// an independent brute-force oracle for arbitrary rays, warnings and input errors.
#include "Tolerance.hpp"
#include "core/Error.hpp"
#include "geometry/HoneycombRings.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

using hvi::geometry::buildHoneycombRings;
using hvi::geometry::HoneycombCoreSpec;
using hvi::geometry::honeycombRelativeDensity;
using hvi::geometry::HoneycombRings;
using hvi::geometry::ImpactSite;
using hvi::geometry::RingDirection;
using hvi::geometry::WarningKind;
using hvi::test::near;

namespace {

const double kSqrt3 = std::sqrt(3.0);

// Radii are sums of at most ~100 mm-sized terms: 1e-10 mm absolute is rounding.
constexpr double kRadiusTol = 1e-10;
// Quantities recomputed from the closed forms with other operations: rounding only.
constexpr double kExact = 1e-12;

/// HITF04150 (thesis_cases.json: 50.8 mm core, 1.27 mm facesheets). The source gives neither
/// cell size nor foil. ASSUMED here: 3/16 in = 4.7625 mm cells, 0.001 in = 0.0254 mm Al 5052
/// foil of density 2.68 g/cm³, a common spacecraft core; standard expanded core (every
/// ribbon wall double foil); a 25 mm domain radius (the measured core damage is 30.5 mm
/// wide).
HoneycombCoreSpec hitf04150() {
    HoneycombCoreSpec spec;
    spec.coreThicknessMm = 50.8;
    spec.cellSizeMm = 4.7625;
    spec.foilThicknessMm = 0.0254;
    spec.foilDensityGCm3 = 2.68;
    spec.domainRadiusMm = 25.0;
    return spec;
}

std::vector<double> radiiOf(const HoneycombRings& rings) {
    std::vector<double> radii;
    for (const auto& r : rings.rings) {
        radii.push_back(r.radiusMm);
    }
    return radii;
}

bool hasWarning(const HoneycombRings& rings, WarningKind kind, const std::string& fragment) {
    for (const auto& w : rings.warnings) {
        if (w.kind == kind && w.message.find(fragment) != std::string::npos) {
            return true;
        }
    }
    return false;
}

std::string pointersOf(const HoneycombCoreSpec& spec) {
    try {
        buildHoneycombRings(spec, "hc.json", "/core");
    } catch (const hvi::InputError& e) {
        std::string all;
        for (const auto& issue : e.issues()) {
            all += issue.pointer + ";";
        }
        return all;
    }
    return "(no error)";
}

} // namespace

// Hand computation, apothem direction from the cell centre:
//   rings at D/2 + kD = 2.38125, 7.14375, 11.90625, 16.66875, 21.43125 mm (the next, 26.19375,
//   is outside 25 mm); all ribbon walls, thickness 2 × 0.0254 = 0.0508 mm.
//   Real core: ρ*/ρ = (8/3)(0.0254/4.7625) = (8/3)/187.5 = 0.0142222; core density
//   2.68 × 0.0142222 = 0.0381156 g/cm³; areal mass × 5.08 cm = 0.193627 g/cm².
//   Reduced: each annulus π((r + w/2)² − (r − w/2)²)H = 2π r w H, so the areal mass is
//   ρ · 2 Σr · w · H / R² = 2.68 g/cm³ × 2 × 59.53125 × 0.0508 × 50.8 / 625 mm
//   = 2.68 × 0.04916129 cm = 0.131752 g/cm²; ratio 0.131752/0.193627 = 0.680442.
TEST(HoneycombRings, Hitf04150ApothemGolden) {
    const auto out = buildHoneycombRings(hitf04150());
    const std::vector<double> expected = {2.38125, 7.14375, 11.90625, 16.66875, 21.43125};
    ASSERT_EQ(out.rings.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& ring = out.rings[i];
        EXPECT_TRUE(near("radius", ring.radiusMm, expected[i], kRadiusTol, 0.0));
        EXPECT_TRUE(near("thickness", ring.thicknessMm, 0.0508, 0.0, kExact));
        EXPECT_TRUE(near("inner", ring.innerRadiusMm, expected[i] - 0.0254, kRadiusTol, 0.0));
        EXPECT_TRUE(near("outer", ring.outerRadiusMm, expected[i] + 0.0254, kRadiusTol, 0.0));
        EXPECT_TRUE(near("z back", ring.zBackMm, 50.8, 0.0, 0.0));
        EXPECT_FALSE(ring.atNode);
    }
    // The hand values above have 6 significant digits: half a unit in the last place is at
    // most 5e-6 relative.
    constexpr double kSixDigits = 5e-6;
    EXPECT_TRUE(near("relative density", out.relativeDensity, 0.0142222, 0.0, kSixDigits));
    EXPECT_TRUE(near("core density", out.coreDensityGCm3, 0.0381156, 0.0, kSixDigits));
    EXPECT_TRUE(near("real areal mass", out.realArealMassGCm2, 0.193627, 0.0, kSixDigits));
    EXPECT_TRUE(near("reduced areal mass", out.reducedArealMassGCm2, 0.131752, 0.0, kSixDigits));
    EXPECT_TRUE(near("mass ratio", out.massRatio, 0.680442, 0.0, kSixDigits));
    EXPECT_EQ(out.direction, RingDirection::Apothem);
    EXPECT_TRUE(near("angle", out.angleDeg, 0.0, 0.0, 0.0));
    // 0.0508 mm rings are above 3 × 0.015 mm: resolved at the calibrated spacing.
    EXPECT_TRUE(out.warnings.empty());
}

// Vertex direction, same core: l = D/√3 = 2.749631 mm; the ray goes through nodes only, at
// l, 2l, 4l, 5l, 7l, 8l = 2.749631, 5.499261, 10.998523, 13.748153, 19.247415, 21.997045 mm
// (10l = 27.50 is outside). Each node joins a ribbon wall and a slanted wall, the third
// (slanted) wall running along the ray: thickness (0.0508 + 0.0254)/2 = 0.0381 mm.
// Reduced areal mass 2.68 × 2 × 27l × 0.0381 × 50.8 / 625 / 10 = 0.123229 g/cm²; ratio 0.636423.
// 0.0381 mm is below 3 × 0.015 mm: the warning asks for 0.0127 mm.
TEST(HoneycombRings, Hitf04150VertexGolden) {
    auto spec = hitf04150();
    spec.direction = RingDirection::Vertex;
    const auto out = buildHoneycombRings(spec);
    const double l = 4.7625 / kSqrt3;
    const std::vector<double> multiples = {1, 2, 4, 5, 7, 8};
    ASSERT_EQ(out.rings.size(), multiples.size());
    for (std::size_t i = 0; i < multiples.size(); ++i) {
        EXPECT_TRUE(near("radius", out.rings[i].radiusMm, multiples[i] * l, kRadiusTol, 0.0));
        EXPECT_TRUE(near("thickness", out.rings[i].thicknessMm, 0.0381, 0.0, kExact));
        EXPECT_TRUE(out.rings[i].atNode);
    }
    EXPECT_TRUE(near("radius 1 (hand)", out.rings[0].radiusMm, 2.749631, 1e-6, 0.0));
    // 6 significant digits, as in the Apothem golden.
    EXPECT_TRUE(near("reduced areal mass", out.reducedArealMassGCm2, 0.123229, 0.0, 5e-6));
    EXPECT_TRUE(near("mass ratio", out.massRatio, 0.636423, 0.0, 5e-6));
    EXPECT_TRUE(hasWarning(out, WarningKind::UnderResolved, "particle spacing <= 0.0127 mm"));
}

// Oracle: Gibson & Ashby's general hexagon, ρ*/ρs = (t/l)(h/l + 2)/(2 cos θ (h/l + sin θ)),
// at h = l, θ = 30°, l = D/√3, with the h-walls (our ribbon walls) of thickness (1 + φ)t,
// i.e. (h/l + 2) -> ((1 + φ) h/l + 2).
TEST(HoneycombRings, RelativeDensityMatchesGibsonAshby) {
    const double d = 4.7625;
    const double t = 0.0254;
    const double l = d / kSqrt3;
    const double theta = 30.0 * std::numbers::pi / 180.0;
    for (double phi : {0.0, 0.5, 1.0}) {
        const double gibsonAshby =
            (t / l) * ((1.0 + phi) * 1.0 + 2.0) / (2.0 * std::cos(theta) * (1.0 + std::sin(theta)));
        EXPECT_TRUE(near("relative density phi=" + std::to_string(phi),
                         honeycombRelativeDensity(d, t, phi), gibsonAshby, 0.0, kExact));
    }
    EXPECT_TRUE(
        near("8/3 t/D", honeycombRelativeDensity(d, t, 1.0), 8.0 / 3.0 * t / d, 0.0, kExact));
    EXPECT_TRUE(near("2 t/D", honeycombRelativeDensity(d, t, 0.0), 2.0 * t / d, 0.0, kExact));
}

// With R an exact multiple N·D, the apothem rings D/2 + kD, k < N, have Σr = N²D/2, so the
// reduced areal mass is ρ·w/D·H: ratio (w/D)/((2/3)(3 + φ)t/D) = 3(1 + φ)/(2(3 + φ)) exactly,
// 0.75 for φ = 1 and 0.5 for φ = 0: the rings drop the radial walls' share of the mass.
TEST(HoneycombRings, ApothemMassRatioIsExactOnWholeCells) {
    for (double phi : {0.0, 1.0}) {
        auto spec = hitf04150();
        spec.doubleWallFraction = phi;
        spec.domainRadiusMm = 40 * spec.cellSizeMm;
        const auto out = buildHoneycombRings(spec);
        EXPECT_EQ(out.rings.size(), 40u);
        EXPECT_TRUE(near("ratio phi=" + std::to_string(phi), out.massRatio,
                         3.0 * (1.0 + phi) / (2.0 * (3.0 + phi)), 0.0, 1e-12));
    }
}

// 60° is the apothem of a slanted family: rings at D/2 + kD again, single foil.
TEST(HoneycombRings, SlantedApothemIsSingleFoil) {
    auto spec = hitf04150();
    spec.direction = RingDirection::Custom;
    spec.ringAngleDeg = 60.0;
    const auto out = buildHoneycombRings(spec);
    ASSERT_EQ(out.rings.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_TRUE(near("radius", out.rings[i].radiusMm, 2.38125 + 4.7625 * static_cast<double>(i),
                         kRadiusTol, 0.0));
        EXPECT_TRUE(near("thickness", out.rings[i].thicknessMm, 0.0254, 0.0, kExact));
    }
    // 0.0254 mm at 0.015 mm spacing: needs 0.0254/3 = 0.00846667 mm.
    EXPECT_TRUE(hasWarning(out, WarningKind::UnderResolved, "0.00846667"));
}

// Impact on the ribbon wall at x = D/2, ray along W: the wall under the impact becomes an
// axial rod of radius 0.0254 mm (half the double-wall thickness), then walls at D, 2D, ...
TEST(HoneycombRings, WallImpactGivesAxialRod) {
    auto spec = hitf04150();
    spec.impactSite = ImpactSite::CellWall;
    const auto out = buildHoneycombRings(spec);
    ASSERT_EQ(out.rings.size(), 6u); // 0, D, ..., 5D = 23.8125
    EXPECT_TRUE(near("rod radius", out.rings[0].radiusMm, 0.0, 0.0, 0.0));
    EXPECT_TRUE(near("rod inner", out.rings[0].innerRadiusMm, 0.0, 0.0, 0.0));
    EXPECT_TRUE(near("rod outer", out.rings[0].outerRadiusMm, 0.0254, kRadiusTol, 0.0));
    for (std::size_t i = 1; i < 6; ++i) {
        EXPECT_TRUE(near("radius", out.rings[i].radiusMm, 4.7625 * static_cast<double>(i),
                         kRadiusTol, 0.0));
    }
    EXPECT_TRUE(near("impact x", out.impactXMm, 2.38125, 0.0, kExact));

    // The same wall, ray along it (L): no rod; the ray leaves the wall at its end node
    // (l/2 from the impact), through a cell centre (3l/2), to the next node (5l/2), along the
    // next ribbon wall to the node at 7l/2, ... — period 3l; the node thickness is the mean of
    // the two slanted walls there (single foil).
    spec.direction = RingDirection::Custom;
    spec.ringAngleDeg = 90.0;
    const auto along = buildHoneycombRings(spec);
    const double l = 4.7625 / kSqrt3;
    const std::vector<double> expected = {0.5 * l, 2.5 * l, 3.5 * l, 5.5 * l, 6.5 * l, 8.5 * l};
    ASSERT_EQ(along.rings.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_TRUE(
            near("radius along wall", along.rings[i].radiusMm, expected[i], kRadiusTol, 0.0));
        EXPECT_TRUE(near("thickness", along.rings[i].thicknessMm, 0.0254, 0.0, kExact));
        EXPECT_TRUE(along.rings[i].atNode);
    }
}

// Independent oracle for an arbitrary impact point and direction: walk the ray in small steps,
// find the nearest cell centre by brute force, and record where it changes (the hexagonal
// cells are the Voronoi cells of the centres). The library intersects lines instead.
TEST(HoneycombRings, ArbitraryRayMatchesBruteForceWalk) {
    const double d = 3.0;
    const double t = 0.02;
    const double ox = 0.31 * d;
    const double oy = -0.12 * d;
    const double angleDeg = 17.3;
    const double radius = 10.0 * d;

    HoneycombCoreSpec spec;
    spec.coreThicknessMm = 10.0;
    spec.cellSizeMm = d;
    spec.foilThicknessMm = t;
    spec.foilDensityGCm3 = 2.7;
    spec.domainRadiusMm = radius;
    spec.impactSite = ImpactSite::Offset;
    spec.impactOffsetXMm = ox;
    spec.impactOffsetYMm = oy;
    spec.direction = RingDirection::Custom;
    spec.ringAngleDeg = angleDeg;
    const auto out = buildHoneycombRings(spec);

    const double a = angleDeg * std::numbers::pi / 180.0;
    auto nearestCell = [&](double s) {
        const double px = ox + s * std::cos(a);
        const double py = oy + s * std::sin(a);
        long bestI = 0;
        long bestK = 0;
        double best = 1e300;
        // Every sampled point lies in x ∈ [0.9, 29.6], y ∈ [-0.4, 8.6] mm: its nearest centre
        // has i ∈ [-2, 11], k ∈ [-1, 4]; the window has a margin of 2.
        for (long i = -4; i <= 13; ++i) {
            for (long k = -3; k <= 6; ++k) {
                const double cx = d * (static_cast<double>(i) + 0.5 * static_cast<double>(k));
                const double cy = d * 0.5 * kSqrt3 * static_cast<double>(k);
                const double dist = std::hypot(px - cx, py - cy);
                if (dist < best) {
                    best = dist;
                    bestI = i;
                    bestK = k;
                }
            }
        }
        return std::pair<long, long>{bestI, bestK};
    };
    const double step = 1e-4 * d;
    std::vector<double> radii;
    std::vector<double> thickness;
    auto previous = nearestCell(0.0);
    for (double s = step; s <= radius; s += step) {
        const auto cell = nearestCell(s);
        if (cell != previous) {
            radii.push_back(s - 0.5 * step);
            // Ribbon wall: the two cells differ by (±1, 0) -> double foil.
            const bool ribbon = cell.second == previous.second;
            thickness.push_back(ribbon ? 2.0 * t : t);
            previous = cell;
        }
    }
    // The oracle keeps crossings up to R; the library keeps rings with outer radius <= R.
    while (!radii.empty() && radii.back() + 0.5 * thickness.back() > radius) {
        radii.pop_back();
        thickness.pop_back();
    }
    ASSERT_EQ(out.rings.size(), radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) {
        // The walk locates a crossing to half a step.
        EXPECT_TRUE(near("radius " + std::to_string(i), out.rings[i].radiusMm, radii[i],
                         0.5 * step + 1e-12, 0.0));
        EXPECT_TRUE(near("thickness " + std::to_string(i), out.rings[i].thicknessMm, thickness[i],
                         0.0, kExact));
        EXPECT_FALSE(out.rings[i].atNode);
    }
}

// The tiling is periodic: an offset by a lattice vector (37 cells along W) changes nothing.
TEST(HoneycombRings, OffsetIsPeriodic) {
    auto spec = hitf04150();
    spec.impactSite = ImpactSite::Offset;
    spec.direction = RingDirection::Custom;
    spec.ringAngleDeg = 41.0;
    spec.impactOffsetXMm = 0.7;
    spec.impactOffsetYMm = 0.3;
    const auto base = radiiOf(buildHoneycombRings(spec));
    spec.impactOffsetXMm = 0.7 + 37.0 * spec.cellSizeMm;
    const auto moved = radiiOf(buildHoneycombRings(spec));
    ASSERT_EQ(base.size(), moved.size());
    ASSERT_FALSE(base.empty());
    for (std::size_t i = 0; i < base.size(); ++i) {
        // 37 × 4.76 mm = 176 mm of offset removed by subtraction: 1e-12 relative of it.
        EXPECT_TRUE(near("radius", moved[i], base[i], 1e-9, 0.0));
    }
}

TEST(HoneycombRings, WarnsWhenRingsOverlap) {
    // Thick foil on 1 mm cells, vertex ray: node rings at l = 0.577 and 2l = 1.155 mm, each
    // (0.9 + 0.45)/2 = 0.675 mm thick: they overlap.
    HoneycombCoreSpec spec;
    spec.coreThicknessMm = 10.0;
    spec.cellSizeMm = 1.0;
    spec.foilThicknessMm = 0.45;
    spec.foilDensityGCm3 = 2.7;
    spec.domainRadiusMm = 5.0;
    spec.direction = RingDirection::Vertex;
    EXPECT_TRUE(hasWarning(buildHoneycombRings(spec), WarningKind::Overlap, "overlap"));
}

TEST(HoneycombRings, RejectsBadInputWithPointers) {
    auto spec = hitf04150();
    spec.cellSizeMm = 0.0;
    EXPECT_EQ(pointersOf(spec), "/core/cell_size_mm;");
    spec = hitf04150();
    spec.foilThicknessMm = 0.5 * spec.cellSizeMm;
    EXPECT_EQ(pointersOf(spec), "/core/foil_thickness_mm;");
    spec = hitf04150();
    spec.coreThicknessMm = std::nan("");
    spec.foilDensityGCm3 = std::nan("");
    EXPECT_EQ(pointersOf(spec), "/core/core_thickness_mm;/core/foil_density_g_cm3;");
    spec = hitf04150();
    spec.doubleWallFraction = 1.5;
    EXPECT_EQ(pointersOf(spec), "/core/double_wall_fraction;");
    spec = hitf04150();
    spec.direction = RingDirection::Custom; // angle missing
    EXPECT_EQ(pointersOf(spec), "/core/ring_angle_deg;");
    spec = hitf04150();
    spec.ringAngleDeg = 10.0; // given, but the apothem rule ignores it
    EXPECT_EQ(pointersOf(spec), "/core/ring_angle_deg;");
    spec = hitf04150();
    spec.impactSite = ImpactSite::Offset; // offsets missing
    EXPECT_EQ(pointersOf(spec), "/core/impact_offset_x_mm;/core/impact_offset_y_mm;");
    spec = hitf04150();
    spec.impactOffsetXMm = 1.0; // given, but the impact is at the cell centre
    EXPECT_EQ(pointersOf(spec), "/core/impact_offset_x_mm;");
}

// The domain must hold at least one ring beyond the axis; the message names the radius.
TEST(HoneycombRings, RejectsDomainInsideFirstRing) {
    auto spec = hitf04150();
    spec.domainRadiusMm = 2.0; // first ring at 2.38125, outer 2.40665
    try {
        buildHoneycombRings(spec, "hc.json", "/core");
        FAIL() << "no InputError";
    } catch (const hvi::InputError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].pointer, "/core/domain_radius_mm");
        EXPECT_NE(e.issues()[0].expected.find(">= 2.40665"), std::string::npos)
            << e.issues()[0].expected;
    }
    // A wall impact whose domain holds only the axial rod is rejected too.
    spec.impactSite = ImpactSite::CellWall;
    EXPECT_EQ(pointersOf(spec), "/core/domain_radius_mm;");
}

TEST(HoneycombRings, NamesRoundTrip) {
    using hvi::geometry::parseImpactSite;
    using hvi::geometry::parseRingDirection;
    for (auto d : {RingDirection::Apothem, RingDirection::Vertex, RingDirection::Custom}) {
        EXPECT_EQ(parseRingDirection(hvi::geometry::toString(d)), d);
    }
    for (auto s : {ImpactSite::CellCentre, ImpactSite::CellWall, ImpactSite::Offset}) {
        EXPECT_EQ(parseImpactSite(hvi::geometry::toString(s)), s);
    }
    EXPECT_FALSE(parseRingDirection("Apothem").has_value());
}
