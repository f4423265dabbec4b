// Hostile but fair inputs (issue #25) through the built tools: each is refused with the
// README's one-line error and exit code, or fails cleanly, and leaves no output behind.
// None may crash.
#include "AssessScenes.hpp"
#include "RunTool.hpp"
#include "io/AtomicOutput.hpp"
#include "io/RunFileReader.hpp"

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace hvi::test;
namespace fs = std::filesystem;

namespace {

// A scene that runs in about a second, for the tests that must show a run is not started.
const char* kScene = R"({"id": "hostile", "geometry": "axisymmetric",
  "sph": {"particle_spacing_mm": 0.1},
  "run": {"end_time_us": 0.02, "stop_debris_speed_km_s": 0, "stop_no_new_penetration_us": 0},
  "output": {"snapshot_every_us": 0.01},
  "domain": {"radius_mm": 2.0},
  "bodies": [
    {"name": "ball", "role": "projectile", "material": "Al6061-T6",
     "shape": {"type": "sphere", "center_z_mm": -0.6, "radius_mm": 0.5},
     "velocity": {"z_km_s": 3.0}},
    {"name": "plate", "role": "bumper", "material": "Al6061-T6",
     "shape": {"type": "plate", "z_front_mm": 0.0, "thickness_mm": 0.5, "outer_radius_mm": 1.5}}
  ]})";

const char* kConstraints = R"({"threat": {"diameter_mm": 3.6, "velocity_km_s": 6.76},
  "shield": {"type": "foam_sandwich", "facesheet_mm": 0.254, "core_thickness_mm": 50.8,
             "relative_density_percent": 7, "ppi": 10}})";

