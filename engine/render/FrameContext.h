#pragma once
// What every pass of a frame may use: the scene, its GPU copy, programs,
// shared uniform buffers, the frame's SSS plan and GL helpers. Owned by the
// Renderer; passes keep a reference in their execute lambdas, so it outlives
// the graph.

#include "gl/FramebufferCache.h"
#include "gl/GlObjects.h"
#include "render/Aov.h"
#include "render/GpuScene.h"
#include "render/LightSetup.h"
#include "render/Programs.h"
#include "render/SssPlan.h"
#include "render/UniformBlocks.h"
#include "scene/Scene.h"

#include <memory>

namespace dermis {

struct TextureSpaceState;

// Texture units every fullscreen pass agrees on for shared tables.
constexpr GLuint kBeckmannUnit = DERMIS_UNIT_BECKMANN;
constexpr GLuint kEnergyUnit = DERMIS_UNIT_ENERGY;

struct FrameContext {
    const Scene* scene = nullptr;
    GpuScene* gpuScene = nullptr;
    Programs* programs = nullptr;
    gl::FramebufferCache* framebuffers = nullptr;
    GLuint objectUniforms = 0;  // ObjectBlock, rewritten per draw
    GLuint passUniforms = 0;    // the per-pass block at DERMIS_BINDING_PASS, rewritten per pass
    GLuint emptyVertexArray = 0;
    GLuint beckmannTable = 0;
    GLuint energyTable = 0;
    GLuint whiteTexture = 0;    // 1x1 RGBA8 white: a neutral input (AO = 1)
    GLuint blackTexture = 0;    // 1x1 RGBA8 black: nothing (no transmitted light)
    LightSetup lights;
    SssPlan sss;
    // Texture-space mode's state across frames (its meshes, this frame's plan),
    // made on first use by passes/TextureSpacePasses.cpp.
    std::shared_ptr<TextureSpaceState> textureSpace;
    int width = 0;
    int height = 0;
    Aov aov = Aov::Final;
    bool lean = false;  // this frame carries LEAN moments (render/SssVariant.h, frameUsesLean); set by the renderer

    void setViewport(int w, int h) const { glViewport(0, 0, w, h); }
    void drawFullscreenTriangle() const;
    void uploadObject(const gpu::ObjectBlock& block) const;
    // Copies `size` bytes to the per-pass block; it must be at most 4 KiB.
    void uploadPassBlock(const void* data, size_t size) const;
    gpu::ObjectBlock objectBlock(size_t characterIndex) const;
};

constexpr size_t kMaxPassBlockBytes = 4096;

}  // namespace dermis
