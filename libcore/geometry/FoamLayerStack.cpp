// Foam core -> layer stack; the method and its conventions are documented in the header.
#include "geometry/FoamLayerStack.hpp"

#include "core/Units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hvi::geometry {

namespace {

/// Above this many layers (or segments per layer) the input is surely a unit mistake
/// (e.g. a standoff in µm); it also keeps the pore count far inside int range.
constexpr double kMaxBodies = 10000.0;

/// A count within this of an integer is that integer (brief: "within 1e-9").
constexpr double kIntegerSnap = 1e-9;

/// Relative slack when deciding that a segment edge coincides with the axis or the domain
/// edge: products like 0.5·(L/0.5) − 2L + L come out as ±1e-16·L, not 0.
constexpr double kEdgeSlack = 1e-9;

/// mm · g/cm³ -> g/cm²
double arealMassGCm2(double thicknessMm, double densityGCm3) {
    return units::mmToCm(thicknessMm) * densityGCm3;
}

struct Annulus {
    double innerMm;
    double outerMm;
};

/// Whole segments of one layer inside [0, R] (see the header: periodic from the axis).
std::vector<Annulus> layerSegments(double lengthMm, double periodMm, double shiftMm,
                                   double radiusMm) {
    std::vector<Annulus> segments;
    const double slack = kEdgeSlack * lengthMm;
    for (double j = -1.0;; j += 1.0) {
        const double inner = shiftMm + j * periodMm;
        const double outer = inner + lengthMm;
        if (outer > radiusMm + slack) {
            break;
        }
        if (outer <= slack) {
            continue; // the j = -1 segment lies wholly at r < 0
        }
        segments.push_back({std::max(inner, 0.0), std::min(outer, radiusMm)});
    }
    return segments;
}

void validate(const FoamCoreSpec& spec, InputChecks& checks) {
    checks.positive("standoff_mm", spec.standoffMm,
                    "core thickness between the facesheets [mm], > 0");
    checks.inRange("relative_density_percent", spec.relativeDensityPercent, 0.0, false, 100.0,
                   false, "foam relative density [%], 0 < value < 100");
    checks.positive("ppi", spec.ppi, "real pores per inch of the foam [1/in], > 0");
    checks.positive("material_density_g_cm3", spec.materialDensityGCm3,
                    "density of the solid ligament material [g/cm^3], > 0");
    checks.positive("domain_radius_mm", spec.domainRadiusMm,
                    "outer radius of the 2D axisymmetric domain [mm], > 0");
    checks.inRange("ppi_factor", spec.ppiFactor, 0.0, false, 1.0, true,
                   "effective PPI / real PPI, 0 < value <= 1 (thesis: 0.5)");
    checks.positive("particle_spacing_mm", spec.particleSpacingMm,
                    "SPH particle spacing the layers are checked against [mm], > 0");

    if (spec.rule == FoamThicknessRule::Ligament) {
        checks.positive("ligament_thickness_mm", spec.ligamentThicknessMm,
                        "measured ligament thickness [mm], > 0, required by thickness_rule "
                        "\"ligament\"");
    } else {
        checks.unused("ligament_thickness_mm", spec.ligamentThicknessMm,
                      "only thickness_rule \"ligament\" uses it");
    }

    if (spec.model == FoamLayerModel::Segments) {
        checks.positive("segment_length_mm", spec.segmentLengthMm,
                        "radial length of one flat segment [mm], > 0, required by layer_model "
                        "\"segments\"");
        checks.inRange("segment_gap_fraction", spec.segmentGapFraction, 0.0, true, 1.0, false,
                       "gap / (segment + gap), 0 <= value < 1");
        checks.inRange("segment_stagger_fraction", spec.segmentStaggerFraction, 0.0, true, 1.0,
                       false, "radial shift of even layers / segment period, 0 <= value < 1");
    } else {
        checks.unused("segment_length_mm", spec.segmentLengthMm,
                      "only layer_model \"segments\" uses it");
    }
}

void addResolutionWarning(FoamLayerStack& stack, double thinnestMm, double narrowestMm,
                          double spacingMm) {
    const double needed = 3.0 * spacingMm;
    if (thinnestMm < needed) {
        stack.warnings.push_back(
            {WarningKind::UnderResolved,
             "layer thickness " + formatNumber(thinnestMm) + " mm is less than 3 particle " +
                 "spacings at " + formatNumber(spacingMm) +
                 " mm; resolving it needs a particle spacing <= " + formatNumber(thinnestMm / 3.0) +
                 " mm (thickness/3)"});
    }
    if (narrowestMm < needed) {
        stack.warnings.push_back(
            {WarningKind::UnderResolved, "segment radial length " + formatNumber(narrowestMm) +
                                             " mm is less than 3 " + "particle spacings at " +
                                             formatNumber(spacingMm) +
                                             " mm; resolving it needs a particle spacing <= " +
                                             formatNumber(narrowestMm / 3.0) + " mm (length/3)"});
    }
}

} // namespace

