#pragma once
// Every GLSL program the renderer uses, compiled together. reload() rebuilds
// them all and keeps the old ones when any fails (the viewer's hot reload).

#include "core/Result.h"
#include "gl/ShaderProgram.h"
#include "plan/LightSetup.h"

#include <array>

namespace dermis {

// A program built twice, with the environment light's code (DERMIS_ENVIRONMENT 1,
// include/Environment.glsl) and without it (0) for frames with no environment.
struct EnvironmentPrograms {
    gl::Program lit;
    gl::Program unlit;
    GLuint get(bool environmentLit) const { return (environmentLit ? lit : unlit).get(); }
};

// A program that filters shadow maps (include/Shadows.glsl), with and
// without the environment: built up front with every filter's code, and on
// first use with only the filters a frame's ShadowCode needs
// (plan/LightSetup.h), which draws the same image faster on CPU drivers.
struct ShadowedPrograms {
    static_assert(size_t(ShadowCode::HardEdges) == 0 && size_t(ShadowCode::SoftEdges) == 1, "specialized's index");
    EnvironmentPrograms everyFilter;
    // [code][environment lit]; for HardEdges and SoftEdges
    std::array<std::array<gl::LazyProgram, 2>, size_t(ShadowCode::EveryFilter)> specialized;
    GLuint get(bool environmentLit, ShadowCode code) const {
        if (code != ShadowCode::EveryFilter) {
            if (GLuint program = specialized[size_t(code)][environmentLit ? 1 : 0].get()) return program;
        }
        return everyFilter.get(environmentLit);
    }
};

// The lighting pass's programs: with the code of the techniques that scatter
// in it (LIGHTING_SCATTER 1, for frames where some profile slot does) and without.
struct LightingPrograms {
    ShadowedPrograms plain;
    ShadowedPrograms scatter;
    bool specialized = true;  // false: the scatter code in every frame (Programs::build)
    GLuint get(bool environmentLit, ShadowCode code, bool scatters) const {
        return (scatters || !specialized ? scatter : plain).get(environmentLit, code);
    }
};

// A G-buffer program built with the vertex colours (COLOR_0) up front and
// without them (GBUFFER_VERTEX_COLOUR 0, for meshes whose colours are all
// white) on first use. Without them the vertex stage hands the rasterizer one
// varying fewer, which llvmpipe's triangle setup pays per triangle
// (docs/speed.md); the white variant falls back to the other if it fails to build.
struct GBufferPrograms {
    gl::Program withColours;
    gl::LazyProgram white;
    GLuint get(bool vertexColours) const {
        if (!vertexColours) {
            if (GLuint program = white.get()) return program;
        }
        return withColours.get();
    }
};

struct Programs {
    gl::Program shadow;
    GBufferPrograms gbuffer;
    LightingPrograms lighting;
    gl::Program composite;
    gl::Program tonemap;
    gl::Program aov;
    gl::Program ssao;           // passes/SsaoPass.cpp
    gl::Program ssaoBlur;
    gl::Program transmittance;  // passes/TransmittancePass.cpp
    gl::Program backDepth;      // passes/ThinEdgePasses.cpp
    gl::Program thinEdges;
    gl::Program sssInit;        // passes/SssPasses.cpp
    gl::Program sssBlur;
    // passes/SssSeparablePasses.cpp: horizontal (chain) and vertical (accumulation) passes,
    // plain and with the LEAN moments (SSS_EXTRA_TARGETS)
    gl::Program sssSeparableH;
    gl::Program sssSeparableV;
    gl::Program sssSeparableLeanH;
    gl::Program sssSeparableLeanV;
    gl::Program sssDisk;        // passes/SssDiskPass.cpp
    gl::Program tsTsm;         // passes/TextureSpacePasses.cpp
    gl::Program tsStretch;
    ShadowedPrograms tsIrradiance;
    gl::Program tsDilate;
    gl::Program tsBlur;
    gl::Program tsGather;
    gl::Program skinning;      // passes/SkinningPass.cpp (compute)
    gl::Program shadowMax;     // passes/ShadowPass.cpp: a shadow map's max-depth mips (compute)
    gl::Program transferRotate;  // passes/SkinningPass.cpp: the environment transfer turned with the skinning (compute)

    GBufferPrograms gbufferLean;  // LEAN variants: G-buffer with the LEAN moments
    LightingPrograms lightingLean;  // lighting that passes the LEAN cross moment on in the irradiance's alpha
    gl::Program sssInitLean;    // SSS chain with the moments as extra targets
    gl::Program sssBlurLean;
    gl::Program sssDiskLean;
    gl::Program sssBlurLeanLast;  // the last step that carries the moments: writes the colour alone (SssBlur.glsl)
    EnvironmentPrograms leanSpecular;  // passes/LeanSpecularPass.cpp (the specular AOV)
    EnvironmentPrograms compositeLean;  // composite with the LEAN specular
    // Environment light (docs/environment.md): the G-buffers with the
    // per-vertex transfer's target (occlusion "transfer"), and the skybox.
    GBufferPrograms gbufferTransfer;
    GBufferPrograms gbufferLeanTransfer;
    gl::Program skybox;

    // specialize false draws every frame with the programs that hold every
    // shadow filter's and SSS technique's code (tests: the specialized ones
    // must draw the same images).
    static Result<Programs> build(bool specialize = true);
};

}  // namespace dermis
