// Built-in cases: scenes the tools can run without an input file (the benchmark, the
// README's default case).
#pragma once

#include <nlohmann/json.hpp>

namespace hvi::app {

/// The source study's bumper calibration case (thesis section 5.2, thesis_cases.json
/// "particle_size_study"): a 3.125 mm Al 6061-T6 sphere at 6.847 km/s on a 0.8 mm
/// Al 6061-T6 plate, SPH only, 3 us. The plate is cut at 10 mm radius: the measured hole
/// is 6.7 mm wide, and a dormant plate edge sends no waves until the impact's reach it.
nlohmann::json bumperCaseScene(double particleSpacingMm);

} // namespace hvi::app