int roundUpPores(double poresExact) {
    if (!(poresExact >= 0.0 && poresExact < 1e9)) {
        throw std::domain_error("roundUpPores: pore count " + formatNumber(poresExact) +
                                " outside [0, 1e9)");
    }
    const double nearest = std::round(poresExact);
    const double pores =
        std::fabs(poresExact - nearest) <= kIntegerSnap ? nearest : std::ceil(poresExact);
    return static_cast<int>(pores);
}

FoamLayerStack buildFoamLayerStack(const FoamCoreSpec& spec, const std::string& file,
                                   const std::string& pointerPrefix) {
    InputChecks checks(file, pointerPrefix);
    validate(spec, checks);
    checks.throwIfAny();

    FoamLayerStack stack;
    stack.rule = spec.rule;
    stack.model = spec.model;
    stack.effectivePpi = spec.ppiFactor * spec.ppi;
    stack.poresExact = stack.effectivePpi * units::mmToInch(spec.standoffMm);
    if (stack.poresExact > kMaxBodies) {
        checks.add("ppi",
                   "ppi * ppi_factor * standoff_mm [in] gives " + formatNumber(stack.poresExact) +
                       " pores across the core",
                   "at most " + formatNumber(kMaxBodies) + " (check the units of standoff_mm)");
        checks.throwIfAny();
    }
    stack.poreCount = roundUpPores(stack.poresExact);
    stack.layerCount = stack.poreCount - 1;
    if (stack.layerCount < 1) {
        checks.add("standoff_mm",
                   "gives " + formatNumber(stack.poresExact) +
                       " pores across the core, rounded up to " + std::to_string(stack.poreCount) +
                       ": no layer between the facesheets",
                   "more than 1 effective pore across the core: standoff_mm > 25.4 / (ppi * "
                   "ppi_factor) = " +
                       formatNumber(units::kMmPerInch / stack.effectivePpi) + " mm");
        checks.throwIfAny();
    }

    const double n = static_cast<double>(stack.layerCount);
    stack.solidThicknessMm = spec.relativeDensityPercent / 100.0 * spec.standoffMm;
    stack.layerSpacingMm = spec.standoffMm / static_cast<double>(stack.poreCount);
    switch (spec.rule) {
    case FoamThicknessRule::Mass:
        stack.layerThicknessMm = stack.solidThicknessMm / n;
        break;
    case FoamThicknessRule::Eq31:
        stack.layerThicknessMm = stack.solidThicknessMm / stack.poresExact;
        break;
    case FoamThicknessRule::Ligament:
        stack.layerThicknessMm = spec.ligamentThicknessMm;
        break;
    }

    const double radius = spec.domainRadiusMm;
    double segmentPeriod = 0.0;
    if (spec.model == FoamLayerModel::Segments) {
        segmentPeriod = spec.segmentLengthMm / (1.0 - spec.segmentGapFraction);
        if (radius / segmentPeriod > kMaxBodies) {
            checks.add("segment_length_mm",
                       "gives " + formatNumber(radius / segmentPeriod) +
                           " segments per layer inside domain_radius_mm",
                       "at most " + formatNumber(kMaxBodies));
            checks.throwIfAny();
        }
    }

    double reducedVolumeOverR2 = 0.0; // Σ t·(r_out² − r_in²) / R², in mm
    double thinnest = stack.layerThicknessMm;
    double thickest = stack.layerThicknessMm;
    double narrowest = std::numeric_limits<double>::infinity(); // segments only
    for (int k = 1; k <= stack.layerCount; ++k) {
        const double zMid = static_cast<double>(k) * stack.layerSpacingMm;
        std::vector<Annulus> bodies;
        double thickness = stack.layerThicknessMm;
        if (spec.model == FoamLayerModel::Disks) {
            bodies.push_back({0.0, radius});
        } else {
            const double shift = (k % 2 == 0) ? spec.segmentStaggerFraction * segmentPeriod : 0.0;
            bodies = layerSegments(spec.segmentLengthMm, segmentPeriod, shift, radius);
            if (bodies.empty()) {
                checks.add(
                    "segment_length_mm",
                    "layer " + std::to_string(k) +
                        " has no whole segment inside domain_radius_mm = " + formatNumber(radius),
                    "segment_length_mm + stagger shift (" + formatNumber(shift) +
                        " mm) <= domain_radius_mm");
                checks.throwIfAny();
            }
            double solidOverR2 = 0.0;
            for (const auto& body : bodies) {
                solidOverR2 +=
                    (body.outerMm * body.outerMm - body.innerMm * body.innerMm) / (radius * radius);
                narrowest = std::min(narrowest, body.outerMm - body.innerMm);
            }
            thickness = stack.layerThicknessMm / solidOverR2;
        }
        thinnest = std::min(thinnest, thickness);
        thickest = std::max(thickest, thickness);
        for (const auto& body : bodies) {
            stack.layers.push_back({k, zMid - 0.5 * thickness, zMid + 0.5 * thickness, thickness,
                                    body.innerMm, body.outerMm});
            reducedVolumeOverR2 += thickness *
                                   (body.outerMm * body.outerMm - body.innerMm * body.innerMm) /
                                   (radius * radius);
        }
    }

    stack.realArealMassGCm2 = arealMassGCm2(stack.solidThicknessMm, spec.materialDensityGCm3);
    stack.reducedArealMassGCm2 = arealMassGCm2(reducedVolumeOverR2, spec.materialDensityGCm3);
    stack.massErrorRelative = stack.reducedArealMassGCm2 / stack.realArealMassGCm2 - 1.0;

    addResolutionWarning(stack, thinnest, narrowest, spec.particleSpacingMm);
    if (thickest >= stack.layerSpacingMm) {
        stack.warnings.push_back(
            {WarningKind::Overlap, "layer thickness " + formatNumber(thickest) +
                                       " mm is not less than the layer spacing " +
                                       formatNumber(stack.layerSpacingMm) +
                                       " mm: neighbouring layers touch or overlap"});
    }
    return stack;
}

std::string_view toString(FoamThicknessRule rule) {
    switch (rule) {
    case FoamThicknessRule::Mass:
        return "mass";
    case FoamThicknessRule::Eq31:
        return "eq31";
    case FoamThicknessRule::Ligament:
        return "ligament";
    }
    return "?";
}

std::string_view toString(FoamLayerModel model) {
    switch (model) {
    case FoamLayerModel::Disks:
        return "disks";
    case FoamLayerModel::Segments:
        return "segments";
    }
    return "?";
}

std::optional<FoamThicknessRule> parseFoamThicknessRule(std::string_view text) {
    for (auto rule :
         {FoamThicknessRule::Mass, FoamThicknessRule::Eq31, FoamThicknessRule::Ligament}) {
        if (text == toString(rule)) {
            return rule;
        }
    }
    return std::nullopt;
}

std::optional<FoamLayerModel> parseFoamLayerModel(std::string_view text) {
    for (auto model : {FoamLayerModel::Disks, FoamLayerModel::Segments}) {
        if (text == toString(model)) {
            return model;
        }
    }
    return std::nullopt;
}

} // namespace hvi::geometry
