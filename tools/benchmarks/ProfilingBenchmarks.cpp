// What recording every frame's timings costs, against the frame (the goal:
// under 1%). Two parts, measured in this one run:
//  - the GL_TIMESTAMP pair that times and places each pass, against one
//    GL_TIME_ELAPSED query per pass (what it replaced, which has no place in
//    time): two renderers of the default head at 640x360 taking turns frame
//    by frame; the wall time of each frame (glFinish after it), so that
//    whatever the queries cost anywhere is counted;
//  - on llvmpipe, the glFlush at each pass's start that keeps passes sharing
//    a framebuffer apart (gl/GpuProfiler.h): a third renderer, stamped
//    without it, takes its turn with the two;
//  - keeping the frame's samples (FrameTimings::addPassReports and
//    addTimings): the CPU time of folding in one frame's reports and timers,
//    timed over many frames of a real run's records.
#include "ProfilingBenchmarks.h"
#include "BenchContext.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

namespace dermis::bench {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;

double wallMsOfFrame(Renderer& renderer) {
    const auto start = std::chrono::steady_clock::now();
    (void)renderer.renderFrame({kWidth, kHeight, Aov::Final});
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void timestampQueries(benchmark::State& state) {
    context();
    // 0: elapsed-time queries, 1: timestamp pairs, 2: timestamp pairs without the batch split.
    std::unique_ptr<Renderer> renderers[3];
    for (int stamped = 0; stamped < 3; ++stamped) {
        auto renderer = Renderer::create(contentScene("default.json"));
        if (!renderer.ok()) {
            state.SkipWithError(renderer.error().message().c_str());
            return;
        }
        renderers[stamped] = std::move(*renderer);
        renderers[stamped]->setGpuTimestamps(stamped >= 1);
        if (stamped == 2) renderers[stamped]->setGpuBatchSplit(false);
        for (int i = 0; i < 3; ++i) (void)wallMsOfFrame(*renderers[stamped]);  // programs, shadow maps
    }
    std::vector<double> ms[3];
    for (auto _ : state) {
        double total = 0.0;
        for (int stamped = 0; stamped < 3; ++stamped) {
            ms[stamped].push_back(wallMsOfFrame(*renderers[stamped]));
            total += ms[stamped].back();
        }
        state.SetIterationTime(total * 1e-3);
    }
    recorded()["profiling/frame with elapsed-time queries"] = median(ms[0]);
    recorded()["profiling/frame with timestamp pairs"] = median(ms[1]);
    recorded()["profiling/frame with timestamp pairs, batches not split"] = median(ms[2]);

    // Folding one frame in, with the run's own records replayed into a fresh FrameTimings.
    renderers[1]->finishTimings();
    const std::vector<FrameRecord>& frames = renderers[1]->timings().frames();
    std::vector<graph::PassReport> reports;
    for (const gl::PassTiming& pass : frames.back().passes) reports.push_back({pass.pass, true, graph::CullReason::None, ""});
    for (const auto& [name, because] : frames.back().culled) reports.push_back({name, false, graph::CullReason::Predicate, because});
    constexpr int kFolded = 2000;
    FrameTimings folded;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < kFolded; ++frame) {
        folded.addPassReports(uint64_t(frame), reports);
        std::vector<gl::PassTiming> timers = frames.back().passes;
        for (gl::PassTiming& timer : timers) timer.frame = uint64_t(frame);
        folded.addTimings(timers);
    }
    const double foldMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / kFolded;
    recorded()["profiling/folding one frame in"] = foldMs;
    recorded()["profiling/passes per frame"] = double(frames.back().passes.size());
}

}  // namespace

void printProfilingSummary() {
    const auto& r = recorded();
    if (r.count("profiling/frame with timestamp pairs") == 0) return;
    const double off = r.at("profiling/frame with elapsed-time queries");
    const double on = r.at("profiling/frame with timestamp pairs");
    const double fold = r.at("profiling/folding one frame in");
    std::printf("\nRecording every frame's timings, default head at %dx%d (median wall ms per frame, glFinish after each):\n"
                "| | ms | share of the frame |\n| --- | ---: | ---: |\n",
                kWidth, kHeight);
    std::printf("| frame timed by a GL_TIME_ELAPSED query per pass | %.3f | |\n", off);
    std::printf("| frame timed and placed by a GL_TIMESTAMP pair per pass (%.0f passes) | %.3f | %+.2f%% |\n",
                r.at("profiling/passes per frame"), on,
                100.0 * (on - off) / off);
    const double unsplit = r.at("profiling/frame with timestamp pairs, batches not split");
    std::printf("| the same without a glFlush at each pass's start (llvmpipe's batch split) | %.3f | %+.2f%% |\n", unsplit,
                100.0 * (unsplit - off) / off);
    // (the flushes cost the difference of this row and the one above)
    std::printf("| keeping one frame's samples (CPU) | %.4f | %.4f%% |\n", fold, 100.0 * fold / off);
    // The stamps against elapsed-time queries, plus the flushes against none, plus the folding.
    const double total = (on - off) / off + (on - unsplit) / unsplit + fold / off;
    std::printf("recording every frame: %+.2f%% of the frame%s\n", 100.0 * total,
                total < 0.01 ? " (under 1%)" : " (OVER 1%)");
}

BENCHMARK(timestampQueries)->UseManualTime()->Iterations(30)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
