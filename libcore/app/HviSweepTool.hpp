// hvi-sweep: the hydrocode's own ballistic limit (workflows/sweep.mk). For one shield and one
// speed it brackets the projectile diameter (or rear-wall thickness) at which the simulated
// verdict flips, starting from the ballistic limit equation's value; the workflow runs the
// points it asks for and `report` gathers the speeds.
//
//   hvi-sweep init (--case ID | --panel FILE --writer NAME [--constraints FILE])
//                  --parameter diameter|rear_wall --speed-km-s V --out-dir DIR
//                  [--tolerance-mm 0.1] [--step-factor 1.25] [--max-points 12]
//       writes DIR/sweep.json (refuses a DIR holding another sweep);
//   hvi-sweep next DIR
//       prints the directory of the next point to run (after writing its panel.json and
//       writer), or nothing once the search has stopped (then DIR/critical.json exists);
//   hvi-sweep report --out-dir OUT -o FILE.csv [--plot FILE.svg]
//       the speeds of OUT/*/ as a CSV and a plot over the equation's curve with the tests
//       of the same shield.
// Layout and search: libcore/sweep/SweepSpec.hpp, Bisection.hpp.
#pragma once

#include "tool/Tool.hpp"

#include <string>

namespace hvi::app {

class HviSweepTool : public tool::Tool {
public:
    HviSweepTool();

protected:
    void addOptions(CLI::App& app) override;
    void execute() override;

private:
    void init();
    void next();
    void report();

    std::string m_action;
    std::string m_dir; ///< next: the sweep directory
    std::string m_case, m_panel, m_writer, m_constraints;
    std::string m_parameter = "diameter";
    double m_speed = 0.0;
    double m_tolerance = 0.1;
    double m_stepFactor = 1.25;
    int m_maxPoints = 12;
    std::string m_outDir;
    std::string m_output;
    std::string m_plot;
};

} // namespace hvi::app
