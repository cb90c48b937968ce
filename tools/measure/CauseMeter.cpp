#include "measure/CauseMeter.h"

#include "measure/MeasuredRender.h"

#include "core/ImageResample.h"
#include "plan/Aov.h"
#include "scene/SceneLoader.h"

#include <cmath>

namespace dermis::measure {

Result<CauseMeter> CauseMeter::create(Session& session, ReferenceImages& references, std::optional<Image> fullReference) {
    CauseMeter meter(references);
    const Scene& scene = *session.scene;
    meter.mSceneScatters = scene.settings.sss.enabled;
    const int width = references.settings().width;
    const int height = references.settings().height;
    if (fullReference) {
        meter.mFull = std::move(*fullReference);
    } else {
        auto full = references.full(scene);
        if (!full.ok()) return full.error();
        meter.mFull = std::move(*full);
    }
    auto off = references.sssOff(scene);
    if (!off.ok()) return off.error();
    meter.mSssOff = std::move(*off);
    auto thickness = references.thicknessMm(scene);
    if (!thickness.ok()) return thickness.error();
    auto ids = objectIds(session, width, height);
    if (!ids.ok()) return ids.error();
    std::vector<bool> isSss(scene.characters.size() + 1, false);
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        isSss[c + 1] = scene.characters[c].material.profile != kOpaqueProfile;
    }
    meter.mRegions = bench::classifyRegions(width, height, *ids, isSss, *thickness);
    // Only what scatters is an SSS pixel: a character's hair, eyes and cloth
    // are not (the scatter AOV, docs/materials.md).
    auto scatters = measure::sssMask(*session.renderer, width, height);
    if (!scatters.ok()) return scatters.error();
    for (size_t i = 0; i < meter.mRegions.size(); ++i)
        if (!(*scatters)[i]) meter.mRegions[i] = bench::kNoRegion;
    meter.mUncoveredPixels = bench::dropUncovered(meter.mRegions, {&meter.mFull, &meter.mSssOff});
    return meter;
}

Result<Image> CauseMeter::renderSssOff(Session& session, int renderWidth, int renderHeight) {
    const RenderSettings settings = session.scene->settings;
    Scene off = *session.scene;
    off.settings.sss.enabled = false;
    const std::string key = sceneToJson(off) + "@" + std::to_string(renderWidth) + "x" + std::to_string(renderHeight);
    if (auto found = mSssOffRenders.find(key); found != mSssOffRenders.end()) return found->second;
    session.scene->settings = off.settings;
    Status rendered = session.renderer->renderFrame({renderWidth, renderHeight, Aov::Diffuse});
    Result<Image> image = rendered.ok() ? session.renderer->readOutput() : Result<Image>(rendered.error());
    session.scene->settings = settings;
    if (!image.ok()) return image;
    const int width = mReferences->settings().width;
    const int height = mReferences->settings().height;
    Image diffuse = (renderWidth == width && renderHeight == height) ? std::move(*image)
                                                                     : resampleImage(*image, width, height);
    mSssOffRenders[key] = diffuse;
    return diffuse;
}

Result<bench::CauseErrors> CauseMeter::measure(Session& session, const Image& diffuse, int renderWidth, int renderHeight) {
    bench::CauseErrors errors;
    bench::measureCause(errors, bench::ErrorCause::Total, mFull, diffuse, mRegions);
    auto off = renderSssOff(session, renderWidth, renderHeight);
    if (!off.ok()) return off.error();
    bench::measureCause(errors, bench::ErrorCause::Irradiance, mSssOff, *off, mRegions);
    auto change = mReferences->scatterChange(session, mSceneScatters);
    if (!change.ok()) return change.error();
    bench::measureCause(errors, bench::ErrorCause::Scatter, bench::addImages(*off, *change), diffuse, mRegions);
    return errors;
}

}  // namespace dermis::measure