std::string nestedArrays(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

/// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

fs::path freshOutput(const std::string& name) {
    const auto path = tempPath(name);
    fs::remove_all(path);
    return path;
}

/// Exit `code` and exactly one line on stderr, beginning with `prefix`.
::testing::AssertionResult oneLine(const ToolResult& r, int code, const std::string& prefix) {
    std::vector<std::string> lines;
    std::istringstream in(r.err);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    if (r.exitCode != code || lines.size() != 1 || lines[0].rfind(prefix, 0) != 0) {
        return ::testing::AssertionFailure()
               << "expected exit " << code << " and one line beginning '" << prefix
               << "'; got exit " << r.exitCode << " and " << lines.size() << " lines:\n"
               << r.err.substr(0, 2000);
    }
    return ::testing::AssertionSuccess();
}

/// Runs a tool without a shell and returns its peak resident memory [kB] (its own, not that
/// of the other tools this test binary ran).
long peakMemoryKb(const std::string& tool, const std::vector<std::string>& args) {
    const std::string path = toolPath(tool).string();
    std::vector<char*> argv{const_cast<char*>(path.c_str())};
    for (const auto& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int devNull = ::open("/dev/null", O_WRONLY);
        ::dup2(devNull, 1);
        ::dup2(devNull, 2);
        ::execv(path.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    ::wait4(pid, &status, 0, &usage);
    return usage.ru_maxrss;
}

} // namespace

// Item 1: a value nested 30,000 levels deep overflowed the stack of ble-size (the finite-
// number check) and hvi-run (the free-form /summary).
TEST(HostileInput, DeepNestingIsBadInput) {
    const auto constraints =
        writeTemp("deep.constraints.json", "{\"threat\": " + nestedArrays(30000) + "}");
    const auto sizing = freshOutput("deep.sizing.json");
    const auto r = runTool("ble-size", constraints.string() + " -o " + sizing.string());
    EXPECT_TRUE(oneLine(r, 2, "ble-size: " + constraints.string() + ": /threat/0/0/0"));
    EXPECT_NE(r.err.find("256 levels"), std::string::npos) << r.err.substr(0, 2000);
    EXPECT_FALSE(fs::exists(sizing));

    const auto scene =
        writeTemp("deep.scene.json",
                  replaced(kScene, "\"geometry\"",
                           "\"summary\": {\"notes\": " + nestedArrays(30000) + "}, \"geometry\""));
    const auto run = freshOutput("deep.h5");
    const auto s = runTool("hvi-run", scene.string() + " -o " + run.string());
    EXPECT_TRUE(oneLine(s, 2, "hvi-run: " + scene.string() + ": /summary/notes/0/0"));
    EXPECT_FALSE(fs::exists(run));

    // A material library given with --materials goes through the same reader.
    const auto library =
        writeTemp("deep.materials.json", "{\"materials\": " + nestedArrays(30000) + "}");
    const auto plain = writeTemp("plain.scene.json", kScene);
    const auto m = runTool("hvi-run", plain.string() + " --materials " + library.string() + " -o " +
                                          run.string());
    EXPECT_TRUE(oneLine(m, 2, "hvi-run: " + library.string() + ": /materials/0/0"));
    EXPECT_FALSE(fs::exists(run));
}

// Item 2: every JSON reader crashed on a broken file with a long whitespace run (the regex
// of the NaN re-scan recursed once per character).
TEST(HostileInput, LongWhitespaceRunIsASyntaxError) {
    const auto input = writeTemp("whitespace.json", "{\"threat\":" + std::string(100000, '\n'));
    for (const std::string tool : {"ble-size", "foam2layers", "hcomb2rings", "hvi-run"}) {
        const auto output = freshOutput("whitespace." + tool + ".out");
        const auto r = runTool(tool, input.string() + " -o " + output.string());
        EXPECT_TRUE(oneLine(r, 2, tool + ": " + input.string() + ": /: not valid JSON")) << tool;
        EXPECT_NE(r.err.find("line 100001"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(output)) << tool;
    }
    // hvi-assess reads its --expect file before the run file.
    const auto verdict = freshOutput("whitespace.verdict.json");
    const auto r = runTool("hvi-assess", tempPath("no-such-run.h5").string() + " --expect " +
                                             input.string() + " -o " + verdict.string());
    EXPECT_TRUE(oneLine(r, 2, "hvi-assess: " + input.string() + ": /: not valid JSON"));
    EXPECT_FALSE(fs::exists(verdict));
}

// Item 2, minor: a 50 MB file cost 1.5 GB in the non-finite scan (a regex copy of the
// text, then a parse of the copy). The scan now reads the text in place.
TEST(HostileInput, LargeFileIsScannedInPlace) {
    const auto input = tempPath("large.constraints.json");
    {
        std::ofstream out(input);
        out << R"({"threat": {"diameter_mm": NaN, "velocity_km_s": 6}, "x": [1.5)";
        for (int i = 0; i < 12'500'000; ++i) {
            out << ",1.5";
        }
        out << "]}";
    }
    ASSERT_GT(fs::file_size(input), 50'000'000u);
    const long peakKb = peakMemoryKb("ble-size", {input.string()});
    EXPECT_LT(peakKb, 200'000) << "peak resident memory for a 50 MB file";
    const auto r = runTool("ble-size", input.string());
    EXPECT_TRUE(oneLine(r, 2, "ble-size: " + input.string() + ": /threat/diameter_mm: is NaN"));
    fs::remove(input);
}

// Minor: 1e400 gave exit 3 "internal error" with no pointer.
TEST(HostileInput, NumberBeyondADoubleIsBadInput) {
    const auto input = writeTemp("overflow.json", replaced(kConstraints, "3.6", "1e400"));
    const auto output = freshOutput("overflow.sizing.json");
    const auto r = runTool("ble-size", input.string() + " -o " + output.string());
    EXPECT_TRUE(oneLine(r, 2, "ble-size: " + input.string() + ": /threat/diameter_mm: is 1e400"));
    EXPECT_FALSE(fs::exists(output));
}

// Minor: a directory given as the input was called "not valid JSON".
TEST(HostileInput, DirectoryIsCalledADirectory) {
    const auto directory = tempPath("a-directory.json");
    fs::create_directories(directory);
    for (const std::string tool : {"ble-size", "foam2layers", "hcomb2rings", "hvi-run"}) {
        const auto r = runTool(tool, directory.string() + " -o " + tempPath("dir.out").string());
        EXPECT_EQ(r.exitCode, 2) << tool;
        EXPECT_NE(r.err.find("directory"), std::string::npos) << tool << ": " << r.err;
    }
    const auto r = runTool("hvi-assess", "no-such-run.h5 --expect " + directory.string());
    EXPECT_TRUE(oneLine(r, 2, "hvi-assess: " + directory.string() + ": /: is a directory"));
}

// A file name that is not UTF-8 (written in another encoding) ended every tool on an internal
// error when its output's provenance was written; the bad bytes now come out as U+FFFD.
TEST(HostileInput, AFileNameThatIsNotUtf8IsKept) {
    const auto input = writeTemp("latin1-\xe9.json", kConstraints);
    const auto output = freshOutput("latin1.sizing.json");
    const auto r = runTool("ble-size", "'" + input.string() + "' -q -o " + output.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFileText(output).find("latin1-\ufffd.json"), std::string::npos);
}

// Item 8: d_c = inf was written as null and called NP, exit 0.
TEST(HostileInput, InfiniteCriticalDiameterIsAComputationFailure) {
    const auto input = writeTemp("inf.json", replaced(kConstraints, "50.8", "1e308"));
    const auto output = freshOutput("inf.sizing.json");
    const auto r = runTool("ble-size", input.string() + " -o " + output.string());
    EXPECT_TRUE(oneLine(r, 3, "ble-size: error: "));
    EXPECT_NE(r.err.find("/performance/critical_diameter_mm"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(output));
}

// Item 10: NaN flag values were ignored (--resolution-mm nan ran at the scene's spacing,
// --times-us nan drew t = 0). Every numeric flag refuses NaN and infinities.
TEST(HostileInput, NonFiniteFlagValuesAreRefused) {
    const auto scene = writeTemp("flags.scene.json", kScene);
    const auto run = freshOutput("flags.h5");
    for (const std::string flag :
         {"--resolution-mm nan", "--end-time-us nan", "--snapshot-every-us inf",
          "--checkpoint-every-s nan", "--end-time-us 1e400"}) {
        fs::remove(run);
        const auto r =
            runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1 " + flag);
        EXPECT_TRUE(oneLine(r, 2, "hvi-run: <flags>: " + flag.substr(0, flag.find(' ')) + ": "))
            << flag;
        EXPECT_FALSE(fs::exists(run)) << flag;
    }
    hvi::test::SyntheticRun synthetic(whippleScene());
    synthetic.addSnapshot(0.5);
    const auto runFile = synthetic.write(tempPath("flags.assess.h5"));
    const auto pictures = freshOutput("flags.pictures");
    const auto verdict = freshOutput("flags.verdict.json");
    const auto r =
        runTool("hvi-assess", runFile.string() + " -o " + verdict.string() + " --pictures " +
                                  pictures.string() + " --times-us 0.5,nan");
    EXPECT_TRUE(oneLine(r, 2, "hvi-assess: <flags>: --times-us: "));
    EXPECT_FALSE(fs::exists(verdict));
    // Flags that set a value of the input document keep naming its JSON pointer.
    const auto b = runTool("ble-size", "--type whipple --diameter-mm inf --velocity-km-s 6 "
                                       "--bumper-mm 1 --rear-wall-mm 1 --standoff-mm 50");
    EXPECT_TRUE(oneLine(b, 2, "ble-size: <flags>: /threat/diameter_mm: is inf (--diameter-mm)"));
}

// Minor: `hvi-run -` did not read the scene from standard input, as the README says every
// tool does.
TEST(HostileInput, HviRunReadsTheSceneFromStdin) {
    const auto run = freshOutput("stdin.h5");
    const auto r = runTool("hvi-run", "- -q --threads 1 -o " + run.string(), kScene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const hvi::io::RunFileReader reader(run.string());
    EXPECT_EQ(reader.scene()["id"], "hostile");
    // Without -o there is no scene file name to put the run file beside.
    const auto noOutput = runTool("hvi-run", "-", kScene);
    EXPECT_TRUE(oneLine(noOutput, 2, "hvi-run: <flags>: --output: "));
}

// Item 5: a tiny spacing allocated until bad_alloc or spun in the particle generator; the
// run is refused before anything is allocated, naming the body, the count and the memory.
TEST(HostileInput, APointCountBeyondTheMachineIsRefusedAtOnce) {
    const auto scene = writeTemp("huge.scene.json", kScene);
    const auto run = freshOutput("huge.h5");
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() +
                                          " --resolution-mm 1e-9 --threads 1");
    EXPECT_TRUE(oneLine(r, 2, "hvi-run: " + scene.string() + ": /bodies/1: body 'plate'")) << r.err;
    EXPECT_NE(r.err.find(" GB is available"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(run));
    const auto bench = runTool("hvi-run", "--benchmark --resolution-mm 1e-9 --threads 1");
    EXPECT_TRUE(oneLine(bench, 2, "hvi-run: <benchmark>: /bodies/")) << bench.err;
}

// Item 6: a full disk while the run file is written printed the error, then crashed in the
// HDF5 library's exit-time clean-up (exit 139). A file-size limit stands in for the full
// disk (the write fails with EFBIG instead of ENOSPC, on the same path).
TEST(HostileInput, AFullDiskIsAComputationFailureNotACrash) {
    std::string text = kScene; // with an FE bumper, whose mesh must not be left either
    const std::string plate = "{\"name\": \"plate\", \"role\": \"bumper\",";
    text.replace(text.find(plate), plate.size(), plate + " \"discretization\": \"fe\",");
    const auto scene = writeTemp("full.scene.json", text);
    const auto run = freshOutput("full.h5");
    const auto errPath = tempPath("full.err");
    const std::string script = "trap '' XFSZ; ulimit -f 100; " + toolPath("hvi-run").string() +
                               " " + scene.string() + " -o " + run.string() +
                               " --threads 1 -q --snapshot-every-us 0.001 2>" + errPath.string();
    const int status = std::system(script.c_str());
    ToolResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(errPath);
    std::stringstream said;
    said << err.rdbuf();
    r.err = said.str();
    EXPECT_TRUE(oneLine(r, 3, "hvi-run: error: ")) << r.exitCode << ": " << r.err;
    EXPECT_FALSE(fs::exists(run));
    EXPECT_FALSE(hvi::io::orphanedTemporary(run).has_value());
    // Item 11: nor an FE mesh (it used to be written before the run started).
    EXPECT_FALSE(fs::exists(fs::path(run).replace_extension(".msh")));
}

// Minor: `hvi-run in.json -o in.json` replaced the scene with the run file.
TEST(HostileInput, HviRunKeepsItsScene) {
    const auto scene = writeTemp("keep.scene.json", kScene);
    const auto sameFile = (scene.parent_path() / "." / scene.filename()).string();
    for (const auto& output : {scene.string(), sameFile}) {
        const auto r = runTool("hvi-run", scene.string() + " -o " + output);
        EXPECT_TRUE(oneLine(r, 2, "hvi-run: <flags>: --output: ")) << output;
    }
    // Nor may a sidecar of the run file (here the XDMF) replace it.
    const auto xmfScene = writeTemp("keep.xmf", kScene);
    const auto r = runTool("hvi-run", xmfScene.string() + " -o " + tempPath("keep.h5").string());
    EXPECT_TRUE(oneLine(r, 2, "hvi-run: <flags>: --output: "));
    std::ifstream in(scene);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), kScene);
}
