// 32 animated characters sharing the skin pixels of one (the goal: the
// screen-space SSS cost within 1.1x of one, and the skinning cost per
// character): the bending cylinder of the tests (out/content, written by
// build/tests/dermis_test_content) once at scale 4, and 32 times at scale
// 4 / sqrt(32) in an 8 x 4 grid over the same region, so that the SSS pixels
// match. Every frame is at a new time, so every character is skinned every
// frame. The SSS cost is measured two ways: the sum of the SSS passes' timers,
// and the frame with SSS on minus the frame with it off. llvmpipe rasterises a
// pass's draws when its framebuffer changes, so some of the work of the passes
// before (the 32 G-buffer draws) can land in the first SSS timers; the
// difference of whole frames does not depend on where it lands.
//
// What animation itself costs the SSS: the same scenes frozen (speed 0: each
// character keeps one pose, skinned once, plan/PoseCache.h)
// beside the animated ones. The eight renderers (1 and 32, animated and
// frozen, SSS on and off) take turns within each iteration.
#include "AnimatedCrowdBenchmarks.h"
#include "BenchContext.h"

#include "plan/Aov.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;
constexpr float kSingleScale = 4.0f;
constexpr int kColumns = 8, kRows = 4;

std::string cylinderPath() {
    return std::string(DERMIS_SOURCE_CONTENT_DIR) + "/../out/content/bending_cylinder.gltf";
}

Scene crowdScene(int count, bool animated) {
    Scene scene = contentScene("default.json");  // lights and settings
    scene.camera.positionM = glm::vec3(0.0f, 0.4f, 1.6f);
    scene.camera.targetM = glm::vec3(0.0f, 0.4f, 0.0f);
    scene.characters.clear();
    Character cylinder;
    cylinder.mesh.gltfPath = cylinderPath();
    cylinder.material.profile = "skin";
    cylinder.animation.clip = "bend";
    cylinder.animation.speed = animated ? 1.0f : 0.0f;
    if (count == 1) {
        // Frozen at the middle of the times the animated one is drawn at
        // (0.05 to 0.45 s), so that both cover about the same pixels.
        if (!animated) cylinder.animation.timeS = 0.25f;
        cylinder.name = "cylinder";
        cylinder.transform.scale = kSingleScale;
        scene.characters.push_back(cylinder);
        return scene;
    }
    const float scale = kSingleScale / std::sqrt(float(count));
    for (int i = 0; i < count; ++i) {
        Character c = cylinder;
        c.name = "cylinder " + std::to_string(i);
        c.transform.scale = scale;
        c.transform.translationM = glm::vec3((float(i % kColumns) - 3.5f) * 0.22f, float(i / kColumns) * 0.22f, 0.0f);
        c.animation.timeS = 0.1f * float(i);  // out of step, as a crowd is
        scene.characters.push_back(c);
    }
    return scene;
}

size_t skinPixels(Renderer& renderer) {
    (void)renderer.renderFrame({kWidth, kHeight, Aov::Object});
    auto image = renderer.readOutput();
    if (!image.ok()) return 0;
    return size_t(std::count_if(image->texels.begin(), image->texels.end(), [](const glm::vec4& t) { return t.r > 0.0f; }));
}

