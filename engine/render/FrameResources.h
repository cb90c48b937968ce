#pragma once
// The prepare step between planning and declaring a frame: the GL objects
// that live across frames, made or resized as the plan asks, and this
// frame's uniform blocks uploaded from it. A GL context must be current.
//
//   planFrame -> FrameResources::prepare -> declareFrame(graph, plan, resources.inputs()) -> compile, execute

#include "core/Result.h"
#include "gl/FramebufferCache.h"
#include "gl/GlObjects.h"
#include "graph/TextureDesc.h"
#include "render/FrameContext.h"
#include "render/FrameInputs.h"
#include "plan/FramePlan.h"
#include "render/GpuEnvironment.h"
#include "render/GpuScene.h"
#include "render/LightingScatter.h"
#include "render/Programs.h"
#include "plan/SceneGeometry.h"
#include "render/GpuEnvironment.h"
#include "render/TsMeshes.h"
#include "gpu/UniformBlocks.h"

#include <array>

namespace dermis {

class FrameResources {
public:
    // Makes the uniform buffers and the constant tables.
    FrameResources(const GpuScene& gpuScene, const Programs& programs, gl::FramebufferCache& framebuffers);
    FrameResources(const FrameResources&) = delete;
    FrameResources& operator=(const FrameResources&) = delete;

    // Makes or resizes the output, the shadow maps and the texture-space
    // meshes the plan needs, and uploads its uniform blocks. Errors: a frame
    // larger than this GL's maximum texture size.
    Status prepare(const FramePlan& plan, SceneGeometry& geometry);

    // What the frame imports and executes with, as prepared.
    FrameInputs inputs() const;
    GLuint output() const { return mOutput.get(); }
    const GpuEnvironment& environment() const { return mEnvironment; }
    const graph::TextureDesc& outputDesc() const { return mOutputDesc; }

private:
    void uploadFrameBlocks(const FramePlan& plan);
    void uploadSssBlocks(const FramePlan& plan);
    void prepareOutput(const FramePlan& plan);
    void prepareShadowMaps(const FramePlan& plan);

    const GpuScene& mGpuScene;
    FrameServices mServices;
    gl::Buffer mFrameUniforms;
    gl::Buffer mLightUniforms;
    gl::Buffer mObjectUniforms;
    gl::Buffer mCharacterUniforms;
    gl::Buffer mProfileUniforms;
    gl::Buffer mPassUniforms;
    gl::Buffer mRegionUniforms;
    gl::VertexArray mEmptyVertexArray;
    gl::Texture mBeckmann;
    gl::Texture mEnergy;
    gl::Texture mWhite;
    gl::Texture mBlack;
    LightingTables mLightingTables;
    struct ShadowMap {
        gl::Texture texture;
        graph::TextureDesc desc;
    };
    std::array<ShadowMap, DERMIS_MAX_SHADOWED_LIGHTS> mShadowMaps;
    size_t mShadowMapsUsed = 0;
    TsMeshes mTsMeshes;
    GpuEnvironment mEnvironment;
    gl::Texture mOutput;
    graph::TextureDesc mOutputDesc{};
};

}  // namespace dermis
