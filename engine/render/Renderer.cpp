#include "render/Renderer.h"

#include "core/Log.h"
#include "gl/TexturePool.h"
#include "passes/AovPass.h"
#include "passes/CompositePass.h"
#include "passes/GBufferPass.h"
#include "passes/LeanSpecularPass.h"
#include "passes/LightingPass.h"
#include "passes/ShadowPass.h"
#include "passes/SsaoPass.h"
#include "passes/SssPasses.h"
#include "passes/TextureSpacePasses.h"
#include "passes/TransmittancePass.h"
#include "render/BeckmannTable.h"
#include "render/SssVariant.h"
#include "sss/EnergyTable.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace dermis {
namespace {

gl::Texture makeTableTexture(const std::vector<float>& table, int size) {
    const auto side = static_cast<uint32_t>(size);
    gl::Texture texture = gl::createTexture2D({side, side, graph::TextureFormat::R32F});
    glTextureSubImage2D(texture.get(), 0, 0, 0, size, size, GL_RED, GL_FLOAT, table.data());
    return texture;
}

gl::Texture makeSolidTexture(float value) {
    gl::Texture texture = gl::createTexture2D({1, 1, graph::TextureFormat::Rgba8});
    const float texel[4] = {value, value, value, value};
    glTextureSubImage2D(texture.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, texel);
    return texture;
}

gl::Buffer makeUniformBuffer(size_t bytes) {
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene) {
    if (scene.characters.size() > DERMIS_MAX_CHARACTERS) {
        return makeError(scene.path, std::to_string(scene.characters.size()) + " characters; the G-buffer's object ids allow " +
                                         std::to_string(DERMIS_MAX_CHARACTERS));
    }
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (scene.lights[i].type == LightType::Point && scene.lights[i].castsShadow) {
            log::warn(scene.path + ": /lights/" + std::to_string(i) + ": point lights cast no shadow yet (no cube maps)");
        }
    }
    if (scene.lights.size() > DERMIS_MAX_LIGHTS) {
        log::warn(scene.path + ": only the first " + std::to_string(DERMIS_MAX_LIGHTS) + " of " +
                  std::to_string(scene.lights.size()) + " lights are used");
    }
    auto gpuScene = GpuScene::create(scene);
    if (!gpuScene.ok()) return gpuScene.error();
    auto programs = Programs::build();
    if (!programs.ok()) return programs.error();
    return std::unique_ptr<Renderer>(new Renderer(scene, std::move(*gpuScene), std::move(*programs)));
}

Renderer::Renderer(const Scene& scene, GpuScene gpuScene, Programs programs)
    : mScene(scene), mGpuScene(std::move(gpuScene)), mPrograms(std::move(programs)), mBackend(mProfiler) {
    mFrameUniforms = makeUniformBuffer(sizeof(gpu::FrameBlock));
    mLightUniforms = makeUniformBuffer(sizeof(gpu::LightsBlock));
    mObjectUniforms = makeUniformBuffer(sizeof(gpu::ObjectBlock));
    mCharacterUniforms = makeUniformBuffer(sizeof(gpu::CharactersBlock));
    mProfileUniforms = makeUniformBuffer(sizeof(gpu::ProfilesBlock));
    mPassUniforms = makeUniformBuffer(kMaxPassBlockBytes);
    mEmptyVertexArray = gl::createVertexArray();
    mBeckmann = makeTableTexture(makeBeckmannTable(kBeckmannTableSize), kBeckmannTableSize);
    mEnergy = makeTableTexture(makeEnergyTable(kEnergyTableSize), kEnergyTableSize);
    mWhite = makeSolidTexture(1.0f);
    mBlack = makeSolidTexture(0.0f);

    mFrameContext.scene = &mScene;
    mFrameContext.gpuScene = &mGpuScene;
    mFrameContext.programs = &mPrograms;
    mFrameContext.framebuffers = &mBackend.framebuffers();
    mFrameContext.objectUniforms = mObjectUniforms.get();
    mFrameContext.passUniforms = mPassUniforms.get();
    mFrameContext.emptyVertexArray = mEmptyVertexArray.get();
    mFrameContext.beckmannTable = mBeckmann.get();
    mFrameContext.energyTable = mEnergy.get();
    mFrameContext.whiteTexture = mWhite.get();
    mFrameContext.blackTexture = mBlack.get();
}

