#include "solver/Profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hvi::solver {

namespace {

constexpr double kBinBase = 1.01; ///< 1 %-wide step-size bins

int binOf(double dtUs) {
    return static_cast<int>(std::floor(std::log(dtUs) / std::log(kBinBase)));
}

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[96];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

/// "evaluate 380.0 (neighbour search 60.2), finish 19.7": the phases with at least 0.5 % of
/// the run, largest first; a package's sections after the phase they are part of, or last.
std::string phaseList(const PhaseTimes& times, double wall) {
    std::vector<std::pair<double, std::string_view>> phases;
    for (std::size_t k = 0; k < kPhaseCount; ++k) {
        const double s = times.phase(static_cast<Phase>(k));
        if (s >= 0.005 * wall && s > 0.0) {
            phases.emplace_back(s, kPhaseNames[k]);
        }
    }
    std::sort(phases.begin(), phases.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string out;
    for (const auto& [s, name] : phases) {
        out += (out.empty() ? "" : ", ") + std::string(name) + format(" %.3g", s);
    }
    std::string sections;
    for (const auto& [name, s] : times.sections()) {
        sections += (sections.empty() ? "" : ", ") + name + format(" %.3g", s);
    }
    if (!sections.empty()) {
        out += "; of which " + sections;
    }
    return out;
}

/// Per package: the point-evaluations made and what time-step bins would have made.
nlohmann::json binnedJson(const std::vector<std::pair<std::string, BinnedWork>>& binned) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [name, work] : binned) {
        out[name] = {{"evaluated_point_steps", work.evaluated()},
                     {"binned_point_steps", work.binned()},
                     {"fraction", work.fraction()}};
    }
    return out;
}

} // namespace

void PhaseTimes::bookSection(std::string_view name, double seconds) {
    for (auto& [known, s] : m_sections) {
        if (known == name) {
            s += seconds;
            return;
        }
    }
    m_sections.emplace_back(std::string(name), seconds);
}

double PhaseTimes::total() const {
    double sum = 0.0;
    for (const double s : m_phase) {
        sum += s;
    }
    return sum;
}

void StepSizeHistogram::add(double dtUs, const std::string& limiter) {
    if (!(dtUs > 0.0) || !std::isfinite(dtUs)) {
        return; // no step was taken
    }
    ++m_bins[binOf(dtUs)];
    ++m_limiters[limiter];
    m_min = m_count == 0 ? dtUs : std::min(m_min, dtUs);
    m_max = m_count == 0 ? dtUs : std::max(m_max, dtUs);
    ++m_count;
}

double StepSizeHistogram::percentile(double q) const {
    if (m_count == 0) {
        return 0.0;
    }
    const double target = std::clamp(q, 0.0, 1.0) * static_cast<double>(m_count);
    long seen = 0;
    for (const auto& [bin, n] : m_bins) {
        seen += n;
        if (static_cast<double>(seen) >= target) {
            // The bin's geometric middle, never outside the steps actually taken.
            const double middle = std::pow(kBinBase, bin + 0.5);
            return std::clamp(middle, m_min, m_max);
        }
    }
    return m_max;
}

nlohmann::json profileJson(const RunProfile& profile) {
    nlohmann::json packages = nlohmann::json::object();
    for (const auto& [name, times] : profile.packages) {
        nlohmann::json phases = nlohmann::json::object();
        for (std::size_t k = 0; k < kPhaseCount; ++k) {
            phases[std::string(kPhaseNames[k])] = times.phase(static_cast<Phase>(k));
        }
        nlohmann::json sections = nlohmann::json::object();
        for (const auto& [section, s] : times.sections()) {
            sections[section] = s;
        }
        packages[name] = {
            {"total_s", times.total()}, {"phases_s", phases}, {"sections_s", sections}};
    }
    nlohmann::json loop = nlohmann::json::object();
    for (const auto& [name, s] : profile.loop) {
        loop[name] = s;
    }
    const StepSizeHistogram& h = profile.steps;
    return {{"wall_time_s", profile.wallSeconds},
            {"packages", packages},
            {"loop_s", loop},
            {"steps", h.count()},
            {"dt_us",
             {{"min", h.min()},
              {"p10", h.percentile(0.1)},
              {"median", h.percentile(0.5)},
              {"p90", h.percentile(0.9)},
              {"max", h.max()}}},
            {"dt_limiter_steps", h.limiterSteps()},
            {"time_bins", binnedJson(profile.binned)}};
}

std::string profileText(const RunProfile& profile) {
    const double wall = std::max(profile.wallSeconds, 1e-9);
    const StepSizeHistogram& h = profile.steps;
    std::string out =
        format("where the %.1f s went", profile.wallSeconds) +
        format(" (%.0f steps, %.2f ms a step):", static_cast<double>(h.count()),
               1e3 * profile.wallSeconds / std::max(1.0, static_cast<double>(h.count())));
    double accounted = 0.0;
    auto row = [&](const std::string& name, double s, const std::string& detail) {
        char line[160];
        std::snprintf(line, sizeof line, "\n  %-12s %9.1f s %5.1f %%", name.c_str(), s,
                      100.0 * s / wall);
        out += line;
        if (!detail.empty()) {
            out += "   " + detail;
        }
        accounted += s;
    };
    for (const auto& [name, times] : profile.packages) {
        row(name, times.total(), phaseList(times, wall));
    }
    for (const auto& [name, s] : profile.loop) {
        row(name, s, "");
    }
    const double rest = std::max(0.0, profile.wallSeconds - accounted);
    row("other", rest, "");
    if (h.count() > 0) {
        out += format("\ntime steps [us]: min %.3g, 10 %% below %.3g", h.min(), h.percentile(0.1)) +
               format(", median %.3g, 90 %% below %.3g", h.percentile(0.5), h.percentile(0.9)) +
               format(", max %.3g; set by", h.max());
        bool first = true;
        for (const auto& [limiter, n] : h.limiterSteps()) {
            out +=
                (first ? " " : ", ") + limiter +
                format(" %.1f %%", 100.0 * static_cast<double>(n) / static_cast<double>(h.count()));
            first = false;
        }
    }
    if (!profile.binned.empty()) {
        out += "\ntime bins (each point at its own power-of-two step, up to " +
               format("%.0f", std::ldexp(1.0, BinnedWork::kMaxBin)) +
               " times the smallest) would evaluate";
        const char* sep = " ";
        for (const auto& [name, work] : profile.binned) {
            out += sep + format("%.0f %% of ", 100.0 * work.fraction()) + name + "'s points";
            sep = ", ";
        }
    }
    return out;
}

} // namespace hvi::solver
