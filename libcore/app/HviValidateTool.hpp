// hvi-validate: the validation cases (libcore/validation) for the workflow that measures the
// toolkit's verdicts against the tests (workflows/validate.mk, docs/validation.md).
//
//   hvi-validate list [--set all|source_study|development|quick]
//       prints the case ids, one per line (Make reads them);
//   hvi-validate inputs CASE --out-dir DIR
//       writes DIR/panel.json (the scene writer's input), DIR/constraints.json (ble-size's)
//       and DIR/writer (the scene writer's name);
//   hvi-validate report --out-dir DIR [--set NAME] [--resolution-mm TEXT] -o FILE
//       writes the markdown report from DIR/<case>/verdict.json and ble.json;
//   hvi-validate progress --out-dir DIR [--set NAME] [--jobs N]
//       one line on stderr: cases done, left, and the time to go;
//   hvi-validate convergence [CASE] --out-dir DIR -o FILE.md [--csv FILE] [--plot FILE.png]
//                [--measured-hole-mm D] [--setup TEXT]
//       the spacing ladder of DIR/s<spacing>/verdict.json (make convergence): error against
//       run time, observed order, Richardson estimate (validation/ConvergenceReport.hpp);
//   hvi-validate extreme --out-dir DIR -o FILE.md
//       the stiff and extreme suite's table from DIR/<case>/run.h5 (validation/StressSuite.hpp).
// Bad input (an unknown action, case or set) is one line naming it, exit 2, nothing written.
#pragma once

#include "tool/Tool.hpp"

#include <string>
#include <vector>

namespace hvi::app {

class HviValidateTool : public tool::Tool {
public:
    HviValidateTool();

protected:
    void addOptions(CLI::App& app) override;
    void execute() override;

private:
    void convergence() const;

    std::string m_action;
    std::string m_case;
    std::string m_set = "all";
    std::string m_outDir;
    std::string m_output = "-";
    std::string m_resolution;
    std::vector<std::string> m_compareKept;
    std::vector<std::string> m_sensitivityKept;
    int m_jobs = 1;
    bool m_interleave = false;
    std::string m_csv, m_plot, m_setup;
    double m_measuredHoleMm = 0.0;
};

} // namespace hvi::app