void animatedCrowd(benchmark::State& state) {
    context();
    if (!std::filesystem::exists(cylinderPath())) {
        state.SkipWithError("out/content/bending_cylinder.gltf not found: run build/tests/dermis_test_content out/content");
        return;
    }
    struct Case {
        int count;
        bool animated;
        bool sss;
        std::unique_ptr<Scene> scene;
        std::unique_ptr<Renderer> renderer;
        std::vector<double> sssPasses, skin, frame;
    };
    std::vector<Case> cases;
    for (int count : {1, kColumns * kRows})
    for (bool animated : {true, false})
    for (bool sss : {true, false}) {
        Case c{count, animated, sss, std::make_unique<Scene>(crowdScene(count, animated)), nullptr, {}, {}, {}};
        c.scene->settings.sss.enabled = sss;
        auto renderer = Renderer::create(*c.scene);
        if (!renderer.ok()) {
            state.SkipWithError(renderer.error().message().c_str());
            return;
        }
        c.renderer = std::move(*renderer);
        if (sss && animated) recorded()["animated/" + std::to_string(count) + "/pixels"] = double(skinPixels(*c.renderer));
        cases.push_back(std::move(c));
    }
    float timeS = 0.0f;
    for (auto _ : state) {
        double total = 0.0;
        timeS += 0.05f;
        for (Case& c : cases) {
            const std::vector<double> ms = renderAndTimeAt(*c.renderer, kWidth, kHeight, timeS, {"sss ", "skin:", ""});
            c.sssPasses.push_back(ms[0]);
            c.skin.push_back(ms[1]);
            c.frame.push_back(ms[2]);
            total += ms[2];
        }
        state.SetIterationTime(total * 1e-3);
    }
    for (Case& c : cases) {
        const std::string key =
            std::string(c.animated ? "animated/" : "frozen/") + std::to_string(c.count) + (c.sss ? "" : "/no sss");
        recorded()[key + "/sss"] = median(c.sssPasses);
        recorded()[key + "/skin per character"] = median(c.skin) / c.count;
        recorded()[key + "/frame"] = median(c.frame);
    }
}

}  // namespace

void printAnimatedCrowdSummary() {
    const auto& r = recorded();
    if (r.count("animated/1/sss") == 0) return;
    std::printf("\nAnimated characters sharing one's skin pixels, %dx%d, every character skinned every frame\n"
                "(median GPU ms; llvmpipe: CPU time; SSS on - off = frame with SSS minus frame without):\n"
                "| characters | skin pixels | SSS passes | ratio | SSS on - off | ratio | skinning per character | frame |\n"
                "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
                kWidth, kHeight);
    auto difference = [&](int count) {
        const std::string key = "animated/" + std::to_string(count);
        return r.at(key + "/frame") - r.at(key + "/no sss/frame");
    };
    for (int count : {1, kColumns * kRows}) {
        const std::string key = "animated/" + std::to_string(count);
        std::printf("| %d | %.0f | %.2f | %.3f | %.2f | %.3f | %.3f | %.1f |\n", count, r.at(key + "/pixels"),
                    r.at(key + "/sss"), r.at(key + "/sss") / r.at("animated/1/sss"), difference(count),
                    difference(count) / difference(1), r.at(key + "/skin per character"), r.at(key + "/frame"));
    }
    const double passes = r.at("animated/32/sss") / r.at("animated/1/sss");
    const double frames = difference(kColumns * kRows) / difference(1);
    std::printf("32 animated / 1, SSS: passes %.3fx, frames on - off %.3fx%s\n", passes, frames,
                frames <= 1.1 ? " (within 1.1x)" : " (OVER 1.1x)");
    // The same characters frozen: what animation itself adds to the SSS.
    auto frozenDifference = [&](int count) {
        const std::string key = "frozen/" + std::to_string(count);
        return r.at(key + "/frame") - r.at(key + "/no sss/frame");
    };
    std::printf("\nThe same scenes frozen (speed 0, skinned once):\n"
                "| characters | SSS passes animated | frozen | animated / frozen | SSS on - off animated | frozen | "
                "animated / frozen | frame animated | frozen |\n"
                "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (int count : {1, kColumns * kRows}) {
        const std::string animated = "animated/" + std::to_string(count), frozen = "frozen/" + std::to_string(count);
        std::printf("| %d | %.2f | %.2f | %.3f | %.2f | %.2f | %.3f | %.1f | %.1f |\n", count, r.at(animated + "/sss"),
                    r.at(frozen + "/sss"), r.at(animated + "/sss") / r.at(frozen + "/sss"), difference(count),
                    frozenDifference(count), difference(count) / frozenDifference(count), r.at(animated + "/frame"),
                    r.at(frozen + "/frame"));
    }
}

BENCHMARK(animatedCrowd)->UseManualTime()->Iterations(9)->Unit(benchmark::kMillisecond);

}  // namespace dermis::bench
