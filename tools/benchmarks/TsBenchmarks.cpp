// Texture-space (ts) against screen-space (ss) SSS cost:
//  - 1, 2, 4 and 8 heads at 1280x720, framed so that together they cover
//    about as many pixels as one head does (the camera backs off sqrt(n)
//    times): screen-space cost should stay about flat, texture-space cost
//    grows with every visible character (its own textures and passes);
//  - 8 heads of which 7 are off screen against 1 head: the 7 must cost
//    (almost) nothing in either mode.
// Times are GPU ms from the renderer's per-pass timers, medians over the
// iterations after a warm-up frame, the scenes of one table rendered in turn
// within each iteration; on llvmpipe they are CPU time.
#include "BenchContext.h"
#include "TsBenchmarks.h"

#include "plan/ScreenFootprint.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
const int kCharacterCounts[] = {1, 2, 4, 8};
constexpr float kColumnSpacingM = 0.25f;
constexpr float kRowSpacingM = 0.38f;

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// n default heads in a grid (1x1, 2x1, 4x1, 4x2) seen along the default
// camera's direction from sqrt(n) times as far, so that together they cover
// about as many pixels as one head does.
Scene grid(int n) {
    Scene scene = contentScene("default.json");
    if (n == 1) return scene;
    const Character head = scene.characters[0];
    const int columns = std::min(n, 4);
    const int rows = (n + columns - 1) / columns;
    scene.characters.clear();
    for (int i = 0; i < n; ++i) {
        Character c = head;
        c.name = "head " + std::to_string(i);
        const float x = (float(i % columns) - 0.5f * float(columns - 1)) * kColumnSpacingM;
        const float y = (0.5f * float(rows - 1) - float(i / columns)) * kRowSpacingM;
        c.transform.translationM += glm::vec3(x, y, 0.0f);
        scene.characters.push_back(c);
    }
    const glm::vec3 offset = scene.camera.positionM - scene.camera.targetM;
    scene.camera.positionM = scene.camera.targetM + offset * std::sqrt(float(n));
    return scene;
}

// One head at the default framing and seven more behind the camera.
Scene oneOnScreenSevenOff() {
    Scene scene = contentScene("default.json");
    const Character head = scene.characters[0];
    const glm::vec3 behind = scene.camera.positionM + 1.5f * (scene.camera.positionM - scene.camera.targetM);
    for (int i = 1; i < 8; ++i) {
        Character c = head;
        c.name = "away " + std::to_string(i);
        c.transform.translationM = behind + glm::vec3(float(i - 4) * kColumnSpacingM, 0.0f, 0.0f);
        scene.characters.push_back(c);
    }
    return scene;
}

struct FrameCost {
    double frameMs = 0.0;
    double sssMs = 0.0;  // the mode's own passes: "sss ..." and "transmittance", or "ts ..."
};

FrameCost renderOnce(Renderer& renderer) {
    renderer.resetTimings();
    if (const Status status = renderer.renderFrame({kWidth, kHeight, Aov::Final}); !status.ok()) {
        std::fprintf(stderr, "error: %s\n", status.error().message().c_str());
        std::exit(1);
    }
    renderer.finishTimings();
    FrameCost cost;
    for (const PassSummary& pass : renderer.timings().summary()) {
        if (!pass.executed) continue;
        cost.frameMs += pass.gpuMs;
        if (pass.name.rfind("sss", 0) == 0 || pass.name == "transmittance" || pass.name.rfind("ts ", 0) == 0)
            cost.sssMs += pass.gpuMs;
    }
    return cost;
}

size_t sssPixels(Renderer& renderer) {
    (void)renderer.renderFrame({kWidth, kHeight, Aov::Object});
    auto image = renderer.readOutput();
    size_t n = 0;
    if (image.ok()) {
        for (const glm::vec4& t : image->texels) n += t.r > 0.5f ? 1 : 0;
    }
    return n;
}

// Renders every scene once per iteration, in turn, so that a slow spell of a
// shared machine hits them all alike; records each one's medians.
void measureRoundRobin(benchmark::State& state, std::vector<Scene> scenes, SssMode mode,
                       const std::vector<std::string>& keys) {
    context();
    std::vector<std::unique_ptr<Renderer>> renderers;
    for (Scene& scene : scenes) scene.settings.mode = mode;
    for (const Scene& scene : scenes) {
        auto renderer = Renderer::create(scene);
        if (!renderer.ok()) {
            state.SkipWithError(renderer.error().message().c_str());
            return;
        }
        renderOnce(**renderer);  // warm-up: shadow maps, pools, shader caches, UV-layout analysis
        renderers.push_back(std::move(*renderer));
    }
    std::vector<std::vector<double>> frame(renderers.size());
    std::vector<std::vector<double>> sss(renderers.size());
    for (auto _ : state) {
        double total = 0.0;
        for (size_t i = 0; i < renderers.size(); ++i) {
            const FrameCost cost = renderOnce(*renderers[i]);
            frame[i].push_back(cost.frameMs);
            sss[i].push_back(cost.sssMs);
            total += cost.frameMs;
        }
        state.SetIterationTime(total * 1e-3);
    }
    for (size_t i = 0; i < renderers.size(); ++i) {
        recorded()[keys[i] + "/frame"] = medianOf(frame[i]);
        recorded()[keys[i] + "/sss"] = medianOf(sss[i]);
        recorded()[keys[i] + "/pixels"] = double(sssPixels(*renderers[i]));
    }
    state.SetLabel(std::string(kSssModes.name(mode)));
}

