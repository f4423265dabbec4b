// The source study's calibrated numerical defaults, written once for the C++ side: the
// structs, the tools' help texts and the benchmark read them from here. The JSON Schemas that
// fill an omitted key (scene, foam_panel, honeycomb_panel) carry the same numbers, since a
// schema cannot read a header; tests/unit/scene/Defaults_test.cpp holds every such schema
// default to these.
#pragma once

#include <string>

namespace hvi::scene {

/// SPH particle spacing and FE element size [mm]: the 2D value the source study calibrated
/// (its particle-size study, section 3.3.1).
inline constexpr double kDefaultParticleSpacingMm = 0.015;
/// FE erosion threshold on the geometric strain [-] (source study's calibrated value).
inline constexpr double kDefaultErosionFactor = 1.5;

/// A default as help texts print it ("0.015").
inline std::string defaultText(double value) {
    std::string s = std::to_string(value);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') {
        s.pop_back();
    }
    return s;
}

} // namespace hvi::scene
