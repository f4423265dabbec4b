#include "validation/ValidationReport.hpp"

#include "core/Error.hpp"
#include "io/JsonInput.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace hvi::validation {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

struct Row {
    const Case* c = nullptr;
    std::optional<std::string> ours, grade;
    bool final = false, axisOnly = false;
    std::optional<double> wallS, energyError, endUs;
    /// A P's outermost failure of the rear wall: the larger of the perforation's and the
    /// detached spall's radius (docs/metrics.md), to tell a speck at the axis from a hole.
    std::optional<double> failureRadiusMm;
    /// A resumed run whose earlier parts were not timed (a checkpoint of a build before the
    /// run facts' earlier_wall_time_s): wallS is its last part only, a lower bound.
    bool wallPartOnly = false;
    bool complete = false;
    std::optional<std::string> ble;
    std::optional<double> bleRatio; ///< d / d_c
    std::string solver;             ///< the build of hvi-run that made the run (its git id)
    /// What the run's profile (run facts' `profile`, solver/Profile.hpp) says of its cost;
    /// empty for a run of a build before the profile.
    struct Cost {
        double wallS = 0.0, steps = 0.0, loopS = 0.0;
        int threads = 1;
        std::map<std::string, double> packageS;                  ///< sph, fe, contact
        std::map<std::string, std::pair<double, double>> bins; ///< binned, evaluated
    };
    std::optional<Cost> cost;
};

std::optional<json> readIfPresent(const fs::path& path) {
    if (!fs::exists(path)) {
        return std::nullopt;
    }
    return io::readJsonFile(path.string());
}

/// The member `key` of `object`, or null when it is absent or `object` is no object (a
/// const operator[] on an absent key is undefined behaviour in nlohmann::json).
const json& member(const json& object, const char* key) {
    static const json absent;
    if (!object.is_object()) {
        return absent;
    }
    const auto it = object.find(key);
    return it == object.end() ? absent : *it;
}

