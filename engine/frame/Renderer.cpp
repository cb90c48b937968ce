#include "frame/Renderer.h"
#include "render/SceneLoading.h"

#include "core/Limits.h"

#include "core/Log.h"
#include "frame/FrameDeclaration.h"
#include "frame/IrradianceCapture.h"
#include "gl/GlDebug.h"

#include <algorithm>
#include <new>
#include <string>

namespace dermis {

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene) {
    auto programs = Programs::build();
    if (!programs.ok()) return programs.error();
    return create(scene, std::make_shared<Programs>(std::move(*programs)));
}

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene, std::shared_ptr<Programs> programs) {
    static_assert(kMaxSceneCharacters == DERMIS_MAX_CHARACTERS, "the scene file's limit is the renderer's");
    if (scene.characters.size() > DERMIS_MAX_CHARACTERS) {
        return makeError(scene.path, std::to_string(scene.characters.size()) + " characters; the G-buffer's object ids allow " +
                                         std::to_string(DERMIS_MAX_CHARACTERS));
    }
    if (scene.lights.size() > DERMIS_MAX_LIGHTS) {
        log::warn(scene.path + ": only the first " + std::to_string(DERMIS_MAX_LIGHTS) + " of " +
                  std::to_string(scene.lights.size()) + " lights are used");
    }
    auto models = loadSharedSceneModels(scene);
    if (!models.ok()) return models.error();
    auto gpuScene = GpuScene::create(scene, *models);
    if (!gpuScene.ok()) return gpuScene.error();
    return std::unique_ptr<Renderer>(
        new Renderer(scene, SceneGeometry(*models), std::move(*gpuScene), std::move(programs)));
}

Renderer::Renderer(const Scene& scene, SceneGeometry geometry, GpuScene gpuScene, std::shared_ptr<Programs> programs)
    : mScene(scene),
      mGeometry(std::move(geometry)),
      mGpuScene(std::move(gpuScene)),
      mPrograms(std::move(programs)),
      mBackend(mProfiler),
      mResources(std::make_unique<FrameResources>(mGpuScene, *mPrograms, mBackend.framebuffers())),
      mLevelsMadeAtLoad(scene.settings.lod.maxErrorPx > 0.0f) {}

// Once per character, when texture-space mode first plans it.
void Renderer::warnOfFallbacks(const FramePlan& plan) {
    if (mScene.settings.mode != SssMode::TextureSpace) return;
    for (const TsCharacterPlan& character : plan.ts.characters) {
        if (character.fallback.empty() || !mWarnedFallbacks.insert(character.character).second) continue;
        log::warn(mScene.path + ": character '" + character.label + "' falls back to screen-space SSS in texture-space mode: " +
                  character.fallback);
    }
}

// Once, when levels of detail are asked for after a load that made none.
void Renderer::warnOfMissingLevels() {
    if (mWarnedMissingLevels || mLevelsMadeAtLoad || !(mScene.settings.lod.maxErrorPx > 0.0f)) return;
    mWarnedMissingLevels = true;
    log::warn(mScene.path + ": settings.lod.max_error_px is above 0, but the scene was loaded without levels of detail "
                            "(they are made at load, render/SceneLoading.h): full meshes are drawn until it is loaded again");
}

Status Renderer::renderFrame(const FrameRequest& frameRequest) {
    warnOfMissingLevels();
    if (const Status loaded = loadEnvironment(mScene, mGeometry); !loaded.ok()) return loaded.error();
    FrameRequest request = frameRequest;
    if (request.previousLods.empty() && mPlan) {
        for (const CharacterPlacement& character : mPlan->characters) request.previousLods.push_back(character.lod);
    }
    auto plan = planFrame(mScene, mGeometry, request, mShadowCache);
    if (!plan.ok()) return plan.error();
    mPlan = std::move(*plan);
    mPoseCache.markCurrent(*mPlan);
    warnOfFallbacks(*mPlan);
    mBackend.sanitiseCounters().bind();  // the prepare step's shaders include Sanitise.glsl too
    if (const Status prepared = mResources->prepare(*mPlan, mGeometry); !prepared.ok()) return prepared;
    mOutputAov = request.aov;
    mLastRequest = request;

    mProfiler.beginFrame(mFrame);
    graph::RenderGraph graph;
    declareFrame(graph, *mPlan, mResources->inputs());
    const Status compiled = graph.compile();
    if (!compiled.ok()) return compiled;
    graph.execute(mBackend);
    mBackend.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    recordShadowMaps(*mPlan, graph, mShadowCache);
    mPoseCache.record(*mPlan, graph);

    mTimings.addPassReports(mFrame, graph.passReports());
    mTimings.addTimings(mProfiler.takeCompleted());
    ++mFrame;
    return success();
}

