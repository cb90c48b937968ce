#pragma once
// What a pass sees: the frame's plan while it is declared, and the GL objects
// its execute step draws with. Declaring reads only `plan` (no GL), so the
// frame can be declared and compiled on the test backend with `gl` null.
// Passes copy the context (two pointers) into their execute steps: the plan
// and the services must outlive the graph's execution.

#include "gl/FramebufferCache.h"
#include "gl/GlObjects.h"
#include "plan/FramePlan.h"
#include "render/GpuEnvironment.h"
#include "render/GpuScene.h"
#include "render/Programs.h"
#include "render/TsMeshes.h"
#include "gpu/UniformBlocks.h"

namespace dermis {

// Texture units every fullscreen pass agrees on for shared tables.
constexpr GLuint kBeckmannUnit = DERMIS_UNIT_BECKMANN;
constexpr GLuint kEnergyUnit = DERMIS_UNIT_ENERGY;

// The largest per-pass block: DiskSssBlock at 128 samples (4128 bytes); GL guarantees 16 KiB.
constexpr size_t kMaxPassBlockBytes = 8192;

// The GL objects passes execute with, owned by the renderer
// (render/FrameResources.h) and made before the frame is declared.
struct FrameServices {
    const GpuScene* gpuScene = nullptr;
    const Programs* programs = nullptr;
    gl::FramebufferCache* framebuffers = nullptr;
    const TsMeshes* tsMeshes = nullptr;  // the texture-space meshes of the characters in FramePlan::ts
    const GpuEnvironment* environment = nullptr;  // the environment's map, block and transfer buffers
    GLuint objectUniforms = 0;  // ObjectBlock, rewritten per draw
    GLuint passUniforms = 0;    // the per-pass block at DERMIS_BINDING_PASS, rewritten per pass
    GLuint regionUniforms = 0;  // ScreenRegionsBlock, rewritten by drawRegions
    GLuint emptyVertexArray = 0;
    GLuint whiteTexture = 0;    // 1x1 RGBA8 white: a neutral input (AO = 1)
    GLuint blackTexture = 0;    // 1x1 RGBA8 black: nothing (no transmitted light)
    GLuint lightingTables = 0;  // render/LightingScatter.h: 0 unless a visible slot scatters in the lighting pass

    void setViewport(int w, int h) const { glViewport(0, 0, w, h); }
    void drawFullscreenTriangle() const;
    // One draw covering these disjoint pixel rectangles (at most
    // DERMIS_MAX_SCREEN_REGIONS; plan/ScreenRegions.h), or the fullscreen
    // triangle when there are none. The program's vertex stage must be
    // shaders/fullscreen.vert.
    void drawRegions(const std::vector<glm::ivec4>& regions) const;
    void uploadObject(const gpu::ObjectBlock& block) const;
    // Runs the bound compute program over `groups` work groups, then a memory
    // barrier of `barriers` for the passes that read what it wrote.
    void dispatchCompute(GLuint groups, GLbitfield barriers) const;
    // Copies `size` bytes to the per-pass block; it must be at most kMaxPassBlockBytes.
    void uploadPassBlock(const void* data, size_t size) const;
};

struct FrameContext {
    const FramePlan& plan;
    const FrameServices* gl = nullptr;  // null where the graph is only compiled, never executed

    // The character's ObjectBlock without a material: transforms and object id.
    gpu::ObjectBlock objectBlock(size_t characterIndex) const;
    // The ObjectBlock of one submesh: its material and profile slot too
    // (execute steps only).
    gpu::ObjectBlock objectBlock(size_t characterIndex, size_t submeshIndex) const;
};

// Binds a material's maps at units 0 (albedo), 1 (normal), DERMIS_UNIT_ROUGHNESS
// and DERMIS_UNIT_SPECULAR (include/Material.glsl).
void bindMaterialMaps(const GpuMaterial& material);

}  // namespace dermis
