// Crowds cost only what is visible (docs/crowds.md): one head on
// screen alone, with 7 heads behind the camera, and with 31 behind the camera
// and beside the view (content/scenes/crowd.json's first 1, 8 and 32
// characters), in both modes at 640x360. The six renderers take turns within
// each iteration, so that a slow spell of the shared machine hits them all
// alike; each one's frame is the sum of its passes' GPU ms (llvmpipe: CPU
// time) and, beside it, the wall clock of the whole frame with its timers
// read back. Each crowd's image is compared with the head alone's.
#include "BenchContext.h"
#include "CrowdBenchmarks.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;
const size_t kCharacterCounts[] = {1, 8, 32};
const char* const kLayoutNames[] = {"1 alone", "1 + 7 behind the camera", "1 + 31 behind and beside"};

struct CrowdCase {
    std::string key;  // "crowd/<mode>/<characters>"
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Renderer> renderer;
    std::vector<double> frameMs;
    std::vector<double> wallMs;
};

Image finalImage(Renderer& renderer) {
    (void)renderer.renderFrame({kWidth, kHeight, Aov::Final});
    auto image = renderer.readOutput();
    return image.ok() ? std::move(*image) : Image{};
}

// The largest difference of a colour channel, in 8-bit steps.
double maxStepDifference(const Image& a, const Image& b) {
    if (a.texels.size() != b.texels.size() || a.texels.empty()) return NAN;
    float largest = 0.0f;
    for (size_t i = 0; i < a.texels.size(); ++i) {
        const glm::vec3 d = glm::abs(glm::vec3(a.texels[i]) - glm::vec3(b.texels[i]));
        largest = std::max({largest, d.r, d.g, d.b});
    }
    return double(largest) * 255.0;
}

void crowds(benchmark::State& state) {
    context();
    std::vector<CrowdCase> cases;
    for (const auto& mode : kSssModes) {
        for (size_t count : kCharacterCounts) {
            CrowdCase c;
            c.key = "crowd/" + std::string(mode.name) + "/" + std::to_string(count);
            c.scene = std::make_unique<Scene>(contentScene("crowd.json"));
            c.scene->characters.resize(count);
            c.scene->settings.mode = mode.value;
            auto renderer = Renderer::create(*c.scene);
            if (!renderer.ok()) {
                state.SkipWithError(renderer.error().message().c_str());
                return;
            }
            c.renderer = std::move(*renderer);
            cases.push_back(std::move(c));
        }
    }
    // Warm-up (shadow maps, pools, UV-layout analysis), then each crowd's image against its mode's head alone.
    std::vector<Image> images;
    for (CrowdCase& c : cases) images.push_back(finalImage(*c.renderer));
    for (size_t i = 0; i < cases.size(); ++i) {
        const size_t alone = i - i % std::size(kCharacterCounts);
        recorded()[cases[i].key + "/max step difference"] = maxStepDifference(images[alone], images[i]);
    }
    for (auto _ : state) {
        double total = 0.0;
        for (CrowdCase& c : cases) {
            const auto start = std::chrono::steady_clock::now();
            const double ms = renderAndTime(*c.renderer, kWidth, kHeight, "");
            c.wallMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            c.frameMs.push_back(ms);
            total += ms;
        }
        state.SetIterationTime(total * 1e-3);
    }
    for (CrowdCase& c : cases) {
        recorded()[c.key + "/frame"] = median(c.frameMs);
        recorded()[c.key + "/wall"] = median(c.wallMs);
    }
}

}  // namespace

void printCrowdSummary() {
    const auto& r = recorded();
    auto get = [&](const std::string& key) { return r.count(key) ? r.at(key) : NAN; };
    if (r.count("crowd/ss/1/frame") == 0) return;
    std::printf("\nCrowds, one head on screen, %dx%d (median ms; frame = sum of the passes' GPU ms, wall = the whole\n"
                "frame with its timers read back; ratio = against the head alone, same mode; diff = largest\n"
                "colour difference from the head alone's image, in 8-bit steps):\n",
                kWidth, kHeight);
    std::string header = "| characters |";
    std::string rule = "| --- |";
    for (const auto& mode : kSssModes) {
        const std::string m(mode.name);
        header += " " + m + " frame | " + m + " ratio | " + m + " wall | " + m + " ratio | " + m + " diff |";
        rule += " ---: | ---: | ---: | ---: | ---: |";
    }
    std::printf("%s\n%s\n", header.c_str(), rule.c_str());
    for (size_t i = 0; i < std::size(kCharacterCounts); ++i) {
        std::printf("| %s |", kLayoutNames[i]);
        for (const auto& mode : kSssModes) {
            const std::string prefix = "crowd/" + std::string(mode.name) + "/";
            const std::string k = prefix + std::to_string(kCharacterCounts[i]);
            const double frame = get(k + "/frame");
            const double wall = get(k + "/wall");
            std::printf(" %.1f | %.3f | %.1f | %.3f | %.0f |", frame, frame / get(prefix + "1/frame"), wall,
                        wall / get(prefix + "1/wall"), get(k + "/max step difference"));
        }
        std::printf("\n");
    }
    for (const auto& mode : kSssModes) {
        const std::string prefix = "crowd/" + std::string(mode.name) + "/";
        const double ratio = get(prefix + "32/frame") / get(prefix + "1/frame");
        const double diff = get(prefix + "32/max step difference");
        std::printf("%s: 1 + 31 off screen / 1 alone = %.3fx%s, image %s\n", std::string(mode.name).c_str(), ratio,
                    ratio <= 1.05 ? " (within 5%)" : " (OVER 5%)", diff <= 1.0 ? "unchanged (<= 1/255)" : "CHANGED");
    }
}

BENCHMARK(crowds)->UseManualTime()->Iterations(9)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
