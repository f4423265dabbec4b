// Checkpoints: a bitwise round trip, atomic replacement, and errors that name what is wrong.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "io/Checkpoint.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <limits>

using namespace hvi::io;
using hvi::InputError;
using hvi::RuntimeFailure;
namespace fs = std::filesystem;

namespace {

CheckpointState sampleState() {
    CheckpointState state;
    state.timeUs = 1.0 / 3.0;
    state.step = 123456789012L; // beyond 32 bits
    state.doubles["z"] = {-0.0, std::numeric_limits<double>::denorm_min(), 1.0e300, 0.1, -2.5};
    state.doubles["vz"] = {std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN(), 6.76};
    state.doubles["empty"] = {};
    state.ints["body_id"] = {0, 1, -7, std::numeric_limits<int32_t>::max()};
    state.ints["alive"] = {1, 0, 1};
    state.extra = {{"next_snapshot", 4},
                   {"deleted_energy_J", 0.125},
                   {"scene_sha256", "ab12"},
                   {"counters", {{"deleted", 3}, {"eroded", 0}}}};
    return state;
}

/// Byte-wise equality of double arrays (NaN == NaN, -0 != +0).
bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

fs::path freshPath(const std::string& name) {
    const fs::path path = hvi::test::tempPath(name);
    fs::remove(path);
    return path;
}

template <class Fn>
hvi::InputIssue inputIssueOf(Fn&& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        EXPECT_EQ(e.issues().size(), 1u);
        return e.issues().front();
    }
    ADD_FAILURE() << "no InputError thrown";
    return {};
}

/// Files in the directory of `path` whose names start with its file name (temporaries).
std::vector<std::string> siblingsOf(const fs::path& path) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path.parent_path())) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(path.filename().string(), 0) == 0) {
            names.push_back(name);
        }
    }
    return names;
}

} // namespace

TEST(Checkpoint, RoundTripIsBitwise) {
    const fs::path path = freshPath("state.ckpt.h5");
    const CheckpointState written = sampleState();
    writeCheckpoint(path, written);
    const CheckpointState read = readCheckpoint(path);

    EXPECT_EQ(std::memcmp(&read.timeUs, &written.timeUs, sizeof(double)), 0);
    EXPECT_EQ(read.step, written.step);
    ASSERT_EQ(read.doubles.size(), written.doubles.size());
    for (const auto& [name, values] : written.doubles) {
        ASSERT_TRUE(read.doubles.count(name)) << name;
        EXPECT_TRUE(sameBits(read.doubles.at(name), values)) << name;
    }
    EXPECT_EQ(read.ints, written.ints);
    EXPECT_EQ(read.extra, written.extra);
    EXPECT_EQ(siblingsOf(path), std::vector<std::string>{"state.ckpt.h5"}) << "temporary left";
}

TEST(Checkpoint, EmptyStateRoundTrips) {
    const fs::path path = freshPath("empty.ckpt.h5");
    writeCheckpoint(path, CheckpointState{});
    const CheckpointState read = readCheckpoint(path);
    EXPECT_EQ(read.timeUs, 0.0);
    EXPECT_EQ(read.step, 0);
    EXPECT_TRUE(read.doubles.empty());
    EXPECT_TRUE(read.ints.empty());
    EXPECT_EQ(read.extra, nlohmann::json::object());
}

TEST(Checkpoint, NewerCheckpointReplacesOlder) {
    const fs::path path = freshPath("replace.ckpt.h5");
    CheckpointState state = sampleState();
    writeCheckpoint(path, state);
    state.step += 1;
    state.doubles.erase("vz");
    state.doubles["z"][0] = 42.0;
    writeCheckpoint(path, state);
    const CheckpointState read = readCheckpoint(path);
    EXPECT_EQ(read.step, state.step);
    EXPECT_EQ(read.doubles.count("vz"), 0u);
    EXPECT_EQ(read.doubles.at("z")[0], 42.0);
    EXPECT_EQ(siblingsOf(path), std::vector<std::string>{"replace.ckpt.h5"});
}

TEST(Checkpoint, FailedWriteKeepsThePreviousCheckpoint) {
    const fs::path path = freshPath("keep.ckpt.h5");
    const CheckpointState good = sampleState();
    writeCheckpoint(path, good);
    CheckpointState bad = good;
    bad.step = 1;
    bad.doubles["a/b"] = {1.0};
    EXPECT_THROW(writeCheckpoint(path, bad), RuntimeFailure);
    bad.doubles.erase("a/b");
    bad.ints[""] = {1};
    EXPECT_THROW(writeCheckpoint(path, bad), RuntimeFailure);
    EXPECT_EQ(readCheckpoint(path).step, good.step);
    EXPECT_EQ(siblingsOf(path), std::vector<std::string>{"keep.ckpt.h5"});
    EXPECT_THROW(writeCheckpoint(hvi::test::tempPath("no/such/dir/x.ckpt.h5"), good),
                 RuntimeFailure);
}

TEST(Checkpoint, ReadErrorsNameTheFileAndPath) {
    const fs::path missing = freshPath("missing.ckpt.h5");
    const auto absent = inputIssueOf([&] { (void)readCheckpoint(missing); });
    EXPECT_EQ(absent.file, missing.string());
    EXPECT_EQ(absent.problem, "no such file");

    const fs::path text = hvi::test::tempPath("text.ckpt.h5");
    std::ofstream(text) << "not a checkpoint\n";
    const auto notHdf5 = inputIssueOf([&] { (void)readCheckpoint(text); });
    EXPECT_EQ(notHdf5.pointer, "/");
    EXPECT_EQ(notHdf5.problem, "not an HDF5 file");

    const fs::path damaged = freshPath("damaged.ckpt.h5");
    writeCheckpoint(damaged, sampleState());
    const hid_t file = H5Fopen(damaged.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, "/extra", H5P_DEFAULT), 0);
    H5Fclose(file);
    const auto noExtra = inputIssueOf([&] { (void)readCheckpoint(damaged); });
    EXPECT_EQ(noExtra.pointer, "/extra");
    EXPECT_EQ(noExtra.problem, "missing");

    const fs::path other = freshPath("other.ckpt.h5");
    const hid_t plain = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(plain, 0);
    H5Fclose(plain);
    EXPECT_EQ(inputIssueOf([&] { (void)readCheckpoint(other); }).pointer, "/@Format");
}

TEST(Checkpoint, PathBesideTheRunFile) {
    EXPECT_EQ(checkpointPathFor("out/run.h5"), fs::path("out/run.ckpt.h5"));
    EXPECT_EQ(checkpointPathFor("case7"), fs::path("case7.ckpt.h5"));
}