Status Renderer::planFrame(const FrameRequest& request) {
    const Camera& camera = mScene.camera;
    mView.viewFromWorld = glm::lookAt(camera.positionM, camera.targetM, camera.up);
    mView.clipFromView = glm::perspective(glm::radians(camera.verticalFovDeg),
                                          float(request.width) / float(request.height), camera.nearM, camera.farM);
    mView.nearM = camera.nearM;
    mView.widthPx = request.width;
    mView.heightPx = request.height;

    mGpuScene.updateTransforms(mScene);
    std::vector<Bounds> bounds;
    for (const GpuCharacter& c : mGpuScene.characters()) bounds.push_back(c.worldBounds);
    auto plan = planSss(mScene, bounds, mView);
    if (!plan.ok()) return plan.error();

    mFrameContext.width = request.width;
    mFrameContext.height = request.height;
    mFrameContext.aov = request.aov;
    mFrameContext.lean = frameUsesLean(mScene.settings);
    mFrameContext.sss = std::move(*plan);
    mFrameContext.lights = setupLights(mScene.lights, mGpuScene.worldBounds(), mScene.settings.shadow);
    // A shadowed light is a back light when it is behind some visible SSS character.
    for (int index : mFrameContext.lights.shadowedLights) {
        const Light& light = mScene.lights[static_cast<size_t>(index)];
        bool behind = false;
        for (size_t c = 0; c < bounds.size() && !behind; ++c) {
            const int slot = mFrameContext.sss.slotOfCharacter[c];
            behind = slot > 0 && mFrameContext.sss.slots[static_cast<size_t>(slot - 1)].visible &&
                     isBackLight(light, bounds[c], camera.positionM);
        }
        mFrameContext.lights.block.lights[index].shadowDepth.w = behind ? 1.0f : 0.0f;
    }
    return success();
}

void Renderer::uploadFrameUniforms(const FrameRequest& request) {
    const Camera& camera = mScene.camera;
    const RenderSettings& settings = mScene.settings;
    gpu::FrameBlock frame{};
    frame.viewFromWorld = mView.viewFromWorld;
    frame.worldFromView = glm::inverse(frame.viewFromWorld);
    frame.clipFromView = mView.clipFromView;
    frame.viewFromClip = glm::inverse(frame.clipFromView);
    frame.clipFromWorld = frame.clipFromView * frame.viewFromWorld;
    frame.cameraPositionM = glm::vec4(camera.positionM, 1.0f);
    frame.viewport = glm::vec4(request.width, request.height, 1.0f / float(request.width), 1.0f / float(request.height));
    frame.depthRangeM = glm::vec4(camera.nearM, camera.farM, 0.0f, 0.0f);
    frame.ambient = glm::vec4(settings.ambient, 0.0f);
    frame.background = glm::vec4(mScene.background.colour, 1.0f);
    frame.shading = glm::vec4(settings.exposure, settings.sss.mix, float(mFrameContext.lights.lightCount),
                              float(int(request.aov)));
    frame.features = glm::vec4(settings.energyConservation ? 1.0f : 0.0f, mView.pixelsPerMetreAtUnitDepth(),
                               settings.ssao.strength, request.materialMipBias);
    glNamedBufferSubData(mFrameUniforms.get(), 0, sizeof frame, &frame);
    glNamedBufferSubData(mLightUniforms.get(), 0, sizeof(gpu::LightsBlock), &mFrameContext.lights.block);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_FRAME, mFrameUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_LIGHTS, mLightUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_OBJECT, mObjectUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_CHARACTERS, mCharacterUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PROFILES, mProfileUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PASS, mPassUniforms.get());
    glBindTextureUnit(kBeckmannUnit, mBeckmann.get());
    glBindTextureUnit(kEnergyUnit, mEnergy.get());
}

