// Screen-space SSS benchmarks (issue: "the SSS blur costs no more than 1.25x a
// pass that only fetches the same taps"; "SSS cost grows with the number of
// SSS pixels, not with the number of characters"). Times are GPU ms from the
// renderer's own per-pass timers; on llvmpipe they are CPU time.
#include "BenchContext.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace dermis::bench {
namespace {

// The edge modes the blur benchmark times (the settings' SssBlur::Variant is one of the first two).
const SssBlur kBlurModes[] = {SssBlur::Bilateral, SssBlur::Control, SssBlur::FetchOnly};
const int kSizes[][2] = {{640, 360}, {1280, 720}};

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Time of one prefix of passes over the benchmark's iterations.
void timeFrames(benchmark::State& state, Renderer& renderer, int width, int height, const std::string& prefix,
                const std::string& key) {
    renderAndTime(renderer, width, height, prefix);  // warm-up: shadow maps, pools, shader caches
    std::vector<double> samples;
    for (auto _ : state) {
        const double ms = renderAndTime(renderer, width, height, prefix);
        samples.push_back(ms);
        state.SetIterationTime(ms * 1e-3);
    }
    recorded()[key] = medianOf(samples);
    state.counters["median_ms"] = recorded()[key];
}

void sssBlur(benchmark::State& state) {
    context();
    const SssBlur blur = kBlurModes[state.range(0)];
    const std::string mode(kSssBlurs.name(blur));
    const int width = kSizes[state.range(1)][0];
    const int height = kSizes[state.range(1)][1];
    Scene scene = contentScene("default.json");
    scene.settings.sss.blur = blur;
    auto renderer = Renderer::create(scene);
    if (!renderer.ok()) {
        state.SkipWithError(renderer.error().message().c_str());
        return;
    }
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    timeFrames(state, **renderer, width, height, "sss skin", std::string("blur/") + mode + "/" + size);
    state.SetLabel(std::string(mode) + " " + size);
}

// Scenes with the same head: one at the default framing (P SSS pixels); four
// in a 2x2 grid seen from twice as far (about P pixels in all, four
// characters); one with half the field of view (about 4P pixels, one
// character).
Scene layout(int which) {
    Scene scene = contentScene("default.json");
    if (which == 1) {
        const Character head = scene.characters[0];
        scene.characters.clear();
        for (int i = 0; i < 4; ++i) {
            Character c = head;
            c.name = "head " + std::to_string(i);
            c.transform.translationM += glm::vec3((i % 2 == 0 ? -0.13f : 0.13f), (i < 2 ? 0.17f : -0.17f), 0.0f);
            scene.characters.push_back(c);
        }
        scene.camera.positionM = scene.camera.targetM + 2.0f * (scene.camera.positionM - scene.camera.targetM);
    } else if (which == 2) {
        scene.camera.verticalFovDeg *= 0.5f;
    }
    return scene;
}

const char* const kLayoutNames[] = {"1 head", "4 heads, same pixels", "1 head, 4x pixels"};

size_t sssPixels(Renderer& renderer, int width, int height) {
    size_t n = 0;
    for (uint8_t inside : sssPixelMask(renderer, width, height)) n += inside;
    return n;
}

void sssPixelsVersusCharacters(benchmark::State& state) {
    context();
    const int which = static_cast<int>(state.range(0));
    const Scene scene = layout(which);
    auto renderer = Renderer::create(scene);
    if (!renderer.ok()) {
        state.SkipWithError(renderer.error().message().c_str());
        return;
    }
    const int width = 640;
    const int height = 360;
    const size_t pixels = sssPixels(**renderer, width, height);
    const std::string key = std::string("layout/") + kLayoutNames[which];
    timeFrames(state, **renderer, width, height, "sss", key);
    recorded()[key + "/pixels"] = double(pixels);
    state.counters["sss_pixels"] = double(pixels);
    state.SetLabel(kLayoutNames[which]);
}

}  // namespace

BENCHMARK(sssBlur)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->UseManualTime()
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(sssPixelsVersusCharacters)->DenseRange(0, 2)->UseManualTime()->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