Result<std::vector<Image>> Renderer::captureIrradianceTextures(int sizeTexels) {
    if (sizeTexels < kMinIrradianceCaptureTexels || sizeTexels > kMaxIrradianceCaptureTexels ||
        (sizeTexels & (sizeTexels - 1)) != 0) {
        return makeError("irradiance capture", "size " + std::to_string(sizeTexels) + " is not a power of two in [" +
                                                   std::to_string(kMinIrradianceCaptureTexels) + ", " +
                                                   std::to_string(kMaxIrradianceCaptureTexels) + "]");
    }
    // Planned as the UV-space AOV is (texture-space plans in either mode);
    // then every SSS character is made visible at the asked size, and the
    // output keeps the last frame's format so that readOutput() still reads it.
    FrameRequest request = mLastRequest;
    request.aov = Aov::IrradianceTexture;
    request.everyCharacterVisible = true;
    if (const Status loaded = loadEnvironment(mScene, mGeometry); !loaded.ok()) return loaded.error();
    auto plan = planFrame(mScene, mGeometry, request, mShadowCache);
    if (!plan.ok()) return plan.error();
    plan->aov = mLastRequest.aov;
    mPoseCache.markCurrent(*plan);
    for (TsCharacterPlan& character : plan->ts.characters) {
        character.visible = mScene.settings.sss.enabled && character.fallback.empty();
        character.size = sizeTexels;
    }
    mBackend.sanitiseCounters().bind();
    if (const Status prepared = mResources->prepare(*plan, mGeometry); !prepared.ok()) return prepared.error();

    std::vector<Image> images;
    mProfiler.beginFrame(mFrame);
    graph::RenderGraph graph;
    declareIrradianceCapture(graph, *plan, mResources->inputs(), images);
    if (const Status compiled = graph.compile(); !compiled.ok()) return compiled.error();
    graph.execute(mBackend);
    mBackend.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    recordShadowMaps(*plan, graph, mShadowCache);
    mPoseCache.record(*plan, graph);
    // Its pass timers are not the frame's.
    mProfiler.drain();
    mProfiler.takeCompleted();
    return images;
}

std::vector<CharacterReport> Renderer::characterReports() const {
    std::vector<CharacterReport> reports;
    if (!mPlan) return reports;
    for (size_t c = 0; c < mPlan->characters.size() && c < mScene.characters.size(); ++c) {
        const CharacterPlacement& placement = mPlan->characters[c];
        CharacterReport report;
        report.name = mScene.characters[c].name;
        report.visible = placement.visible;
        report.culledBecause = placement.culledBecause;
        report.footprintPixels = placement.footprintPixels;
        report.animated = placement.animated;
        report.clipTimeS = placement.clipTimeS;
        report.lod = placement.lod;
        report.lodErrorPx = placement.lodErrorPx;
        for (const TsCharacterPlan& ts : mPlan->ts.characters) {
            if (static_cast<size_t>(ts.character) != c || !mPlan->textureSpace) continue;
            report.textureSpaceSize = ts.runs() ? ts.size : 0;
            report.textureSpaceFallback = ts.fallback;
        }
        if (!mPlan->textureSpace && c < mPlan->sss.characterChoices.size()) {
            const CharacterSssChoice& sss = mPlan->sss.characterChoices[c];
            report.hasSss = sss.hasSss && mScene.settings.sss.enabled;  // disabled: no choice to report
            report.sssChoice = sss.choice;
            report.pixelsPerMm = sss.pixelsPerMm;
            report.sssChoiceSource = sss.source;
        }
        reports.push_back(std::move(report));
    }
    return reports;
}

Status Renderer::reloadShaders() {
    auto programs = Programs::build();
    if (!programs.ok()) return programs.error();
    *mPrograms = std::move(*programs);
    return success();
}

void Renderer::finishTimings() {
    mProfiler.drain();
    mTimings.addTimings(mProfiler.takeCompleted());
}

Result<Image> Renderer::readOutput() {
    const GLuint output = mResources->output();
    if (output == 0) return makeError("renderer", "no frame rendered yet");
    Image image;
    image.width = static_cast<int>(mResources->outputDesc().width);
    image.height = static_cast<int>(mResources->outputDesc().height);
    image.colourSpace = mOutputAov == Aov::Final ? ColourSpace::Srgb : ColourSpace::Linear;
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    // A target the driver could not allocate leaves the frame undefined (often
    // black) with no other sign; without --gl-debug only the error flag tells.
    if (gl::drainGlErrorsNoting().outOfMemory)
        return makeError("renderer", "the GL driver ran out of memory for the " + size + " frame's targets; try a smaller --size");
    std::vector<glm::vec4> bottomFirst;
    try {
        bottomFirst.resize(static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
        image.texels.resize(bottomFirst.size());
    } catch (const std::bad_alloc&) {
        return makeError("renderer", "not enough memory to read back the " + size + " frame; try a smaller --size");
    }
    glGetTextureImage(output, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(bottomFirst.size() * sizeof(glm::vec4)),
                      bottomFirst.data());
    const auto rowLength = static_cast<size_t>(image.width);
    for (size_t y = 0; y < static_cast<size_t>(image.height); ++y) {
        std::copy_n(bottomFirst.begin() + static_cast<std::ptrdiff_t>((static_cast<size_t>(image.height) - 1 - y) * rowLength),
                    rowLength, image.texels.begin() + static_cast<std::ptrdiff_t>(y * rowLength));
    }
    return image;
}

const GpuEnvironment& Renderer::gpuEnvironment() const { return mResources->environment(); }

}  // namespace dermis