std::string fmt(const char* format, double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

/// The run's cost from its profile (JSON text in the run facts), if it has one.
void readCost(Row& row, const json& run) {
    if (!member(run, "profile").is_string()) {
        return;
    }
    const json p = json::parse(member(run, "profile").get<std::string>(), nullptr, false);
    if (!member(p, "wall_time_s").is_number()) {
        return; // not a profile this report can read
    }
    Row::Cost cost;
    cost.wallS = member(p, "wall_time_s").get<double>();
    cost.steps = member(p, "steps").is_number() ? member(p, "steps").get<double>() : 0.0;
    cost.threads = member(run, "threads").is_number() ? member(run, "threads").get<int>() : 1;
    if (member(p, "packages").is_object()) {
        for (const auto& [name, pkg] : member(p, "packages").items()) {
            if (member(pkg, "total_s").is_number()) {
                cost.packageS[name] = member(pkg, "total_s").get<double>();
            }
        }
    }
    if (member(p, "loop_s").is_object()) {
        for (const auto& [name, seconds] : member(p, "loop_s").items()) {
            cost.loopS += seconds.is_number() ? seconds.get<double>() : 0.0;
        }
    }
    if (member(p, "time_bins").is_object()) {
        for (const auto& [name, b] : member(p, "time_bins").items()) {
            if (member(b, "binned_point_steps").is_number() &&
                member(b, "evaluated_point_steps").is_number()) {
                cost.bins[name] = {member(b, "binned_point_steps").get<double>(),
                                   member(b, "evaluated_point_steps").get<double>()};
            }
        }
    }
    row.cost = cost;
}

/// The hydrocode's part of a row from an hvi-assess verdict file, if there is one.
void readVerdict(Row& row, const fs::path& file) {
    if (const auto v = readIfPresent(file)) {
        if (!v->contains("damage_grade")) {
            throw InputError(file.string(), "/damage_grade",
                             "is missing: the verdict predates the damage grades",
                             "a verdict of this hvi-assess (delete it and rerun make validate)");
        }
        if (member(*v, "verdict").is_string()) {
            row.ours = member(*v, "verdict").get<std::string>();
            row.grade = member(*v, "damage_grade").is_string()
                            ? member(*v, "damage_grade").get<std::string>()
                            : std::string();
            row.final = member(*v, "verdict_final") == true;
            row.axisOnly = member(*v, "axis_band_only") == true;
            if (*row.ours == "P") {
                const json& wall = member(*v, "rear_wall");
                for (const char* key : {"perforation_radius_mm", "spall_radius_mm"}) {
                    if (member(wall, key).is_number()) {
                        row.failureRadiusMm = std::max(row.failureRadiusMm.value_or(0.0),
                                                       member(wall, key).get<double>());
                    }
                }
            }
        }
        if (member(*v, "wall_time_s").is_number()) {
            row.wallS = member(*v, "wall_time_s").get<double>();
        }
        const json& run = member(*v, "run");
        if (member(run, "resumed") == true && !member(run, "earlier_wall_time_s").is_number()) {
            row.wallPartOnly = true;
            if (!row.wallS && member(run, "this_wall_time_s").is_number()) {
                row.wallS = member(run, "this_wall_time_s").get<double>();
            }
        }
        readCost(row, run);
        row.complete = member(*v, "complete") == true;
        if (member(*v, "solver").is_object() && member(member(*v, "solver"), "git").is_string()) {
            row.solver = member(member(*v, "solver"), "git").get<std::string>();
        }
        if (member(*v, "final_time_us").is_number()) {
            row.endUs = member(*v, "final_time_us").get<double>();
        }
        if (member(*v, "energy_error").is_number()) {
            row.energyError = member(*v, "energy_error").get<double>();
        }
    }
}

Row readRow(const Case& c, const fs::path& dir) {
    Row row;
    row.c = &c;
    readVerdict(row, dir / "verdict.json");
    if (const auto b = readIfPresent(dir / "ble.json")) {
        const json& perf = member(*b, "performance");
        if (perf.is_object() && member(perf, "verdict").is_string()) {
            row.ble = member(perf, "verdict").get<std::string>();
            if (member(perf, "critical_over_projectile_diameter").is_number()) {
                row.bleRatio =
                    1.0 / member(perf, "critical_over_projectile_diameter").get<double>();
            }
        }
    }
    return row;
}

struct Tally {
    int right = 0, total = 0;
    std::string text() const {
        return total == 0 ? "–"
                          : std::to_string(right) + "/" + std::to_string(total) + " (" +
                                fmt("%.0f", 100.0 * right / total) + " %)";
    }
    void add(const std::optional<std::string>& verdict, const std::string& result) {
        if (verdict) {
            ++total;
            right += *verdict == result ? 1 : 0;
        }
    }
};

std::string speedBand(double v) {
    return v < 3.0 ? "< 3 km/s" : v <= 7.0 ? "3-7 km/s" : "> 7 km/s";
}

/// One verdict in a cell: "P, perforation, axis, 26 s".
std::string verdictCell(const Row& r) {
    if (!r.ours) {
        return "–";
    }
    std::string cell = *r.ours;
    if (r.grade && !r.grade->empty()) {
        cell += ", " + *r.grade;
    }
    cell += r.axisOnly ? ", axis" : "";
    cell += r.ours == std::string("NP") && !r.final ? ", provisional" : "";
    if (r.wallS) {
        cell += ", " + std::string(r.wallPartOnly ? "≥" : "") + fmt("%.0f", *r.wallS) + " s";
    }
    return cell;
}

using Kept = std::vector<std::pair<std::string, fs::path>>;

/// A case's kept verdicts in each of `dirs` (<id>.json), beside this run's row.
struct Beside {
    const Row* row = nullptr;
    std::vector<Row> kept;
    bool same = true; ///< every kept verdict equals this run's (where both exist)
};

/// The rows with a kept verdict in at least one of `dirs`, in the rows' order.
std::vector<Beside> besides(const std::vector<Row>& rows, const Kept& dirs) {
    std::vector<Beside> out;
    for (const auto& r : rows) {
        Beside b;
        b.row = &r;
        bool any = false; // a verdict in one of the directories at least
        for (const auto& [label, dir] : dirs) {
            Row o;
            o.c = r.c;
            readVerdict(o, dir / (r.c->id + ".json"));
            any |= o.ours.has_value();
            b.same &= !o.ours || !r.ours || *o.ours == *r.ours;
            b.kept.push_back(o);
        }
        if (any) {
            out.push_back(std::move(b));
        }
    }
    return out;
}

/// The side-by-side table: this run's column, then one per kept directory.
std::string besideTable(const std::vector<Beside>& bs, const Kept& dirs,
                        const std::string& thisColumn, const std::string& labelSuffix) {
    std::ostringstream md;
    md << "| case | shield | test | " << thisColumn;
    for (const auto& [label, dir] : dirs) {
        md << " | " << label << labelSuffix;
    }
    md << " |\n|---|---|---|---|";
    for (std::size_t k = 0; k < dirs.size(); ++k) {
        md << "---|";
    }
    md << "\n";
    for (const auto& b : bs) {
        const Case& c = *b.row->c;
        md << "| " << c.id << " | " << toString(c.shield) << " | " << c.result << " | "
           << verdictCell(*b.row);
        for (const auto& o : b.kept) {
            md << " | " << verdictCell(o);
        }
        md << " |\n";
    }
    return md.str();
}

/// How many of the cases with this run's verdict and a kept one keep it everywhere.
std::pair<int, int> keptOfCompared(const std::vector<Beside>& bs) {
    int compared = 0, kept = 0;
    for (const auto& b : bs) {
        if (b.row->ours) {
            ++compared;
            kept += b.same ? 1 : 0;
        }
    }
    return {kept, compared};
}

std::string thisColumn(const ReportOptions& options) {
    return options.resolution.empty() ? std::string("this run") : options.resolution + " mm";
}

/// The cases that have a verdict at another spacing too (ReportOptions::otherSpacings), side
/// by side: a verdict that changes with the spacing measures the discretisation, not the
/// shield.
std::string stabilitySection(const std::vector<Row>& rows, const ReportOptions& options) {
    const auto bs = besides(rows, options.otherSpacings);
    if (bs.empty()) {
        return {};
    }
    const auto [kept, compared] = keptOfCompared(bs);
    std::ostringstream md;
    md << "## Verdict stability over the spacing\n\n"
       << "The cases run at other spacings too (the kept verdicts of each): " << kept << " of the "
       << compared << " with verdicts at two spacings or more keep their verdict at every "
       << "spacing run.\n\n"
       << besideTable(bs, options.otherSpacings, thisColumn(options), " mm") << "\n";
    return md.str();
}

/// The cases run with other material libraries too (ReportOptions::variants), side by side,
/// with each variant's agreement with the tests beside this run's on the cases both ran: a
/// verdict that moves within a constant's uncertainty is decided by that constant.
std::string sensitivitySection(const std::vector<Row>& rows, const ReportOptions& options) {
    const auto bs = besides(rows, options.variants);
    if (bs.empty()) {
        return {};
    }
    const auto [kept, compared] = keptOfCompared(bs);
    std::ostringstream md;
    md << "## Sensitivity to material constants\n\n"
       << "The cases run at the same spacing with a material library laid over the built-in "
          "one (`workflows/materials/<variant>.json`, `make -C workflows validate "
          "VARIANT=<variant>`): "
       << kept << " of the " << compared << " run with both keep their verdict under every "
       << "variant run. Agreement with the tests on the cases each variant ran, the built-in "
          "library's beside it:";
    const char* sep = " ";
    for (std::size_t k = 0; k < options.variants.size(); ++k) {
        Tally builtin, variant;
        for (const auto& b : bs) {
            if (b.row->ours && b.kept[k].ours) {
                builtin.add(b.row->ours, b.row->c->result);
                variant.add(b.kept[k].ours, b.row->c->result);
            }
        }
        md << sep << "`" << options.variants[k].first << "` " << variant.text() << " (built-in "
           << builtin.text() << ")";
        sep = "; ";
    }
    md << ".";
    sep = " Verdicts that move: ";
    for (const auto& b : bs) {
        if (b.row->ours && !b.same) {
            md << sep << b.row->c->id;
            sep = ", ";
        }
    }
    md << (kept == compared ? " No verdict moves." : ".") << "\n\n"
       << besideTable(bs, options.variants, "built-in", "") << "\n";
    return md.str();
}

/// Where the runs' time went, by set and shield: the sums of their profiles.
std::string costSection(const std::vector<Row>& rows) {
    struct Group {
        std::vector<double> walls, steps;
        double wallS = 0.0, loopS = 0.0;
        std::map<std::string, double> packageS;
        std::map<std::string, std::pair<double, double>> bins;
        std::set<int> threads;
        void add(const Row::Cost& c) {
            walls.push_back(c.wallS);
            steps.push_back(c.steps);
            wallS += c.wallS;
            loopS += c.loopS;
            threads.insert(c.threads);
            for (const auto& [name, seconds] : c.packageS) {
                packageS[name] += seconds;
            }
            for (const auto& [name, b] : c.bins) {
                bins[name].first += b.first;
                bins[name].second += b.second;
            }
        }
    };
    std::map<std::string, Group> groups;
    Group all;
    for (const auto& r : rows) {
        if (r.ours && r.cost) {
            groups[r.c->set + " " + toString(r.c->shield)].add(*r.cost);
            all.add(*r.cost);
        }
    }
    if (all.walls.empty()) {
        return {};
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    const auto share = [](double part, double whole) {
        return whole > 0.0 ? fmt("%.0f %%", 100.0 * part / whole) : std::string("–");
    };
    const auto binned = [](const Group& g, const char* name) {
        const auto it = g.bins.find(name);
        return it != g.bins.end() && it->second.second > 0.0
                   ? fmt("%.0f %%", 100.0 * it->second.first / it->second.second)
                   : std::string("–");
    };
    const auto line = [&](const std::string& name, const Group& g) {
        std::string threads;
        for (const int t : g.threads) {
            threads += (threads.empty() ? "" : ", ") + std::to_string(t);
        }
        const auto pkg = [&](const char* p) {
            const auto it = g.packageS.find(p);
            return share(it == g.packageS.end() ? 0.0 : it->second, g.wallS);
        };
        return "| " + name + " | " + std::to_string(g.walls.size()) + " | " + threads + " | " +
               fmt("%.1f", g.wallS / 3600.0) + " | " + fmt("%.0f", median(g.walls)) + " | " +
               fmt("%.0f", *std::max_element(g.walls.begin(), g.walls.end())) + " | " +
               fmt("%.0f", median(g.steps)) + " | " + pkg("sph") + " | " + pkg("fe") + " | " +
               pkg("contact") + " | " + share(g.loopS, g.wallS) + " | " + binned(g, "sph") +
               " | " + binned(g, "fe") + " |\n";
    };
    std::string md = "## Run cost\n\nFrom each run's profile (`/run@profile`, "
                     "docs/performance.md), for the runs that have one: their wall time by set "
                     "and shield, its share in each package and in the loop's own work "
                     "(deletion, stop rules, output), and what time-step bins would leave of the "
                     "packages' point evaluations (the profile's bound).\n\n"
                     "| set, shield | runs | threads | wall h | median s | max s | median steps | "
                     "sph | fe | contact | loop | bins: sph | bins: fe |\n"
                     "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& [name, g] : groups) {
        md += line(name, g);
    }
    return md + line("all", all) + "\n";
}

} // namespace

