// hvi-assess: the verdict of one hvi-run run file (the last step of the design workflow).
//
//   hvi-assess RUN.h5 [-o VERDICT.json] [--expect EXPECTED.json [--case ID] [--check LIST]]
//                     [--pictures DIR [--times-us LIST] [--view-mm Z0,Z1,R]
//                      [--picture-width-px W] [--picture-height-px H]]
//
// Reads the run (complete, partial or from a killed run), evaluates the metrics of
// docs/metrics.md, writes the verdict (schemas/verdict.schema.json; default stdout), and with
// --pictures the material and damage pictures, the rear-wall damage profile and the energy
// and momentum histories. With --expect it compares the verdict with an expected outcome and
// prints one line "hvi-assess: expect ID: PASS|FAIL: ..." on stderr; the exit status is then
// 1 when a check fails (docs/conventions.md), the verdict being written all the same.
// A bad run file or expectation file is exit 2 with nothing written.
#pragma once

#include "tool/Tool.hpp"

#include <string>
#include <vector>

namespace hvi::app {

class HviAssessTool : public tool::Tool {
public:
    HviAssessTool();

protected:
    void addOptions(CLI::App& app) override;
    void execute() override;

private:
    std::string m_run;
    std::string m_output = "-";
    std::string m_expect;
    std::string m_case;
    std::vector<std::string> m_checks;
    std::string m_pictures;
    std::vector<double> m_timesUs;
    std::vector<double> m_viewMm;
    int m_pictureWidth = 1200;
    int m_pictureHeight = 800;
};

} // namespace hvi::app
