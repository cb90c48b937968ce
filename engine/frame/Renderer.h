#pragma once
// The renderer: owns the GPU copy of a scene and, every frame, plans it
// (plan/FramePlan.h, no GL), prepares its GL resources
// (render/FrameResources.h), declares the render graph
// (frame/FrameDeclaration.h), lets it cull, and runs it. A GL context must
// be current.
//
//   Renderer renderer = *Renderer::create(scene);
//   renderer.renderFrame({640, 360, Aov::Final});
//   Image image = *renderer.readOutput();

#include "core/Image.h"
#include "core/Result.h"
#include "gl/GlGraphBackend.h"
#include "gl/GpuProfiler.h"
#include "plan/Aov.h"
#include "plan/FramePlan.h"
#include "render/FrameResources.h"
#include "render/FrameTimings.h"
#include "render/GpuScene.h"
#include "render/Programs.h"
#include "plan/SceneGeometry.h"
#include "plan/PoseCache.h"
#include "plan/ShadowCache.h"
#include "scene/Scene.h"

#include <memory>
#include <optional>
#include <set>

namespace dermis {

class Renderer {
public:
    // Loads and uploads the scene's content and compiles the shaders. The
    // scene must outlive the renderer.
    static Result<std::unique_ptr<Renderer>> create(const Scene& scene);
    // The same with programs compiled before (Programs::build), shared by
    // renderers made one after another in one context (the stress test's
    // cases): compiling them is most of create's time on llvmpipe.
    // reloadShaders() replaces them for every renderer that shares them.
    static Result<std::unique_ptr<Renderer>> create(const Scene& scene, std::shared_ptr<Programs> programs);

    Status renderFrame(const FrameRequest& request);
    // The last frame's output: tone-mapped sRGB (values in [0,1]) for
    // Aov::Final, linear floats otherwise. Rows top first.
    Result<Image> readOutput();
    // Waits for outstanding GPU timers and folds them into timings().
    void finishTimings();
    // The last frame's output texture (RGBA8 for Aov::Final, RGBA32F
    // otherwise), for a viewer to draw without a CPU read-back.
    GLuint outputTexture() const { return mResources->output(); }
    // Inspect every texture each pass writes (gl/NonFiniteCounter.h); slow.
    void setPassInspector(gl::PassInspector inspector) { mBackend.setInspector(std::move(inspector)); }
    // Per-pass counts of sanitised values and the planted NaN of
    // `dermis stress --plant-nan` (gl/SanitiseCounters.h; counting is slow).
    gl::SanitiseCounters& sanitiseCounters() { return mBackend.sanitiseCounters(); }
    // The passes the last frame ran, in order.
    const std::vector<std::string>& framePasses() const { return mBackend.framePasses(); }
    // The texture-space irradiance texture (E x albedo^mix, shaders/ts_irradiance.frag)
    // of every character, in scene order, sizeTexels on a side, before
    // dilation and blurs; frame/IrradianceCapture.h gives the layout. Empty
    // for a character without SSS (or with sss.enabled false). In either
    // mode, as the last frame's view lit it (640 x 360 Final before the
    // first): its shadow maps, SSAO (the caller turns it off for a reference
    // that has none), energy conservation and ambient. The next frame and
    // readOutput() are not affected; sizeTexels is a power of two within
    // frame/IrradianceCapture.h's limits (an error otherwise).
    Result<std::vector<Image>> captureIrradianceTextures(int sizeTexels);
    // Recompiles every shader from disk. On an error the old programs stay
    // in use and the error (file and compiler log) is returned.
    Status reloadShaders();

    const FrameTimings& timings() const { return mTimings; }
    // Each character as the last frame planned it (for the timings JSON); empty before the first frame.
    std::vector<CharacterReport> characterReports() const;
    void resetTimings() { mTimings = FrameTimings{}; }
    // The next `frames` frames after a reset are warm-up: recorded, marked, not in the medians.
    void setWarmUpFrames(size_t frames) { mTimings.setWarmUpFrames(frames); }
    // Off: GL_TIME_ELAPSED instead of GL_TIMESTAMP pairs, so no GPU thread in a trace (what they cost: tools/benchmarks).
    void setGpuTimestamps(bool on) { mProfiler.setTimestamps(on); }
    // Off: no glFlush at each pass's start on llvmpipe (gl/GpuProfiler.h), so passes that share a framebuffer
    // share their time; what the flushes cost: tools/benchmarks.
    void setGpuBatchSplit(bool on) { mProfiler.setSplitBatches(on); }
    GpuScene& gpuScene() { return mGpuScene; }
    // The environment's GPU side: its map, block and per-character transfer buffers.
    const GpuEnvironment& gpuEnvironment() const;
    // The CPU side of the scene's meshes: bounds, UV layouts, rigs and their clips.
    const SceneGeometry& geometry() const { return mGeometry; }
    // The render graph's pooled transient targets (gl/TexturePool.h), in bytes.
    uint64_t texturePoolBytes() { return mBackend.pool().bytes(); }

private:
    Renderer(const Scene& scene, SceneGeometry geometry, GpuScene gpuScene, std::shared_ptr<Programs> programs);
    void warnOfFallbacks(const FramePlan& plan);
    void warnOfMissingLevels();

    const Scene& mScene;
    SceneGeometry mGeometry;
    GpuScene mGpuScene;
    std::shared_ptr<Programs> mPrograms;  // never null
    gl::GpuProfiler mProfiler;
    gl::GlGraphBackend mBackend;
    ShadowCache mShadowCache;
    PoseCache mPoseCache;
    std::unique_ptr<FrameResources> mResources;
    std::optional<FramePlan> mPlan;  // the frame being run: its passes read it while they execute
    FrameTimings mTimings;
    Aov mOutputAov = Aov::Final;
    FrameRequest mLastRequest;
    uint64_t mFrame = 0;
    std::set<int> mWarnedFallbacks;  // characters whose texture-space fall-back was logged
    bool mLevelsMadeAtLoad = false;  // render/SceneLoading.h makes levels of detail only when asked at load
    bool mWarnedMissingLevels = false;
};

}  // namespace dermis
