#include "BenchContext.h"

#include "measure/MeasuredRender.h"

#include "core/Log.h"
#include "scene/SceneLoader.h"

#include <cstdio>
#include <cstdlib>

namespace dermis::bench {

gl::Context& context() {
    static std::unique_ptr<gl::Context> sContext = [] {
        auto made = gl::createHeadlessContext({});
        if (!made.ok()) {
            std::fprintf(stderr, "error: %s\n", made.error().message().c_str());
            std::exit(1);
        }
        return std::move(*made);
    }();
    return *sContext;
}

const Scene& contentScene(const std::string& name) {
    static std::map<std::string, std::unique_ptr<Scene>> sScenes;
    auto& slot = sScenes[name];
    if (!slot) {
        auto scene = loadScene(std::string(DERMIS_SOURCE_CONTENT_DIR) + "/scenes/" + name);
        if (!scene.ok()) {
            std::fprintf(stderr, "error: %s\n", scene.error().message().c_str());
            std::exit(1);
        }
        slot = std::make_unique<Scene>(std::move(*scene));
    }
    return *slot;
}

Image renderAov(Renderer& renderer, int width, int height, Aov aov) {
    if (!renderer.renderFrame({width, height, aov}).ok()) return {};
    auto image = renderer.readOutput();
    return image.ok() ? std::move(*image) : Image{};
}

std::vector<uint8_t> sssPixelMask(Renderer& renderer, int width, int height) {
    auto mask = measure::sssMask(renderer, width, height);
    return mask.ok() ? std::move(*mask) : std::vector<uint8_t>{};
}

double renderAndTime(Renderer& renderer, int width, int height, const std::string& prefix) {
    return renderAndTimeAt(renderer, width, height, 0.0f, {prefix})[0];
}

std::vector<double> renderAndTimeAt(Renderer& renderer, int width, int height, float timeS,
                                    const std::vector<std::string>& prefixes) {
    renderer.resetTimings();
    FrameRequest request{width, height, Aov::Final};
    request.timeS = timeS;
    const Status status = renderer.renderFrame(request);
    if (!status.ok()) {
        std::fprintf(stderr, "error: %s\n", status.error().message().c_str());
        std::exit(1);
    }
    renderer.finishTimings();
    std::vector<double> ms(prefixes.size(), 0.0);
    for (const PassSummary& pass : renderer.timings().summary()) {
        for (size_t i = 0; i < prefixes.size(); ++i)
            if (pass.executed && pass.name.rfind(prefixes[i], 0) == 0) ms[i] += pass.gpuMs;
    }
    return ms;
}

std::map<std::string, double>& recorded() {
    static std::map<std::string, double> sRecorded;
    return sRecorded;
}

}  // namespace dermis::bench