void Renderer::uploadSssUniforms() {
    const SsaoSettings& ssao = mScene.settings.ssao;
    gpu::CharactersBlock characters{};
    const size_t count = std::min<size_t>(mScene.characters.size(), DERMIS_MAX_CHARACTERS);
    for (size_t c = 0; c < count; ++c) {
        const Character& character = mScene.characters[c];
        const float radiusM = character.ssao.radiusM > 0.0f ? character.ssao.radiusM : ssao.radiusM;
        const int samples = character.ssao.samples > 0 ? character.ssao.samples : ssao.samples;
        const bool lean = c < mGpuScene.characters().size() && mGpuScene.characters()[c].leanMap1.isValid();
        characters.characters[c + 1].params =
            glm::vec4(float(mFrameContext.sss.slotOfCharacter[c]), radiusM, float(samples), lean ? 1.0f : 0.0f);
    }
    glNamedBufferSubData(mCharacterUniforms.get(), 0, sizeof characters, &characters);

    gpu::ProfilesBlock profiles{};
    for (const SssSlotPlan& slot : mFrameContext.sss.slots) {
        gpu::ProfileParams& p = profiles.profiles[slot.slot];
        const auto& gaussians = slot.profile->gaussians();
        const size_t n = std::min<size_t>(gaussians.size(), DERMIS_MAX_PROFILE_GAUSSIANS);
        for (size_t i = 0; i < n; ++i) p.gaussians[i] = glm::vec4(gaussians[i].weight, gaussians[i].varianceMm2);
        p.info = glm::vec4(float(n), slot.initWeight);
    }
    profiles.transmittance =
        glm::vec4(mScene.settings.transmittance.shrinkMm, mScene.settings.transmittance.strength, 0.0f, 0.0f);
    glNamedBufferSubData(mProfileUniforms.get(), 0, sizeof profiles, &profiles);
}

void Renderer::ensureOutput(const FrameRequest& request) {
    const graph::TextureDesc desc{static_cast<uint32_t>(request.width), static_cast<uint32_t>(request.height),
                                  request.aov == Aov::Final ? graph::TextureFormat::Rgba8 : graph::TextureFormat::Rgba32F};
    if (mOutput.isValid() && desc == mOutputDesc) return;
    if (mOutput.isValid()) mBackend.framebuffers().forget(mOutput.get());
    mOutput = gl::createTexture2D(desc);
    mOutputDesc = desc;
}

void Renderer::declareFrame(graph::RenderGraph& graph, const FrameRequest& request) {
    FrameContext& frame = mFrameContext;
    const graph::TextureDesc solidDesc{1, 1, graph::TextureFormat::Rgba8};
    const graph::TextureHandle output = graph.importTexture("output", mOutputDesc, mOutput.get());
    const graph::TextureHandle white = graph.importTexture("white", solidDesc, mWhite.get());
    const graph::TextureHandle black = graph.importTexture("black", solidDesc, mBlack.get());

    const std::vector<graph::TextureHandle> shadowMaps = addShadowPasses(graph, frame, mShadowCache);
    const GBuffer gbuffer = addGBufferPass(graph, frame);
    const graph::TextureHandle ambientOcclusion = addSsaoPasses(graph, frame, gbuffer, white);
    const Lighting lighting = addLightingPass(graph, frame, gbuffer, shadowMaps, ambientOcclusion, gbuffer.hasLean());

    // In the LEAN variants the specular comes after the SSS chain, which blurs the moments.
    if (request.aov == Aov::Final || request.aov == Aov::Diffuse || (request.aov == Aov::Specular && gbuffer.hasLean())) {
        const graph::TextureHandle irradiance =
            addTransmittancePass(graph, frame, gbuffer, shadowMaps, lighting.irradiance, black);
        graph::TextureHandle diffuse;
        LeanShading lean;
        if (mScene.settings.mode == SssMode::TextureSpace) {
            diffuse = addTextureSpacePasses(graph, frame, gbuffer, shadowMaps, ambientOcclusion, lighting.irradiance);
        } else {
            const SssChain chain = addSssChain(graph, frame, gbuffer, irradiance, gbuffer.leanTargets());
            diffuse = chain.diffuse;
            if (gbuffer.hasLean()) lean = {chain.extras[0], chain.diffuse, lighting.visibility};
        }
        if (request.aov == Aov::Final) {
            const graph::TextureHandle hdr = addCompositePass(graph, frame, gbuffer, diffuse, lighting.specular, lean);
            graph.markOutput(addTonemapPass(graph, frame, hdr, output));
            return;
        }
        if (request.aov == Aov::Specular) {
            const graph::TextureHandle specular = addLeanSpecularPass(graph, frame, gbuffer, lean, lighting.specular);
            graph.markOutput(addAovPass(graph, frame, {gbuffer, {}, specular, {}}, output));
            return;
        }
        graph.markOutput(addAovPass(graph, frame, {gbuffer, diffuse, {}, {}}, output));
        return;
    }
    AovInputs inputs{gbuffer, {}, lighting.specular, {}};
    if (request.aov == Aov::Irradiance) inputs.component = lighting.irradiance;
    if (request.aov == Aov::Ao) inputs.component = ambientOcclusion;
    if (request.aov == Aov::Transmittance || request.aov == Aov::Thickness) {
        inputs.component = addTransmittancePass(graph, frame, gbuffer, shadowMaps, {}, black);
    }
    if (aovIsUvLayout(request.aov)) {
        inputs.component = addTsAovPasses(graph, frame, request.aov, gbuffer, shadowMaps, ambientOcclusion, black);
    }
    graph.markOutput(addAovPass(graph, frame, inputs, output));
}

