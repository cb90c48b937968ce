// What environment light adds to a frame (docs/environment.md): the default
// head at 640x360 in both modes without an environment, and with the built-in
// studio under each occlusion (none, ssao, transfer; prefiltered specular and
// the skybox on; the diffuse light from the irradiance map), and with the
// transfer under nine SH coefficients (diffuse "sh") beside it. The renderers take turns within each iteration, so that a
// slow spell of the shared machine hits them all alike; each frame is the sum
// of its passes' GPU ms (llvmpipe: CPU time). The transfer is computed (or
// read from the disk cache) during the warm-up, not timed.
#include "BenchContext.h"
#include "EnvironmentBenchmarks.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;
const char* const kVariants[] = {"off", "none", "ssao", "transfer", "transfer-sh"};

struct EnvironmentCase {
    std::string key;  // "environment/<mode>/<variant>"
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Renderer> renderer;
    std::vector<double> frameMs;
};

void environmentCost(benchmark::State& state) {
    context();
    std::vector<EnvironmentCase> cases;
    for (const auto& mode : kSssModes) {
        for (const char* variant : kVariants) {
            EnvironmentCase c;
            c.key = "environment/" + std::string(mode.name) + "/" + variant;
            c.scene = std::make_unique<Scene>(contentScene("default.json"));
            c.scene->settings.mode = mode.value;
            if (std::string(variant) != "off") {
                c.scene->environment.source = "studio";
                const bool sh = std::string(variant) == "transfer-sh";
                c.scene->environment.occlusion = *kEnvironmentOcclusions.parse(sh ? "transfer" : variant);
                c.scene->environment.diffuse = sh ? EnvironmentDiffuse::Sh : EnvironmentDiffuse::Map;
            }
            auto renderer = Renderer::create(*c.scene);
            if (!renderer.ok()) {
                state.SkipWithError(renderer.error().message().c_str());
                return;
            }
            c.renderer = std::move(*renderer);
            (void)renderAndTime(*c.renderer, kWidth, kHeight, "");  // warm-up: maps, transfer, pools
            cases.push_back(std::move(c));
        }
    }
    for (auto _ : state) {
        double total = 0.0;
        for (EnvironmentCase& c : cases) {
            const double ms = renderAndTime(*c.renderer, kWidth, kHeight, "");
            c.frameMs.push_back(ms);
            total += ms;
        }
        state.SetIterationTime(total * 1e-3);
    }
    for (EnvironmentCase& c : cases) recorded()[c.key] = median(c.frameMs);
}

}  // namespace

void printEnvironmentSummary() {
    const auto& r = recorded();
    if (r.count("environment/ss/off") == 0) return;
    std::printf("\nEnvironment light, default head, %dx%d, built-in studio (median frame GPU ms; ratio = against no\n"
                "environment, same mode; goal: at most 1.10 in screen space):\n",
                kWidth, kHeight);
    std::printf("| mode | no environment | occlusion none | ratio | ssao | ratio | transfer | ratio | transfer, diffuse sh | ratio |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const auto& mode : kSssModes) {
        const std::string prefix = "environment/" + std::string(mode.name) + "/";
        const double off = r.at(prefix + "off");
        std::printf("| %s | %.1f |", std::string(mode.name).c_str(), off);
        for (const char* variant : {"none", "ssao", "transfer", "transfer-sh"}) {
            const double ms = r.at(prefix + variant);
            std::printf(" %.1f | %.3f |", ms, ms / off);
        }
        std::printf("\n");
    }
}

BENCHMARK(environmentCost)->UseManualTime()->Iterations(9)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
