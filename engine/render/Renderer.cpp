#include "render/Renderer.h"

#include "gl/TexturePool.h"
#include "passes/AovPass.h"
#include "passes/CompositePass.h"
#include "passes/GBufferPass.h"
#include "passes/LightingPass.h"
#include "passes/ShadowPass.h"
#include "render/BeckmannTable.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace dermis {
namespace {

ShadowSettings shadowSettings(const RenderSettings& s) {
    ShadowSettings out;
    out.mapSize = s.shadowMapSize;
    out.biasConstantM = s.shadowBiasConstant;
    out.biasSlopeTexels = s.shadowBiasSlope;
    out.filter = s.shadowFilter == "poisson" ? 1 : 0;
    return out;
}

gl::Texture makeBeckmannTexture() {
    const std::vector<float> table = makeBeckmannTable(kBeckmannTableSize);
    gl::Texture texture = gl::createTexture2D({kBeckmannTableSize, kBeckmannTableSize, graph::TextureFormat::R32F});
    glTextureSubImage2D(texture.get(), 0, 0, 0, kBeckmannTableSize, kBeckmannTableSize, GL_RED, GL_FLOAT, table.data());
    return texture;
}

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene) {
    auto gpuScene = GpuScene::create(scene);
    if (!gpuScene.ok()) return gpuScene.error();
    auto programs = Programs::build();
    if (!programs.ok()) return programs.error();
    return std::unique_ptr<Renderer>(new Renderer(scene, std::move(*gpuScene), std::move(*programs)));
}

Renderer::Renderer(const Scene& scene, GpuScene gpuScene, Programs programs)
    : mScene(scene), mGpuScene(std::move(gpuScene)), mPrograms(std::move(programs)), mBackend(mProfiler) {
    mFrameUniforms = gl::createBuffer();
    glNamedBufferStorage(mFrameUniforms.get(), sizeof(gpu::FrameBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    mLightUniforms = gl::createBuffer();
    glNamedBufferStorage(mLightUniforms.get(), sizeof(gpu::LightsBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    mObjectUniforms = gl::createBuffer();
    glNamedBufferStorage(mObjectUniforms.get(), sizeof(gpu::ObjectBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    mEmptyVertexArray = gl::createVertexArray();
    mBeckmann = makeBeckmannTexture();

    mFrameContext.scene = &mScene;
    mFrameContext.gpuScene = &mGpuScene;
    mFrameContext.programs = &mPrograms;
    mFrameContext.framebuffers = &mBackend.framebuffers();
    mFrameContext.objectUniforms = mObjectUniforms.get();
    mFrameContext.emptyVertexArray = mEmptyVertexArray.get();
    mFrameContext.beckmannTable = mBeckmann.get();
}

void Renderer::uploadFrameUniforms(const FrameRequest& request) {
    const Camera& camera = mScene.camera;
    const float aspect = float(request.width) / float(request.height);
    gpu::FrameBlock frame{};
    frame.viewFromWorld = glm::lookAt(camera.positionM, camera.targetM, camera.up);
    frame.worldFromView = glm::inverse(frame.viewFromWorld);
    frame.clipFromView = glm::perspective(glm::radians(camera.verticalFovDeg), aspect, camera.nearM, camera.farM);
    frame.viewFromClip = glm::inverse(frame.clipFromView);
    frame.clipFromWorld = frame.clipFromView * frame.viewFromWorld;
    frame.cameraPositionM = glm::vec4(camera.positionM, 1.0f);
    frame.viewport = glm::vec4(request.width, request.height, 1.0f / float(request.width), 1.0f / float(request.height));
    frame.depthRangeM = glm::vec4(camera.nearM, camera.farM, 0.0f, 0.0f);
    frame.ambient = glm::vec4(mScene.settings.ambient, 0.0f);
    frame.background = glm::vec4(mScene.background.colour, 1.0f);
    frame.shading = glm::vec4(mScene.settings.exposure, 0.5f, float(mFrameContext.lights.lightCount), float(int(request.aov)));
    glNamedBufferSubData(mFrameUniforms.get(), 0, sizeof frame, &frame);
    glNamedBufferSubData(mLightUniforms.get(), 0, sizeof(gpu::LightsBlock), &mFrameContext.lights.block);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_FRAME, mFrameUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_LIGHTS, mLightUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_OBJECT, mObjectUniforms.get());
}

void Renderer::ensureOutput(const FrameRequest& request) {
    const graph::TextureDesc desc{static_cast<uint32_t>(request.width), static_cast<uint32_t>(request.height),
                                  request.aov == Aov::Final ? graph::TextureFormat::Rgba8 : graph::TextureFormat::Rgba32F};
    if (mOutput.isValid() && desc == mOutputDesc) return;
    if (mOutput.isValid()) mBackend.framebuffers().forget(mOutput.get());
    mOutput = gl::createTexture2D(desc);
    mOutputDesc = desc;
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
    mGpuScene.updateTransforms(mScene);
    mFrameContext.width = request.width;
    mFrameContext.height = request.height;
    mFrameContext.aov = request.aov;
    mFrameContext.lights = setupLights(mScene.lights, mGpuScene.worldBounds(), shadowSettings(mScene.settings));
    uploadFrameUniforms(request);
    ensureOutput(request);
    mOutputAov = request.aov;

    graph::RenderGraph graph;
    const graph::TextureHandle output = graph.importTexture("output", mOutputDesc, mOutput.get());
    const std::vector<graph::TextureHandle> shadowMaps = addShadowPasses(graph, mFrameContext, mShadowCache);
    const GBuffer gbuffer = addGBufferPass(graph, mFrameContext);
    const Lighting lighting = addLightingPass(graph, mFrameContext, gbuffer, shadowMaps);
    if (request.aov == Aov::Final) {
        const graph::TextureHandle hdr = addCompositePass(graph, mFrameContext, gbuffer, lighting);
        graph.markOutput(addTonemapPass(graph, mFrameContext, hdr, output));
    } else {
        graph.markOutput(addAovPass(graph, mFrameContext, gbuffer, lighting, output));
    }

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
