#include "assess/Criteria.hpp"

namespace hvi::assess {

using nlohmann::json;

json Criteria::toJson() const {
    return {{"failed_damage", failedDamage},
            {"failed_density_ratio", failedDensityRatio},
            {"intact_density_ratio", intactDensityRatio},
            {"axial_window_thicknesses", axialWindowThicknesses},
            {"hole_span_fraction", holeSpanFraction},
            {"hole_edge_bins", holeEdgeBins},
            {"min_crossing_items", minCrossingItems},
            {"link_spacings", linkSpacings},
            {"join_spacings", joinSpacings},
            {"axis_band_spacings", axisBandSpacings},
            {"bulge_spacings", bulgeSpacings},
            {"rest_speed_km_s", restSpeedKmS},
            {"leading_edge_mass_fraction", leadingEdgeMassFraction},
            {"front_mass_fraction", frontMassFraction}};
}

} // namespace hvi::assess