std::string validationReport(const std::vector<Case>& cases, const fs::path& outDir,
                             const ReportOptions& options) {
    std::vector<Row> rows;
    for (const auto& c : cases) {
        rows.push_back(readRow(c, outDir / c.id));
    }
    std::ostringstream md;
    md << "# Validation: verdicts against the tests\n\n"
       << "Generated by `make -C workflows validate` (`hvi-validate report`); do not edit by "
          "hand. Selection `"
       << options.selection << "`"
       << (options.resolution.empty() ? std::string()
                                      : ", particle spacing " + options.resolution + " mm")
       << ". A verdict is P when the rear wall is perforated or sheds detached spall "
          "(docs/metrics.md). `final`: a P, or an NP with the wall at rest at the end of the "
          "run. `axis`: every sign of failure lies in the axis band. `fail r`: for a P, the "
          "outermost radius of the rear wall's perforation or detached spall. BLE: the NASA JSC "
          "equation of the same shield (`ble-size`), d/d_c its ratio of projectile to "
          "critical diameter.\n\n";

    // Summary first.
    std::map<std::string, std::pair<Tally, Tally>> byShield, bySpeed;
    std::map<std::string, int> casesOf;
    Tally oursAll, bleAll, bleOnRun;
    int tp = 0, fp = 0, fn = 0, tn = 0, axisOnly = 0, notRun = 0, provisional = 0, partOnly = 0;
    double wall = 0.0;
    std::map<std::string, int> solvers; // build -> verdicts it made
    for (const auto& r : rows) {
        const std::string shield = r.c->set + " " + toString(r.c->shield);
        const std::string band = speedBand(r.c->velocityKmS);
        ++casesOf[shield];
        byShield[shield].first.add(r.ours, r.c->result);
        byShield[shield].second.add(r.ble, r.c->result);
        bySpeed[band].first.add(r.ours, r.c->result);
        bySpeed[band].second.add(r.ble, r.c->result);
        oursAll.add(r.ours, r.c->result);
        bleAll.add(r.ble, r.c->result);
        if (!r.ours) {
            ++notRun;
            continue;
        }
        bleOnRun.add(r.ble, r.c->result);
        const bool p = *r.ours == "P", testP = r.c->result == "P";
        (p ? (testP ? tp : fp) : (testP ? fn : tn))++;
        axisOnly += r.axisOnly ? 1 : 0;
        provisional += r.final ? 0 : 1;
        wall += r.wallS.value_or(0.0);
        partOnly += r.wallPartOnly ? 1 : 0;
        ++solvers[r.solver.empty() ? "unknown" : r.solver];
    }
    md << "## Summary\n\n"
       << "| set, shield | cases | ours | BLE on the same cases | BLE on all |\n"
       << "|---|---|---|---|---|\n";
    for (const auto& [shield, t] : byShield) {
        Tally bleSame;
        for (const auto& r : rows) {
            if (r.c->set + " " + toString(r.c->shield) == shield && r.ours) {
                bleSame.add(r.ble, r.c->result);
            }
        }
        md << "| " << shield << " | " << casesOf[shield] << " | " << t.first.text() << " | "
           << bleSame.text() << " | " << t.second.text() << " |\n";
    }
    md << "| all | " << rows.size() << " | " << oursAll.text() << " | " << bleOnRun.text() << " | "
       << bleAll.text() << " |\n\n";
    md << "| speed | ours | BLE on all |\n|---|---|---|\n";
    for (const auto& [band, t] : bySpeed) {
        md << "| " << band << " | " << t.first.text() << " | " << t.second.text() << " |\n";
    }
    md << "\nConfusion matrix of ours (test in rows): P/P " << tp << ", P/NP (missed) " << fn
       << ", NP/P (false alarm) " << fp << ", NP/NP " << tn << ". P verdicts resting on the axis "
       << "band alone: " << axisOnly
       << ". Provisional NP verdicts (run ended before rest): " << provisional
       << ". Not run: " << notRun << " of " << rows.size()
       << ". Wall time of the runs: " << (partOnly > 0 ? "at least " : "") << fmt("%.0f", wall)
       << " s"
       << (partOnly > 0 ? " (" + std::to_string(partOnly) +
                              " resumed runs timed by their last part only, marked ≥)"
                        : std::string())
       << ".";
    if (!solvers.empty()) {
        // Verdicts kept from an older solver are not a measurement of the current one.
        md << " Runs made by hvi-run build";
        const char* sep = " ";
        for (const auto& [build, n] : solvers) {
            md << sep << "`" << build << "` (" << n << ")";
            sep = ", ";
        }
        md << ".";
    }
    md << "\n\n";

    md << "## Cases\n\n"
       << "| case | shield | d mm | V km/s | test | ours | grade | final | axis | fail r mm | BLE |"
          " d/d_c | run s | energy error | end µs |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const Case& c = *r.c;
        md << "| " << c.id << " | " << toString(c.shield) << " | " << fmt("%.3g", c.diameterMm)
           << " | " << fmt("%.3g", c.velocityKmS) << " | " << c.result << " | "
           << (r.ours ? *r.ours : std::string("not run")) << " | " << r.grade.value_or("") << " | "
           << (r.ours ? (r.final ? "yes" : "no") : "") << " | "
           << (r.ours && r.axisOnly ? "yes" : "") << " | "
           << (r.failureRadiusMm ? fmt("%.2f", *r.failureRadiusMm) : std::string("")) << " | "
           << r.ble.value_or("–") << " | "
           << (r.bleRatio ? fmt("%.2f", *r.bleRatio) : std::string("–")) << " | "
           << (r.wallS ? (r.wallPartOnly ? "≥" : "") + fmt("%.0f", *r.wallS) : std::string(""))
           << " | " << (r.energyError ? fmt("%.1e", *r.energyError) : std::string("")) << " | "
           << (r.endUs ? fmt("%.1f", *r.endUs) + (r.complete ? "" : " (partial)") : std::string(""))
           << " |\n";
    }
    md << "\n"
       << costSection(rows) << stabilitySection(rows, options) << sensitivitySection(rows, options)
       << "## Assumptions\n\n";
    for (const auto& c : cases) {
        for (const auto& a : c.assumptions) {
            md << "- " << c.id << ": " << a << "\n";
        }
    }
    return md.str();
}

} // namespace hvi::validation
