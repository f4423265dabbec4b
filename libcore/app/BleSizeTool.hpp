// ble-size: ballistic-limit sizing of a shield for a threat (the first step of the design
// workflow). Reads constraints (schemas/constraints.schema.json) from a file and/or flags,
// writes the sizing document (schemas/sizing.schema.json), and optionally the ballistic
// limit curve as CSV and as an SVG/PNG plot with test points overlaid.
#pragma once

#include "tool/Tool.hpp"

#include <map>
#include <string>

namespace hvi::app {

class BleSizeTool : public tool::Tool {
public:
    BleSizeTool();

protected:
    void addOptions(CLI::App& app) override;
    void execute() override;
    std::string inputSchemaName() const override { return "constraints"; }

private:
    std::string m_input;
    std::string m_output = "-";
    std::string m_curveCsv, m_plot, m_overlay;
    std::string m_mode, m_type, m_nnoConstants;
    bool m_thesisCompat = false;
    bool m_listMaterials = false;
    /// Flag values by JSON pointer into the constraints document (set only when given).
    std::map<std::string, double> m_numbers;
    std::map<std::string, std::string> m_strings;
};

} // namespace hvi::app
