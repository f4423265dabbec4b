// hvi-run: the explicit 2D axisymmetric SPH hydrocode. Reads a scene
// (schemas/scene.schema.json), writes an HDF5 run file with an XDMF sidecar, shows progress
// on stderr, checkpoints and resumes. `--benchmark` measures throughput on the built-in
// bumper case.
#pragma once

#include "app/RunScene.hpp"
#include "tool/Tool.hpp"

namespace hvi::app {

class HviRunTool : public tool::Tool {
public:
    HviRunTool();

protected:
    void addOptions(CLI::App& app) override;
    void execute() override;
    std::string inputSchemaName() const override { return "scene"; }

private:
    void benchmark();
    RunScene loadScene() const;
    void checkScene() const;

    std::string m_scene, m_output, m_materials;
    int m_threads = 0;
    double m_resolution = 0.0, m_endTime = 0.0, m_snapshotEvery = 0.0;
    double m_checkpointEvery = 300.0;
    bool m_resume = false, m_benchmark = false, m_listMaterials = false, m_check = false;
    long m_benchmarkSteps = 200;
    std::string m_benchmarkScene = "both";
};

} // namespace hvi::app