// The mode a benchmark's first argument selects: DenseRange over the table.
SssMode modeOf(const benchmark::State& state) { return kSssModes.begin()[state.range(0)].value; }
std::string modeName(const benchmark::State& state) { return std::string(kSssModes.name(modeOf(state))); }

// Scenes sharing the camera of the 8-head grid: n of its heads, each as large on screen as in the grid.
Scene sameSize(int n) {
    Scene scene = grid(8);
    scene.characters.resize(static_cast<size_t>(n));
    return scene;
}

void characters(benchmark::State& state) {
    const std::string mode = modeName(state);
    std::vector<Scene> scenes;
    std::vector<std::string> keys;
    for (int n : kCharacterCounts) {
        scenes.push_back(grid(n));
        keys.push_back("ts-bench/" + mode + "/" + std::to_string(n));
    }
    measureRoundRobin(state, std::move(scenes), modeOf(state), keys);
}

void charactersSameSize(benchmark::State& state) {
    const std::string mode = modeName(state);
    std::vector<Scene> scenes;
    std::vector<std::string> keys;
    for (int n : kCharacterCounts) {
        scenes.push_back(sameSize(n));
        keys.push_back("ts-bench/" + mode + "/same size " + std::to_string(n));
    }
    measureRoundRobin(state, std::move(scenes), modeOf(state), keys);
}

void offScreen(benchmark::State& state) {
    const std::string mode = modeName(state);
    measureRoundRobin(state, {contentScene("default.json"), oneOnScreenSevenOff()}, modeOf(state),
                      {"ts-bench/" + mode + "/1 alone", "ts-bench/" + mode + "/1+7 off"});
}

}  // namespace

void printTextureSpaceSummary() {
    const auto& r = recorded();
    auto get = [&](const std::string& key) { return r.count(key) ? r.at(key) : NAN; };
    const std::vector<std::string> modes = kSssModes.names();
    const std::string first = "ts-bench/" + modes.front() + "/";
    auto table = [&](const char* title, const std::string& prefix) {
        bool any = false;
        for (const std::string& mode : modes) any = any || r.count("ts-bench/" + mode + "/" + prefix + "1/frame") > 0;
        if (!any) return;
        std::printf("\n%s, %dx%d (median GPU ms; SSS = the mode's own passes):\n", title, kWidth, kHeight);
        std::string header = "| characters | SSS pixels |";
        std::string rule = "| --- | --- |";
        for (const std::string& mode : modes) {
            header += " " + mode + " SSS ms | " + mode + " frame ms |";
            rule += " --- | --- |";
        }
        std::printf("%s\n%s\n", header.c_str(), rule.c_str());
        for (int n : kCharacterCounts) {
            const std::string k = prefix + std::to_string(n);
            std::printf("| %d | %.0f |", n, get(first + k + "/pixels"));
            for (const std::string& mode : modes) {
                std::printf(" %.2f | %.2f |", get("ts-bench/" + mode + "/" + k + "/sss"),
                            get("ts-bench/" + mode + "/" + k + "/frame"));
            }
            std::printf("\n");
        }
    };
    table("Texture space against screen space, characters sharing the pixels of one", "");
    table("Texture space against screen space, every character as large as in the 8-character view", "same size ");
    for (const std::string& mode : modes) {
        const double one = get("ts-bench/" + mode + "/1 alone/frame");
        const double offs = get("ts-bench/" + mode + "/1+7 off/frame");
        if (std::isfinite(one) && std::isfinite(offs) && one > 0.0) {
            const double ratio = offs / one;
            std::printf("%s: 8 characters (7 off screen) / 1 character, whole frame: %.3f ms / %.3f ms = %.3fx%s\n", mode.c_str(),
                        offs, one, ratio, ratio <= 1.1 ? "  (within 10%)" : "  (OVER 10%)");
        }
    }
}

BENCHMARK(characters)->DenseRange(0, int(kSssModes.size()) - 1)->UseManualTime()->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(charactersSameSize)->DenseRange(0, int(kSssModes.size()) - 1)->UseManualTime()->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(offScreen)->DenseRange(0, int(kSssModes.size()) - 1)->UseManualTime()->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
