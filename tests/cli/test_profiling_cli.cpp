// `dermis render --timings FILE.json|FILE.csv --trace FILE.json --warm-up N`
// (docs/profiling.md): every frame's samples, a summary over the frames after
// the warm-up that is computed here again from those samples, and a trace in
// the Trace Event format whose slices are those samples to the nanosecond.
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

using dermis::test::ProcessResult;
using dermis::test::readTextFile;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kRun = " --size 160x90 --frames 5 --warm-up 1 --quiet";
// The trace holds a pass's milliseconds x 1000 as microseconds: the same double
// but for the product's rounding, far below this (a nanosecond).
constexpr double kMicrosecondTolerance = 1e-3;

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Slice {
    double begin, end;
};

// Slices on one thread either do not overlap or one holds the other (what
// the Trace Event format asks of complete events on one thread).
void expectNested(std::vector<Slice> slices, const std::string& thread) {
    std::sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.begin < b.begin || (a.begin == b.begin && a.end > b.end); });
    std::vector<Slice> open;
    for (const Slice& s : slices) {
        while (!open.empty() && open.back().end <= s.begin + kMicrosecondTolerance) open.pop_back();
        if (!open.empty()) {
            EXPECT_LE(s.end, open.back().end + kMicrosecondTolerance)
                << thread << ": a slice at " << s.begin << " overlaps the end of one at " << open.back().begin;
        }
        open.push_back(s);
    }
}

}  // namespace

// ctest: cost=8
TEST(ProfilingCli, TheTraceIsTheTimingsFrameByFrame) {
    TempDir dir;
    const ProcessResult r = runProcess(kDermis + " render " + dermis::test::contentScene("default.json") + kRun + " --out " +
                                       dir.file("x.png") + " --timings " + dir.file("t.json") + " --trace " + dir.file("trace.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json timings = nlohmann::json::parse(readTextFile(dir.file("t.json")));
    const nlohmann::json trace = nlohmann::json::parse(readTextFile(dir.file("trace.json")));

    // The summary, again from the frames after the warm-up.
    ASSERT_EQ(timings["per_frame"].size(), 6u);
    EXPECT_EQ(timings["warm_up_frames"], 1);
    EXPECT_TRUE(timings["per_frame"][0]["warm_up"].get<bool>());
    std::map<std::string, std::vector<double>> gpuByPass;
    size_t samples = 0;
    for (const auto& frame : timings["per_frame"]) {
        samples += frame["passes"].size();
        if (frame["warm_up"].get<bool>()) continue;
        for (const auto& pass : frame["passes"]) gpuByPass[pass["name"]].push_back(pass["gpu_ms"].get<double>());
    }
    int executed = 0;
    for (const auto& pass : timings["passes"]) {
        if (!pass["executed"].get<bool>()) continue;
        ++executed;
        const std::string name = pass["name"];
        EXPECT_DOUBLE_EQ(pass["gpu_ms"].get<double>(), medianOf(gpuByPass[name])) << name;
        EXPECT_LE(pass["gpu_p5_ms"].get<double>(), pass["gpu_ms"].get<double>()) << name;
        EXPECT_GE(pass["gpu_p95_ms"].get<double>(), pass["gpu_ms"].get<double>()) << name;
    }
    EXPECT_GE(executed, 6);

    // The trace: the format's rules, then every slice against its sample.
    ASSERT_TRUE(trace["traceEvents"].is_array());
    std::map<int, std::vector<Slice>> threads;
    std::map<std::string, double> gpuSlice, cpuSlice;  // "frame/pass" -> dur
    std::map<std::string, std::string> instants;       // "frame/pass" -> because
    for (const auto& event : trace["traceEvents"]) {
        ASSERT_TRUE(event["name"].is_string());
        ASSERT_TRUE(event["ph"].is_string());
        EXPECT_EQ(event["pid"], 1);
        const std::string phase = event["ph"];
        ASSERT_TRUE(phase == "X" || phase == "i" || phase == "M") << phase;
        if (phase == "M") continue;
        ASSERT_TRUE(event["ts"].is_number() && event["tid"].is_number_integer()) << event.dump();
        const std::string key = std::to_string(event["args"]["frame"].get<int>()) + "/";
        if (phase == "i") {
            EXPECT_EQ(event["s"], "t");
            instants[key + event["args"]["pass"].get<std::string>()] = event["args"]["because"];
            continue;
        }
        ASSERT_TRUE(event["dur"].is_number() && event["dur"].get<double>() >= 0.0) << event.dump();
        threads[event["tid"]].push_back({event["ts"].get<double>(), event["ts"].get<double>() + event["dur"].get<double>()});
        if (event["cat"] == "frame") continue;
        (event["tid"] == 2 ? gpuSlice : cpuSlice)[key + event["name"].get<std::string>()] = event["dur"];
    }
    EXPECT_EQ(cpuSlice.size(), samples);
    EXPECT_EQ(gpuSlice.size(), samples) << "llvmpipe has GL_TIMESTAMP: every pass has a GPU slice";
    for (const auto& frame : timings["per_frame"]) {
        const std::string key = std::to_string(frame["frame"].get<int>()) + "/";
        for (const auto& pass : frame["passes"]) {
            const std::string name = key + pass["name"].get<std::string>();
            EXPECT_NEAR(gpuSlice[name], 1e3 * pass["gpu_ms"].get<double>(), kMicrosecondTolerance) << name;
            EXPECT_NEAR(cpuSlice[name], 1e3 * pass["cpu_ms"].get<double>(), kMicrosecondTolerance) << name;
        }
        for (const auto& culled : frame["culled"]) {
            const std::string name = key + culled["name"].get<std::string>();
            ASSERT_TRUE(instants.count(name)) << name;
            EXPECT_EQ(instants[name], culled["because"]) << name;
        }
    }
    EXPECT_GE(instants.size(), 6u) << "the default head's frames cull passes (texture space, cached shadows)";
    for (const auto& [thread, slices] : threads) expectNested(slices, "thread " + std::to_string(thread));

    // The CSV: one row per pass per frame, the warm-up marked.
    const ProcessResult csvRun = runProcess(kDermis + " render " + dermis::test::contentScene("default.json") + kRun +
                                            " --out " + dir.file("y.png") + " --timings " + dir.file("t.csv"));
    ASSERT_EQ(csvRun.exitCode, 0) << csvRun.err;
    std::istringstream csv(readTextFile(dir.file("t.csv")));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "frame,warm_up,pass,gpu_ms,cpu_ms,gpu_begin_ms,cpu_begin_ms");
    size_t rows = 0, warmUpRows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        warmUpRows += line.rfind("0,1,", 0) == 0;
    }
    EXPECT_EQ(rows, samples) << "the same scene and frames";
    EXPECT_EQ(warmUpRows, timings["per_frame"][0]["passes"].size());
}

TEST(ProfilingCli, BadTimingsOrTraceFilesAreUsageErrors) {
    TempDir dir;
    const std::pair<std::string, std::string> cases[] = {
        {" --frames 1 --timings " + dir.file("t.txt"), "the file must end in .json or .csv"},
        {" --frames 1 --trace " + dir.file("t.csv"), "the file must end in .json"},
        {" --frames 1 --warm-up -1", "expected a non-negative integer"},
        {" --warm-up 1 --sequence 0:1:2", "not with --sequence"},
    };
    for (const auto& [option, message] : cases) {
        const ProcessResult r = runProcess(kDermis + " render " + dermis::test::contentScene("default.json") +
                                           " --size 32x18 --quiet --out " + dir.file("x.png") + option);
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << option << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.png"))) << option;
    }
}
