#pragma once
// Every GLSL program the renderer uses, compiled together. reload() rebuilds
// them all and keeps the old ones when any fails (the viewer's hot reload).

#include "core/Result.h"
#include "gl/ShaderProgram.h"

namespace dermis {

// A program built twice, with the environment light's code (DERMIS_ENVIRONMENT 1,
// include/Environment.glsl) and without it (0) for frames with no environment.
struct EnvironmentPrograms {
    gl::Program lit;
    gl::Program unlit;
    GLuint get(bool environmentLit) const { return (environmentLit ? lit : unlit).get(); }
};

struct Programs {
    gl::Program shadow;
    gl::Program gbuffer;
    EnvironmentPrograms lighting;
    gl::Program composite;
    gl::Program tonemap;
    gl::Program aov;
    gl::Program ssao;           // passes/SsaoPass.cpp
    gl::Program ssaoBlur;
    gl::Program transmittance;  // passes/TransmittancePass.cpp
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
    EnvironmentPrograms tsIrradiance;
    gl::Program tsDilate;
    gl::Program tsBlur;
    gl::Program tsGather;
    gl::Program skinning;      // passes/SkinningPass.cpp (compute)
    gl::Program transferRotate;  // passes/SkinningPass.cpp: the environment transfer turned with the skinning (compute)

    gl::Program gbufferLean;    // LEAN variants: G-buffer with the LEAN moments
    EnvironmentPrograms lightingLean;  // lighting that passes the LEAN cross moment on in the irradiance's alpha
    gl::Program sssInitLean;    // SSS chain with the moments as extra targets
    gl::Program sssBlurLean;
    gl::Program sssDiskLean;
    gl::Program sssBlurLeanLast;  // the last step that carries the moments: writes the colour alone (SssBlur.glsl)
    EnvironmentPrograms leanSpecular;  // passes/LeanSpecularPass.cpp (the specular AOV)
    EnvironmentPrograms compositeLean;  // composite with the LEAN specular
    // Environment light (docs/environment.md): the G-buffers with the
    // per-vertex transfer's target (occlusion "transfer"), and the skybox.
    gl::Program gbufferTransfer;
    gl::Program gbufferLeanTransfer;
    gl::Program skybox;

    static Result<Programs> build();
};

}  // namespace dermis
