// The screen-space SSS techniques side by side (docs/screen-space.md,
// docs/results/techniques.md): the default head at 640x360, 1280x720 and 320x180 with the
// shipped d'Eon chain, then every other technique's tuner candidates (scene/SssTechniques.h).
// The renderers take turns within each iteration, so that a slow spell of the
// shared machine hits them all alike; each figure is the median over the
// iterations of the SSS passes' GPU ms (sss init and every technique pass;
// llvmpipe: CPU time) and of the lighting pass, where the pre-integrated
// technique does its work. Each case's loss is the relative RMSE of its diffuse
// AOV over SSS pixels against the finest setting (the d'Eon chain with every
// Gaussian at 33 taps, no Gaussian skipped): what the cheaper technique gives
// up. The error against the CPU reference comes from `dermis bench`
// (docs/bench.md), which sweeps the same settings.
#include "BenchContext.h"
#include "TechniqueBenchmarks.h"

#include "core/ImageMetrics.h"
#include "render/FrameTimings.h"
#include "scene/QualityTable.h"
#include "scene/SssTechniques.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

// 320x180 last: the size of the bench sweep that measures their scatter error (docs/screen-space.md).
const int kSizes[][2] = {{640, 360}, {1280, 720}, {320, 180}};

struct TechniqueCase {
    std::string label;  // "separable samples=17" (describeSssChoice)
    SssSettings sss;
};

// The shipped settings, then every other technique's tuner candidates (scene/SssTechniques.h).
std::vector<TechniqueCase> techniqueCases(const SssSettings& shipped) {
    std::vector<TechniqueCase> cases{{std::string(kSssTechniques.name(shipped.technique)) + " (default)", shipped}};
    for (const SssTechniqueInfo& technique : sssTechniques()) {
        if (technique.technique == shipped.technique) continue;
        for (const SssChoice& choice : technique.candidates) {
            SssSettings s = shipped;
            choice.canonical().applyTo(s);
            cases.push_back({describeSssChoice(choice), s});
        }
    }
    return cases;
}

// SssChoice::finest() with no Gaussian skipped: the reference of the loss, as `dermis tune` has it.
SssSettings finestSettings(SssSettings s) {
    SssChoice::finest().applyTo(s);
    s.minWidthPx = 0.0f;
    return s;
}

std::string sizeName(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

struct Rendered {
    Image diffuse;
    std::vector<uint8_t> sssMask;
};

Result<Rendered> renderDiffuse(Renderer& renderer, int width, int height) {
    Rendered out{renderAov(renderer, width, height, Aov::Diffuse), sssPixelMask(renderer, width, height)};
    if (out.diffuse.texels.empty() || out.sssMask.empty()) return makeError("renderer", "a frame failed");
    return out;
}

struct TimedCase {
    std::string key;  // "technique/<size>/<label>"
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Renderer> renderer;
    std::vector<double> sssMs;
    std::vector<double> lightingMs;  // the lighting pass, where "preintegrated" does its work
};

void sssTechniques(benchmark::State& state) {
    context();
    const int width = kSizes[state.range(0)][0];
    const int height = kSizes[state.range(0)][1];
    const std::string size = sizeName(width, height);
    const Scene& base = contentScene("default.json");

    Scene finestScene = base;
    finestScene.settings.sss = finestSettings(base.settings.sss);
    auto finest = Renderer::create(finestScene);
    if (!finest.ok()) {
        state.SkipWithError(finest.error().message().c_str());
        return;
    }
    auto finestImage = renderDiffuse(**finest, width, height);
    if (!finestImage.ok()) {
        state.SkipWithError(finestImage.error().message().c_str());
        return;
    }

    std::vector<TimedCase> cases;
    for (const TechniqueCase& t : techniqueCases(base.settings.sss)) {
        TimedCase c;
        c.key = "technique/" + size + "/" + t.label;
        c.scene = std::make_unique<Scene>(base);
        c.scene->settings.sss = t.sss;
        auto renderer = Renderer::create(*c.scene);
        if (!renderer.ok()) {
            state.SkipWithError(renderer.error().message().c_str());
            return;
        }
        c.renderer = std::move(*renderer);
        auto image = renderDiffuse(*c.renderer, width, height);
        if (!image.ok()) {
            state.SkipWithError(image.error().message().c_str());
            return;
        }
        auto loss = compareImages(finestImage->diffuse, image->diffuse, finestImage->sssMask);
        recorded()[c.key + "/loss"] = loss.ok() ? loss->relativeRmse : -1.0;
        (void)renderAndTime(*c.renderer, width, height, "sss ");  // warm-up of the final output
        cases.push_back(std::move(c));
    }
    for (auto _ : state) {
        double total = 0.0;
        for (TimedCase& c : cases) {
            const std::vector<double> ms = renderAndTimeAt(*c.renderer, width, height, 0.0f, {"sss ", "lighting"});
            c.sssMs.push_back(ms[0]);
            c.lightingMs.push_back(ms[1]);
            total += ms[0] + ms[1];
        }
        state.SetIterationTime(total * 1e-3);
    }
    for (TimedCase& c : cases) {
        recorded()[c.key] = median(c.sssMs);
        recorded()[c.key + "/lighting"] = median(c.lightingMs);
    }
    state.SetLabel(size);
}

}  // namespace

void printTechniqueSummary() {
    const auto& r = recorded();
    const std::vector<TechniqueCase> cases = techniqueCases(SssSettings{});
    for (const auto& dims : kSizes) {
        const std::string size = sizeName(dims[0], dims[1]);
        const std::string prefix = "technique/" + size + "/";
        const auto base = r.find(prefix + cases[0].label);
        if (base == r.end() || base->second <= 0.0) continue;
        std::printf("\nScreen-space SSS techniques, default head, %s (median GPU ms of the SSS passes and of the\n"
                    "lighting pass, renderers interleaved; ratio of their sum against the shipped d'Eon chain's;\n"
                    "loss = relative RMSE of the diffuse over SSS pixels against the finest d'Eon chain):\n",
                    size.c_str());
        std::printf("| technique | SSS ms | lighting ms | ratio | loss %% |\n| --- | ---: | ---: | ---: | ---: |\n");
        const double baseMs = base->second + r.at(prefix + cases[0].label + "/lighting");
        for (const TechniqueCase& c : cases) {
            const auto ms = r.find(prefix + c.label);
            if (ms == r.end()) continue;
            const double lightingMs = r.at(prefix + c.label + "/lighting");
            std::printf("| %s | %.2f | %.2f | %.3f | %.2f |\n", c.label.c_str(), ms->second, lightingMs,
                        (ms->second + lightingMs) / baseMs, 100.0 * r.at(prefix + c.label + "/loss"));
        }
    }
}

BENCHMARK(sssTechniques)->DenseRange(0, 2)->UseManualTime()->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
