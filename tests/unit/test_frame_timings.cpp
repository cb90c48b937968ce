// Per-frame timings and the trace made from them (render/FrameTimings.h,
// render/TraceEvents.h), on made-up frames, without a GPU: percentiles
// against numpy's definition worked by hand, warm-up frames kept out of the
// summary but in the frames, and the trace's slices against the samples.
#include "render/FrameTimings.h"
#include "render/TraceEvents.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace dermis {
namespace {

gl::PassTiming timing(uint64_t frame, const std::string& pass, double gpuMs, double cpuMs, double gpuBeginMs,
                      double cpuBeginMs) {
    gl::PassTiming t;
    t.frame = frame;
    t.pass = pass;
    t.gpuMs = gpuMs;
    t.cpuMs = cpuMs;
    t.gpuBeginMs = gpuBeginMs;
    t.cpuBeginMs = cpuBeginMs;
    return t;
}

TEST(FrameTimings, PercentilesInterpolateBetweenOrderStatistics) {
    // numpy.percentile([4, 1, 3, 2], p): position p/100 x 3 between the sorted values.
    EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 5.0), 1.15);
    EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 95.0), 3.85);
    EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 50.0), median({4, 1, 3, 2}));
    EXPECT_DOUBLE_EQ(percentile({7.0}, 5.0), 7.0);
    EXPECT_DOUBLE_EQ(percentile({}, 50.0), 0.0);
    const Distribution d = distributionOf({4, 1, 3, 2});
    EXPECT_DOUBLE_EQ(d.median, 2.5);
    EXPECT_DOUBLE_EQ(d.p5, 1.15);
    EXPECT_DOUBLE_EQ(d.p95, 3.85);
    EXPECT_DOUBLE_EQ(d.spread(), (3.85 - 1.15) / 2.5);
    EXPECT_DOUBLE_EQ(distributionOf({7.0, 1.0, 4.0}).median, 4.0);
}

// Frame 0 is a warm-up with an 8 ms pass; frames 1-4 take 1, 2, 3, 4 ms in
// "lighting"; "shadow" runs in frame 0 only and is culled after.
FrameTimings fourFramesAfterAWarmUp() {
    FrameTimings timings;
    timings.setWarmUpFrames(1);
    for (uint64_t frame = 0; frame < 5; ++frame) {
        const bool first = frame == 0;
        timings.addPassReports(frame, {{"shadow", first, first ? graph::CullReason::None : graph::CullReason::Predicate,
                                        first ? "" : "shadow map cached"},
                                       {"lighting", true, graph::CullReason::None, ""}});
        std::vector<gl::PassTiming> timers;
        const double start = 10.0 * double(frame);
        if (first) timers.push_back(timing(frame, "shadow", 5.0, 0.5, start, start));
        timers.push_back(timing(frame, "lighting", first ? 8.0 : double(frame), 0.25, start + 5.0, start + 1.0));
        timings.addTimings(timers);
    }
    return timings;
}

TEST(FrameTimings, WarmUpFramesAreKeptButNotSummarised) {
    const FrameTimings timings = fourFramesAfterAWarmUp();
    ASSERT_EQ(timings.frames().size(), 5u);
    EXPECT_TRUE(timings.frames()[0].warmUp);
    EXPECT_FALSE(timings.frames()[1].warmUp);
    EXPECT_EQ(timings.frames()[0].passes.size(), 2u);
    const std::vector<PassSummary> summary = timings.summary();
    ASSERT_EQ(summary.size(), 2u);
    EXPECT_EQ(summary[0].name, "shadow");
    EXPECT_FALSE(summary[0].executed) << "it ran in the warm-up only";
    EXPECT_EQ(summary[0].culledBecause, "predicate: shadow map cached");
    EXPECT_EQ(summary[1].samples, 4u);
    EXPECT_DOUBLE_EQ(summary[1].gpuMs, 2.5);       // median of 1, 2, 3, 4: the 8 ms warm-up is out
    EXPECT_DOUBLE_EQ(summary[1].gpuP5Ms, 1.15);    // as numpy.percentile([1, 2, 3, 4], 5)
    EXPECT_DOUBLE_EQ(summary[1].gpuP95Ms, 3.85);
    EXPECT_DOUBLE_EQ(timings.frameGpuMs(), 2.5);
    const nlohmann::json json = nlohmann::json::parse(timings.toJson(RunInfo{}));
    EXPECT_EQ(json["warm_up_frames"], 1);
    ASSERT_EQ(json["per_frame"].size(), 5u);
    EXPECT_EQ(json["per_frame"][0]["warm_up"], true);
    EXPECT_EQ(json["per_frame"][0]["gpu_ms"], 13.0);
    EXPECT_EQ(json["per_frame"][2]["culled"][0]["because"], "predicate: shadow map cached");
    EXPECT_DOUBLE_EQ(json["passes"][1]["gpu_spread"].get<double>(), (3.85 - 1.15) / 2.5);
    const std::string csv = timings.toCsv();
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "frame,warm_up,pass,gpu_ms,cpu_ms,gpu_begin_ms,cpu_begin_ms");
    EXPECT_NE(csv.find("\n0,1,lighting,8,0.25,5,1\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n4,0,lighting,4,0.25,45,41\n"), std::string::npos) << csv;
}