Status Renderer::renderFrame(const FrameRequest& request) {
    if (request.width <= 0 || request.height <= 0 || request.width > kMaxFrameDimension ||
        request.height > kMaxFrameDimension) {
        return makeError("frame size", std::to_string(request.width) + "x" + std::to_string(request.height) +
                                           " is outside 1x1 .. " + std::to_string(kMaxFrameDimension) + "x" +
                                           std::to_string(kMaxFrameDimension));
    }
    GLint maxTexture = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    if (request.width > maxTexture || request.height > maxTexture) {
        return makeError("frame size", "larger than this GL's maximum texture size " + std::to_string(maxTexture));
    }

    mProfiler.beginFrame(mFrame);
    if (const Status planned = planFrame(request); !planned.ok()) return planned;
    uploadFrameUniforms(request);
    uploadSssUniforms();
    ensureOutput(request);
    mOutputAov = request.aov;

    graph::RenderGraph graph;
    declareFrame(graph, request);
    const Status compiled = graph.compile();
    if (!compiled.ok()) return compiled;
    graph.execute(mBackend);
    mBackend.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    mTimings.addPassReports(graph.passReports());
    mTimings.addTimings(mProfiler.takeCompleted());
    ++mFrame;
    return success();
}

Status Renderer::reloadShaders() {
    auto programs = Programs::build();
    if (!programs.ok()) return programs.error();
    mPrograms = std::move(*programs);
    return success();
}

void Renderer::finishTimings() {
    mProfiler.drain();
    mTimings.addTimings(mProfiler.takeCompleted());
}

Result<Image> Renderer::readOutput() {
    if (!mOutput.isValid()) return makeError("renderer", "no frame rendered yet");
    Image image;
    image.width = static_cast<int>(mOutputDesc.width);
    image.height = static_cast<int>(mOutputDesc.height);
    image.colourSpace = mOutputAov == Aov::Final ? ColourSpace::Srgb : ColourSpace::Linear;
    std::vector<glm::vec4> bottomFirst(static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
    glGetTextureImage(mOutput.get(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(bottomFirst.size() * sizeof(glm::vec4)),
                      bottomFirst.data());
    image.texels.resize(bottomFirst.size());
    const auto rowLength = static_cast<size_t>(image.width);
    for (size_t y = 0; y < static_cast<size_t>(image.height); ++y) {
        std::copy_n(bottomFirst.begin() + static_cast<std::ptrdiff_t>((static_cast<size_t>(image.height) - 1 - y) * rowLength),
                    rowLength, image.texels.begin() + static_cast<std::ptrdiff_t>(y * rowLength));
    }
    return image;
}

}  // namespace dermis
