#include "validation/Progress.hpp"

#include "io/JsonInput.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hvi::validation {

Progress progressOf(const std::vector<Case>& cases, const std::filesystem::path& outDir) {
    Progress p;
    p.total = cases.size();
    double sum = 0.0;
    for (const auto& c : cases) {
        const auto verdict = outDir / c.id / "verdict.json";
        if (!std::filesystem::exists(verdict)) {
            continue;
        }
        ++p.done;
        const auto v = io::readJsonFile(verdict.string());
        if (v.contains("wall_time_s") && v["wall_time_s"].is_number()) {
            sum += v["wall_time_s"].get<double>();
            ++p.timed;
        }
    }
    p.meanWallS = p.timed > 0 ? sum / static_cast<double>(p.timed) : 0.0;
    return p;
}

std::string progressLine(const Progress& p, int jobs) {
    char line[200];
    if (p.done >= p.total) {
        std::snprintf(line, sizeof line, "validate: all %zu cases done", p.total);
        return line;
    }
    const std::size_t left = p.total - p.done;
    const int n = std::max(1, jobs);
    if (p.timed == 0) {
        std::snprintf(line, sizeof line, "validate: %zu/%zu cases done, %zu left", p.done, p.total,
                      left);
        return line;
    }
    // Whole runs side by side: the rest takes ceil(left / jobs) rounds of a mean run.
    const double rounds = std::ceil(static_cast<double>(left) / static_cast<double>(n));
    const double seconds = rounds * p.meanWallS;
    const long minutes = std::lround(seconds / 60.0);
    char eta[48];
    if (seconds < 60.0) {
        std::snprintf(eta, sizeof eta, "%.0f s", seconds);
    } else if (minutes >= 60) {
        std::snprintf(eta, sizeof eta, "%ld h %02ld min", minutes / 60, minutes % 60);
    } else {
        std::snprintf(eta, sizeof eta, "%ld min", minutes);
    }
    std::snprintf(line, sizeof line,
                  "validate: %zu/%zu cases done, %zu left, about %s to go at %d job%s (mean %.0f s "
                  "a run)",
                  p.done, p.total, left, eta, n, n == 1 ? "" : "s", p.meanWallS);
    return line;
}

} // namespace hvi::validation
