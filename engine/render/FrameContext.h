#pragma once
// What every pass of a frame may use: the scene, its GPU copy, programs,
// shared uniform buffers and GL helpers. Owned by the Renderer; passes keep a
// reference in their execute lambdas, so it outlives the graph.

#include "gl/FramebufferCache.h"
#include "gl/GlObjects.h"
#include "render/Aov.h"
#include "render/GpuScene.h"
#include "render/LightSetup.h"
#include "render/Programs.h"
#include "render/UniformBlocks.h"
#include "scene/Scene.h"

namespace dermis {

struct FrameContext {
    const Scene* scene = nullptr;
    GpuScene* gpuScene = nullptr;
    Programs* programs = nullptr;
    gl::FramebufferCache* framebuffers = nullptr;
    GLuint objectUniforms = 0;  // ObjectBlock buffer, rewritten per draw
    GLuint emptyVertexArray = 0;
    GLuint beckmannTable = 0;
    LightSetup lights;
    int width = 0;
    int height = 0;
    Aov aov = Aov::Final;

    void setViewport(int w, int h) const { glViewport(0, 0, w, h); }
    void drawFullscreenTriangle() const;
    void uploadObject(const gpu::ObjectBlock& block) const;
    gpu::ObjectBlock objectBlock(const GpuCharacter& character) const;
};

}  // namespace dermis
