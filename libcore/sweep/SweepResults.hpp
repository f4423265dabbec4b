// The results of a sweep over speeds: every DIR/<speed>/critical.json beside its sweep.json,
// as a CSV table (one row per speed) and as the validation tests of the same shield, for the
// plot over the ballistic limit equation (workflows/sweep.mk, hvi-sweep report).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::sweep {

struct SpeedResult {
    nlohmann::json spec;     ///< sweep.json
    nlohmann::json critical; ///< critical.json
};

/// The speeds of OUT (subdirectories holding both files), by increasing speed. Throws
/// std::runtime_error when none has finished.
std::vector<SpeedResult> readResults(const std::filesystem::path& outDir);

/// speed_km_s, parameter, state, critical_mm, fail_side_mm, hold_side_mm, runs, guess_mm,
/// held_beyond_fail_side_mm (';'-separated); empty cells for what a search did not find.
std::string resultsCsv(const std::vector<SpeedResult>& results);

struct TestShot {
    std::string id;
    double speedKmS = 0.0;
    double valueMm = 0.0; ///< the swept parameter's value in the test
    bool perforated = false;
};

/// The validation tests (libcore/validation) of the swept shield: same shield type; the
/// front plate, the gap and the parameter not swept (rear wall or diameter) within 2 % of the
/// sweep's, as tests of one series vary by; the same plate and core alloys where the panel
/// names them. Their speed and swept value.
std::vector<TestShot> testsOfShield(const nlohmann::json& spec);

} // namespace hvi::sweep
