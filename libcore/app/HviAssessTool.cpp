#include "app/HviAssessTool.hpp"

#include "assess/Assessment.hpp"
#include "assess/Expectation.hpp"
#include "assess/Pictures.hpp"
#include "assess/Verdict.hpp"
#include "io/AtomicOutput.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "io/RunFileReader.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

namespace hvi::app {

using nlohmann::json;

namespace {

const std::set<std::string> kCheckable = {"pnp", "penetration_depth_mm", "bumper_hole_diameter_mm",
                                          "core_damage_width_mm"};

std::string summaryLine(const json& v) {
    auto number = [](const json& x, const char* format) {
        if (!x.is_number()) {
            return std::string("n/a");
        }
        char buf[48];
        std::snprintf(buf, sizeof buf, format, x.get<double>());
        return std::string(buf);
    };
    std::string line = "verdict " + (v["verdict"].is_string() ? v["verdict"].get<std::string>()
                                                              : std::string("none"));
    if (v["damage_grade"].is_string()) {
        line += ", grade " + v["damage_grade"].get<std::string>();
    }
    line += v["complete"].get<bool>() ? " (complete run" : " (PARTIAL run";
    line += ", t = " + number(v["final_time_us"], "%.3f") + " us";
    line += v["verdict_final"] == false ? ", provisional NP)" : ")";
    if (v["axis_band_only"] == true) {
        line += "; failed only in the axis band";
    }
    line += "; hole " + number(v["bumper_hole_diameter_mm"], "%.3f") + " mm";
    line += "; depth " + number(v["penetration_depth_mm"], "%.3f") + " mm";
    line += "; debris front " + number(v["debris_cloud"]["leading_edge_z_mm"], "%.3f") + " mm at " +
            number(v["debris_cloud"]["leading_edge_speed_km_s"], "%.3f") + " km/s";
    line += "; energy error " + number(v["energy_error"], "%.2e");
    return line;
}

} // namespace

HviAssessTool::HviAssessTool()
    : tool::Tool("hvi-assess", "Verdict of an hvi-run run file: perforation (P/NP) of the rear "
                               "wall, penetration depth, bumper hole diameter, debris cloud, "
                               "energy error; pictures; comparison with expected results") {}

void HviAssessTool::addOptions(CLI::App& app) {
    app.add_option("run", m_run,
                   "Run file (HDF5) written by hvi-run; a partial run or the "
                   "NAME.tmp.PID of a killed run is assessed too, and labelled so")
        ->required();
    app.add_option("-o,--output", m_output, "Verdict JSON to write ('-' = stdout, the default)");
    auto* expect = app.add_option(
        "--expect", m_expect,
        "Compare with an expected outcome: an expected block {\"pnp\": \"P\"|\"NP\", "
        "\"penetration_depth_mm\", \"bumper_hole_diameter_mm\", \"core_damage_width_mm\", "
        "\"tolerances\"}, a case with \"expected\", or a file of cases such as "
        "thesis_cases.json (the case is --case, or the run's scene id). Exit 1 on a mismatch");
    app.add_option("--case", m_case, "Case id to pick from the --expect file")->needs(expect);
    app.add_option("--check", m_checks,
                   "Compare only these quantities (comma-separated): pnp, penetration_depth_mm, "
                   "bumper_hole_diameter_mm, core_damage_width_mm (default: all in the block)")
        ->delimiter(',')
        ->check(CLI::IsMember(kCheckable))
        ->needs(expect);
    auto* pictures = app.add_option(
        "--pictures", m_pictures,
        "Directory for PNG pictures (created if needed): material and damage fields mirrored "
        "about the axis, rear-wall damage profile, energy and momentum histories");
    app.add_option("--times-us", m_timesUs,
                   "Times of the field pictures [us], comma-separated; the nearest snapshot is "
                   "drawn (default: 1/4, 1/2, 3/4 and all of the last snapshot's time)")
        ->delimiter(',')
        ->check(CLI::NonNegativeNumber)
        ->needs(pictures);
    app.add_option("--view-mm", m_viewMm,
                   "Picture view: ZMIN,ZMAX,RMAX [mm] (default: the bodies and the debris)")
        ->delimiter(',')
        ->expected(3)
        ->needs(pictures);
    app.add_option("--picture-width-px", m_pictureWidth, "Picture width [px]")
        ->check(CLI::Range(320, 8000))
        ->needs(pictures);
    app.add_option("--picture-height-px", m_pictureHeight, "Picture height [px]")
        ->check(CLI::Range(240, 8000))
        ->needs(pictures);
}

void HviAssessTool::execute() {
    // Everything is read and checked before anything is written.
    std::optional<json> expectDocument;
    if (!m_expect.empty()) {
        expectDocument = io::readJsonFile(m_expect);
    }
    if (m_viewMm.size() == 3 &&
        !(std::isfinite(m_viewMm[0]) && std::isfinite(m_viewMm[1]) && std::isfinite(m_viewMm[2]) &&
          m_viewMm[1] > m_viewMm[0] && m_viewMm[2] > 0.0)) {
        throw InputError("<flags>", "--view-mm", "is not a view",
                         "ZMIN,ZMAX,RMAX [mm] with ZMAX > ZMIN and RMAX > 0");
    }
    if (m_output != "-") {
        const auto parent = std::filesystem::path(m_output).parent_path();
        if (!parent.empty() && !std::filesystem::is_directory(parent)) {
            throw RuntimeFailure("cannot write " + m_output + ": directory " + parent.string() +
                                 " does not exist");
        }
    }
    const io::RunFileReader reader(m_run);

    assess::AssessOptions options;
    std::vector<int> pictureIndices;
    if (!m_pictures.empty()) {
        pictureIndices = assess::pictureSnapshots(reader.snapshots(), m_timesUs);
        options.keepSnapshots.insert(pictureIndices.begin(), pictureIndices.end());
        if (!reader.snapshots().empty()) {
            options.keepSnapshots.insert(reader.snapshots().back().index);
        }
    }
    const assess::Assessment assessment = assess::assessRun(reader, options);

    json verdict = assess::verdictJson(assessment);
    std::optional<assess::Expectation> expectation;
    if (expectDocument) {
        const auto block = assess::selectExpected(
            *expectDocument, m_expect,
            m_case.empty() ? std::nullopt : std::optional<std::string>(m_case),
            assessment.layout.sceneId);
        expectation = assess::compareWithExpected(
            block, assessment, std::set<std::string>(m_checks.begin(), m_checks.end()));
        verdict["expectation"] = expectation->toJson();
    }
    json resolved = {
        {"run_file", m_run}, {"output", m_output}, {"criteria", assessment.criteria.toJson()}};
    if (!m_expect.empty()) {
        resolved["expect"] = m_expect;
        resolved["case"] = m_case.empty() ? json(nullptr) : json(m_case);
        resolved["check"] = m_checks;
    }
    if (!m_pictures.empty()) {
        resolved["pictures"] = m_pictures;
        resolved["times_us"] = m_timesUs;
        resolved["picture_width_px"] = m_pictureWidth;
        resolved["picture_height_px"] = m_pictureHeight;
        resolved["view_mm"] = m_viewMm.empty() ? json(nullptr) : json(m_viewMm);
    }
    verdict["provenance"] = provenance(m_run, resolved);

    for (const auto& w : assessment.warnings) {
        warn(w);
    }

    // Outputs: pictures first (the verdict lists them), then the verdict.
    if (!m_pictures.empty()) {
        assess::PictureOptions po;
        po.directory = m_pictures;
        po.widthPx = m_pictureWidth;
        po.heightPx = m_pictureHeight;
        if (m_viewMm.size() == 3) {
            po.view = std::array<double, 3>{m_viewMm[0], m_viewMm[1], m_viewMm[2]};
        }
        verdict["pictures"] = assess::writePictures(assessment, pictureIndices, po);
    }
    io::writeTextAtomically(m_output, io::jsonText(verdict, 2) + "\n");
    info(m_run + ": " + summaryLine(verdict));
    if (expectation) {
        // The result of the check the user asked for: printed even with --quiet.
        std::cerr << name() << ": " << expectation->reportLine() << "\n";
        if (!expectation->passed) {
            setCheckFailed();
        }
    }
}

} // namespace hvi::app
