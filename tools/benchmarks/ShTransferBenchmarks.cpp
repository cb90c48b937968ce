// The SH transfer precompute (env/ShTransfer.h) on the procedural head and the
// head scan (skipped when its content is absent): seconds for every vertex's
// occlusion-weighted transfer at the default ray count, on every thread.
// docs/environment.md "Speed" quotes it.
#include "BenchContext.h"

#include "env/ShTransfer.h"
#include "import/ModelLoader.h"
#include "raytrace/ParallelFor.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

namespace dermis::bench {
namespace {

void shTransfer(benchmark::State& state, const std::string& sceneName) {
    const Scene& scene = contentScene(sceneName);
    auto model = scene.characters.empty() ? Result<Model>(makeError(sceneName, "no character"))
                                          : loadCharacterModel(scene.characters[0]);
    if (!model.ok()) {
        state.SkipWithError(("cannot load " + sceneName + " (the scan's content absent?)").c_str());
        return;
    }
    ShTransferOptions options;
    options.progressLabel.clear();
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        Result<ShTransfer> transfer = computeShTransfer(model->mesh, options);
        state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (!transfer.ok()) {
            state.SkipWithError(transfer.error().message().c_str());
            return;
        }
    }
    const double rays = double(model->mesh.vertices.size()) * options.raysPerVertex;
    state.counters["vertices"] = double(model->mesh.vertices.size());
    state.counters["threads"] = double(raytrace::resolveThreadCount(options.threads));
    state.counters["Mrays_per_s"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK_CAPTURE(shTransfer, procedural_head, std::string("default.json"))
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shTransfer, scan, std::string("lee_perry_smith.json"))
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace dermis::bench