// The viewer resets its timings after every frame, and a frame's timers
// arrive frames later: they must still count, or its profiler shows zeros
// (it did, for a while, when timers without their frame's report were dropped).
TEST(FrameTimings, TimersThatArriveAfterAResetStillCount) {
    FrameTimings timings;
    timings.addPassReports(7, {{"lighting", true, graph::CullReason::None, ""}});
    timings.addTimings({timing(5, "lighting", 2.5, 0.5, 50.0, 50.0)});  // frame 5's, reported before the reset
    const std::vector<PassSummary> summary = timings.summary();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_EQ(summary[0].samples, 1u);
    EXPECT_DOUBLE_EQ(summary[0].gpuMs, 2.5);
}

TEST(TraceEvents, SlicesAreTheSamplesAndNestOnTheirThread) {
    FrameTimings timings = fourFramesAfterAWarmUp();
    // A GPU stamp inside the previous pass (llvmpipe stamps when it bins): frame 5's
    // second pass is stamped 1 ms after the first began, while the first took 3 ms.
    timings.addPassReports(5, {{"a", true, graph::CullReason::None, ""}, {"b", true, graph::CullReason::None, ""}});
    timings.addTimings({timing(5, "a", 3.0, 0.1, 60.0, 60.0), timing(5, "b", 2.0, 0.1, 61.0, 60.5)});
    const nlohmann::json trace = nlohmann::json::parse(traceEventsJson(timings, RunInfo{}));
    ASSERT_TRUE(trace["traceEvents"].is_array());
    EXPECT_EQ(trace["displayTimeUnit"], "ms");
    int gpuPasses = 0, cpuPasses = 0, culled = 0;
    for (const nlohmann::json& event : trace["traceEvents"]) {
        if (event["ph"] == "i") {
            ++culled;
            EXPECT_EQ(event["args"]["because"], "predicate: shadow map cached");
        }
        if (event["ph"] != "X" || event["cat"] == "frame") continue;
        (event["tid"] == 2 ? gpuPasses : cpuPasses)++;
        if (event["tid"] == 2 && event["name"] == "b") {
            EXPECT_DOUBLE_EQ(event["ts"].get<double>(), 63000.0) << "moved to where a ended";
            EXPECT_DOUBLE_EQ(event["dur"].get<double>(), 2000.0) << "the measured time";
            EXPECT_DOUBLE_EQ(event["args"]["stamped_ts"].get<double>(), 61000.0);
        }
        if (event["tid"] == 2 && event["name"] == "lighting" && event["args"]["frame"] == 3) {
            EXPECT_DOUBLE_EQ(event["ts"].get<double>(), 35000.0);
            EXPECT_DOUBLE_EQ(event["dur"].get<double>(), 3000.0);
            EXPECT_EQ(event["cat"], "pass");
        }
        if (event["args"]["frame"] == 0) EXPECT_EQ(event["cat"], "pass,warm_up");
    }
    EXPECT_EQ(gpuPasses, 8);  // 2 + 4 x 1 + 2
    EXPECT_EQ(cpuPasses, 8);
    EXPECT_EQ(culled, 4);     // shadow in frames 1-4
}

}  // namespace
}  // namespace dermis
