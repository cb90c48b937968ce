#pragma once
// The renderer: owns the GPU copy of a scene and, every frame, declares the
// render graph, lets it cull, and runs it. A GL context must be current.
//
//   Renderer renderer = *Renderer::create(scene);
//   renderer.renderFrame({640, 360, Aov::Final});
//   Image image = *renderer.readOutput();

#include "core/Image.h"
#include "core/Result.h"
#include "gl/GlGraphBackend.h"
#include "gl/GpuProfiler.h"
#include "render/Aov.h"
#include "render/FrameContext.h"
#include "render/FrameTimings.h"
#include "render/GpuScene.h"
#include "render/Programs.h"
#include "render/ShadowCache.h"
#include "scene/Scene.h"

#include <memory>

namespace dermis {

struct FrameRequest {
    int width = 640;
    int height = 360;
    Aov aov = Aov::Final;
    // Added to the mip level of material maps (albedo, normal, LEAN); tests
    // force level 0 with a large negative bias for supersampled references.
    float materialMipBias = 0.0f;
};

// Largest frame a request may ask for (GL_MAX_TEXTURE_SIZE may be smaller).
constexpr int kMaxFrameDimension = 16384;

class Renderer {
public:
    // Loads and uploads the scene's content and compiles the shaders. The
    // scene must outlive the renderer.
    static Result<std::unique_ptr<Renderer>> create(const Scene& scene);

    Status renderFrame(const FrameRequest& request);
    // The last frame's output: tone-mapped sRGB (values in [0,1]) for
    // Aov::Final, linear floats otherwise. Rows top first.
    Result<Image> readOutput();
    // Waits for outstanding GPU timers and folds them into timings().
    void finishTimings();
    // The last frame's output texture (RGBA8 for Aov::Final, RGBA32F
    // otherwise), for a viewer to draw without a CPU read-back.
    GLuint outputTexture() const { return mOutput.get(); }
    // Inspect every texture each pass writes (gl/NonFiniteCounter.h); slow.
    void setPassInspector(gl::PassInspector inspector) { mBackend.setInspector(std::move(inspector)); }
    // Recompiles every shader from disk. On an error the old programs stay
    // in use and the error (file and compiler log) is returned.
    Status reloadShaders();

    const FrameTimings& timings() const { return mTimings; }
    void resetTimings() { mTimings = FrameTimings{}; }
    uint64_t frameCount() const { return mFrame; }
    GpuScene& gpuScene() { return mGpuScene; }
    const SssPlan& sssPlan() const { return mFrameContext.sss; }

private:
    Renderer(const Scene& scene, GpuScene gpuScene, Programs programs);
    Status planFrame(const FrameRequest& request);
    void uploadFrameUniforms(const FrameRequest& request);
    void uploadSssUniforms();
    void declareFrame(graph::RenderGraph& graph, const FrameRequest& request);
    void ensureOutput(const FrameRequest& request);

    const Scene& mScene;
    GpuScene mGpuScene;
    Programs mPrograms;
    gl::GpuProfiler mProfiler;
    gl::GlGraphBackend mBackend;
    ShadowCache mShadowCache;
    FrameTimings mTimings;
    FrameContext mFrameContext;
    gl::Buffer mFrameUniforms;
    gl::Buffer mLightUniforms;
    gl::Buffer mObjectUniforms;
    gl::Buffer mCharacterUniforms;
    gl::Buffer mProfileUniforms;
    gl::Buffer mPassUniforms;
    gl::VertexArray mEmptyVertexArray;
    gl::Texture mBeckmann;
    gl::Texture mEnergy;
    gl::Texture mWhite;
    gl::Texture mBlack;
    ViewParams mView;
    gl::Texture mOutput;
    graph::TextureDesc mOutputDesc{};
    Aov mOutputAov = Aov::Final;
    uint64_t mFrame = 0;
};

}  // namespace dermis
