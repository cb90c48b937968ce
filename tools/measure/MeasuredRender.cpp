#include "measure/MeasuredRender.h"

#include "core/Log.h"
#include "plan/Aov.h"
#include "frame/Renderer.h"
#include "reference/ReferenceDefinition.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace dermis::measure {

Result<MeasuredRender> measureRender(Session& session, const std::string& scenePath, int width, int height,
                                     int frames, int warmUpFrames) {
    Renderer& renderer = *session.renderer;
    for (int i = 0; i < warmUpFrames; ++i) {
        if (const Status status = renderer.renderFrame({width, height, Aov::Final}); !status.ok()) return status.error();
    }
    renderer.finishTimings();
    renderer.resetTimings();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        if (const Status status = renderer.renderFrame({width, height, Aov::Final}); !status.ok()) return status.error();
    }
    glFinish();
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    renderer.finishTimings();
    RunInfo info = session.runInfo(scenePath, width, height, frames);
    info.wallMsPerFrame = wallMs / frames;
    MeasuredRender result;
    result.timings = renderer.timings();
    result.timingsJson = result.timings.toJson(info);
    result.wallMsPerFrame = info.wallMsPerFrame;
    auto finalImage = renderer.readOutput();
    if (!finalImage.ok()) return finalImage.error();
    result.finalImage = std::move(*finalImage);
    if (const Status status = renderer.renderFrame({width, height, Aov::Diffuse}); !status.ok()) return status.error();
    auto diffuse = renderer.readOutput();
    if (!diffuse.ok()) return diffuse.error();
    result.diffuse = std::move(*diffuse);
    return result;
}

Result<std::vector<int>> objectIds(Session& session, int width, int height) {
    if (const Status status = session.renderer->renderFrame({width, height, Aov::Object}); !status.ok())
        return status.error();
    auto ids = session.renderer->readOutput();
    if (!ids.ok()) return ids.error();
    std::vector<int> out(ids->texels.size(), 0);
    const long characters = static_cast<long>(session.scene->characters.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const long id = std::lround(ids->texels[i].r);
        out[i] = id >= 1 && id <= characters ? static_cast<int>(id) : 0;
    }
    return out;
}

Result<std::vector<uint8_t>> sssMask(Renderer& renderer, int width, int height) {
    if (const Status status = renderer.renderFrame({width, height, Aov::Scatter}); !status.ok()) return status.error();
    auto shares = renderer.readOutput();
    if (!shares.ok()) return shares.error();
    std::vector<uint8_t> mask(shares->texels.size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = shares->texels[i].r > 0.0f ? 1 : 0;
    return mask;
}

Result<Image> loadReferenceImage(const std::string& path, int width, int height, const Scene& scene) {
    auto image = loadImage(path, ColourSpace::Linear);
    if (!image.ok()) return image.error();
    if (image->storedType != "float" && image->storedType != "half") {
        return makeError(path, "the reference must be a linear float image (dermis reference writes one as .exr), not " +
                                   image->storedType + " values");
    }
    const bool recorded = std::any_of(image->attributes.begin(), image->attributes.end(),
                                      [](const auto& attribute) { return attribute.first == reference::kDefinitionAttribute; });
    if (!recorded)
        log::warn(path + ": no record of what it is a reference of (not made by dermis reference): taken as it is, "
                  "unchecked against the scene");
    for (const auto& [name, record] : image->attributes) {
        if (name == reference::kSamplesPerPixelAttribute && record != "1") {
            log::warn(path + ": the reference averages " + record + " samples per pixel (--spp " + record +
                      "), where the engine shades each pixel's centre: the outlines' antialiasing counts as error "
                      "(make it with dermis reference --spp 1)");
        }
        if (name != reference::kDefinitionAttribute) continue;
        const std::vector<std::string> differing = reference::definitionMismatch(record, scene);
        if (differing.empty()) continue;
        std::string parts;
        for (const std::string& part : differing) parts += (parts.empty() ? "" : ", ") + part;
        const std::string scenePath = scene.path.empty() ? std::string("SCENE") : scene.path;
        return makeError(path, "a reference of another scene: it differs from " +
                                   (scene.path.empty() ? std::string("this scene") : scene.path) + " in its " + parts +
                                   " (make it with dermis reference " + scenePath + " and the same --set)");
    }
    if (image->width != width || image->height != height) {
        return makeError(path, "the reference is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                                   " but the frame is " + std::to_string(width) + "x" + std::to_string(height) +
                                   " (make it with dermis reference --size " + std::to_string(width) + "x" +
                                   std::to_string(height) + ")");
    }
    return image;
}

nlohmann::ordered_json differenceJson(const ImageDifference& difference) {
    auto finite = [](double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); };
    nlohmann::ordered_json json;
    json["sss_pixels"] = difference.pixels;
    json["relative_rmse"] = finite(difference.relativeRmse);
    json["rmse"] = finite(difference.rmse);
    json["max_abs_difference"] = finite(difference.maxAbsDifference);
    json["psnr_db"] = finite(difference.psnrDb);
    json["peak"] = finite(difference.peak);
    return json;
}

}  // namespace dermis::measure
