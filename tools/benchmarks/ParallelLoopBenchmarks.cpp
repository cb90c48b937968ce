// The in-house parallel loop (raytrace/ParallelFor.h: std::threads started per
// call, items taken from a shared counter) against oneTBB's parallel_for (a
// pool kept across calls, work stealing) on the CPU reference's own work: the
// environment's visibility rays of RayWorkload, on every thread. They are traced
// with the in-house BVH, not Embree: an Embree device made with "threads=1", as
// raytrace/EmbreeBvh.cpp makes its own, limits oneTBB to one thread in the whole
// process (Embree sets a tbb::global_control), which would time oneTBB on one
// thread. Two shapes:
//   rows   one loop over 400 items of 1,000 rays: the reference's pixel rows and
//          the SH transfer's vertex blocks (a few long loops per image)
//   calls  400 loops of 8 items of 125 rays each: many short loops, where
//          starting threads per call would show
// Each iteration runs all four, the two loops alternating first, so that a slow
// spell of the shared machine hits both; both must mark the same rays occluded.
// docs/results/reference.md "Speed" quotes the table printed after the run.
#include "ParallelLoopBenchmarks.h"
#include "RayBenchmarks.h"

#include "raytrace/Bvh.h"
#include "raytrace/ParallelFor.h"

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr size_t kRowItems = 400;
constexpr size_t kCalls = 400;
constexpr size_t kItemsPerCall = 8;

struct LoopFigures {
    int threads = 0;
    double rowsMs[2] = {0, 0};   // in-house, oneTBB
    double callsMs[2] = {0, 0};
    size_t disagreements = 0;
    bool ran = false;
};
LoopFigures sLoops;

using Loop = std::function<void(size_t count, const std::function<void(size_t)>& work)>;

double runShape(const Loop& loop, const raytrace::Bvh& tracer, const std::vector<raytrace::Ray>& rays,
                size_t calls, size_t itemsPerCall, std::vector<uint8_t>& occluded) {
    occluded.assign(rays.size(), 0);
    const size_t raysPerCall = rays.size() / calls;
    const size_t raysPerItem = raysPerCall / itemsPerCall;
    const auto start = std::chrono::steady_clock::now();
    for (size_t call = 0; call < calls; ++call) {
        loop(itemsPerCall, [&](size_t item) {
            const size_t first = call * raysPerCall + item * raysPerItem;
            for (size_t r = first; r < first + raysPerItem; ++r) {
                occluded[r] = tracer.anyHit(rays[r], 0.0f, std::numeric_limits<float>::infinity());
            }
        });
    }
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void parallelLoops(benchmark::State& state) {
    RayWorkload work;
    if (!loadRayWorkload("default.json", &work)) {
        state.SkipWithError("cannot load default.json");
        return;
    }
    const raytrace::Bvh tracer = raytrace::Bvh::build(work.cornersM);
    const int threads = raytrace::resolveThreadCount(0);
    tbb::task_arena arena(threads);
    const Loop inHouse = [&](size_t count, const std::function<void(size_t)>& body) {
        raytrace::parallelFor(count, threads, body);
    };
    const Loop oneTbb = [&](size_t count, const std::function<void(size_t)>& body) {
        arena.execute([&] {
            // Grain 1 and the simple partitioner: one item per task, as the shared counter hands them out.
            tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1),
                              [&](const tbb::blocked_range<size_t>& range) {
                                  for (size_t i = range.begin(); i != range.end(); ++i) body(i);
                              },
                              tbb::simple_partitioner());
        });
    };
    const Loop loops[2] = {inHouse, oneTbb};
    std::vector<double> rows[2], calls[2];
    std::vector<uint8_t> occluded[2];
    size_t round = 0;
    sLoops.disagreements = 0;
    for (auto _ : state) {
        for (int turn = 0; turn < 2; ++turn) {
            const int k = (turn + int(round)) % 2;
            rows[k].push_back(runShape(loops[k], tracer, work.occlusion, 1, kRowItems, occluded[k]));
            calls[k].push_back(runShape(loops[k], tracer, work.occlusion, kCalls, kItemsPerCall, occluded[k]));
        }
        for (size_t r = 0; r < occluded[0].size(); ++r) sLoops.disagreements += occluded[0][r] != occluded[1][r];
        ++round;
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    sLoops.threads = threads;
    for (int k = 0; k < 2; ++k) {
        sLoops.rowsMs[k] = median(rows[k]);
        sLoops.callsMs[k] = median(calls[k]);
    }
    sLoops.ran = true;
    state.counters["tbb_speedup_rows"] = sLoops.rowsMs[0] / std::max(sLoops.rowsMs[1], 1e-9);
    state.counters["tbb_speedup_calls"] = sLoops.callsMs[0] / std::max(sLoops.callsMs[1], 1e-9);
}

BENCHMARK(parallelLoops)->Iterations(7)->Unit(benchmark::kMillisecond);

}  // namespace

void printParallelLoopSummary() {
    if (!sLoops.ran) return;
    std::printf("\nParallel loops, %d threads, 400,000 occlusion rays on the default head (median ms; in-house / oneTBB):\n",
                sLoops.threads);
    std::printf("  rows  (1 loop of %zu items):    %8.1f / %8.1f = %5.2fx\n", kRowItems, sLoops.rowsMs[0],
                sLoops.rowsMs[1], sLoops.rowsMs[0] / std::max(sLoops.rowsMs[1], 1e-9));
    std::printf("  calls (%zu loops of %zu items): %8.1f / %8.1f = %5.2fx\n", kCalls, kItemsPerCall, sLoops.callsMs[0],
                sLoops.callsMs[1], sLoops.callsMs[0] / std::max(sLoops.callsMs[1], 1e-9));
    std::printf("  rays marked differently: %zu (must be 0)\n", sLoops.disagreements);
}

}  // namespace dermis::bench
