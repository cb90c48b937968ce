#pragma once
// Plan, then declare. From the scene, the CPU side of its meshes and the
// frame request, planFrame decides everything the frame's passes need, on the
// CPU and without GL:
//
//   - the view (one ViewParams for every planner),
//   - where each character is (world transform and bounds) and whether it
//     is visible: only visible characters are drawn in the G-buffer and
//     texture space,
//   - the lights' block and shadow layout: which light owns which shadow
//     slot, each map fitted to the visible characters and holding only the
//     casters that can shade them (plan/ShadowCasters.h), which slots'
//     cached maps are still current (their passes are skipped) and which
//     lights are back lights (Jimenez et al. 2010: only those transmit light
//     through thin regions),
//   - the screen-space SSS plan (plan/SssPlan.h) and, when the frame uses
//     texture space, the texture-space plan per character (plan/TsPlan.h),
//   - the blur kernels, whether the frame carries LEAN moments, and so which
//     resources the prepare step (render/FrameResources.h) must make.
//
// Errors come back as the status; nothing is logged and dropped. The frame is
// then prepared (GL work: textures, uploads) and declared
// (frame/FrameDeclaration.h), which only reads the plan.

#include "core/Result.h"
#include "graph/RenderGraph.h"
#include "graph/TextureDesc.h"
#include "plan/Aov.h"
#include "plan/LightSetup.h"
#include "plan/SceneGeometry.h"
#include "plan/ShadowCache.h"
#include "plan/ShadowCasters.h"
#include "plan/SssPlan.h"
#include "plan/TsPlan.h"
#include "anim/Rig.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"
#include "sss/BlurKernel.h"

#include "plan/EnvironmentPlan.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

struct FrameRequest {
    int width = 640;
    int height = 360;
    Aov aov = Aov::Final;
    // Added to the mip level of material maps (albedo, normal, LEAN); tests
    // force level 0 with a large negative bias for supersampled references.
    float materialMipBias = 0.0f;
    // The transmittance skips the rings of a point whose back surfaces all lie
    // this many sigmas beyond its profile's reach (include/Transmittance.glsl);
    // tests set 0 to compare with the full integral everywhere.
    float transmittanceSkipSigmas = DERMIS_TRANSMITTANCE_SKIP_SIGMAS;
    // The frame's time, seconds: each animated character's clip time is
    // animation.time_s + animation.speed x timeS (scene/Scene.h).
    float timeS = 0.0f;
    // Every character counts as visible: the irradiance capture renders
    // characters off screen too (Renderer::captureIrradianceTextures).
    bool everyCharacterVisible = false;
    // Each character's level of detail last frame (FramePlan::characters[c].lod),
    // for the hysteresis (plan/LevelOfDetail.h); empty: none.
    std::vector<int> previousLods{};
};

// Largest frame a request may ask for (GL_MAX_TEXTURE_SIZE may be smaller).
constexpr int kMaxFrameDimension = 16384;

// Where a character is this frame.
struct CharacterPlacement {
    glm::mat4 worldFromObject{1.0f};
    Bounds worldBounds;
    // An animated character (anim/Rig.h): this frame's pose, the pass that
    // skins it into its vertex buffer, and whether that buffer already holds
    // this pose (plan/PoseCache.h; then the pass is skipped).
    bool animated = false;
    float clipTimeS = 0.0f;
    RigPose pose;
    std::string skinPassName;
    bool poseCurrent = false;
    // Its bounds may cover a pixel (plan/ScreenFootprint.h); else why not.
    bool visible = true;
    std::string culledBecause;
    float footprintPixels = 0.0f;  // its bounds' area on screen, unclipped (INFINITY across the near plane)
    // The level of detail it draws (plan/LevelOfDetail.h; 0: the full mesh)
    // and that level's error projected on screen, pixels.
    int lod = 0;
    float lodErrorPx = 0.0f;

    // Its world size per object unit (the transform's scale is uniform).
    float metresPerUnit() const { return glm::length(glm::vec3(worldFromObject[0])); }
};

// One shadow-casting light's map this frame.
struct ShadowSlotPlan {
    int light = 0;             // index into the frame's lights (LightSetup::sources)
    std::string passName;      // "shadow:light<i>(dir)", "(spot)" or "(point)"
    graph::TextureDesc desc;   // the map: R32F linear light depth, metres
    ShadowCasters casters;     // the characters drawn into it, and why the others are not
    std::vector<float> key;    // what it is rendered from (ShadowCache::makeKey)
    bool current = false;      // the cached map was rendered from the same: its pass is skipped
    // Whether the casters draw their levels of detail (CharacterPlacement::lod)
    // or their full meshes. Full meshes unless some kept caster is animated:
    // a map of static casters is cached, so a level would save no time per
    // frame, while it would shade the receivers with the level's shadow and
    // draw the map again each time a caster's level changed.
    bool castersDrawLevels = false;
};

struct FramePlan {
    const Scene* scene = nullptr;
    int width = 0;
    int height = 0;
    Aov aov = Aov::Final;
    float materialMipBias = 0.0f;
    float transmittanceSkipSigmas = DERMIS_TRANSMITTANCE_SKIP_SIGMAS;
    ViewParams view;
    bool lean = false;  // the frame carries LEAN moments (plan/SssVariant.h, frameUsesLean)
    std::vector<CharacterPlacement> characters;  // one per scene character
    Bounds worldBounds;                          // of all characters; a unit box at the origin when there are none
    LightSetup lights;                           // the scene's and the environment's; shadowDepth.w marks the back lights
    std::vector<ShadowSlotPlan> shadows;         // one per LightSetup::shadowedLights entry
    bool anyBackLight = false;                   // some shadowed light is behind a visible SSS character
    SssPlan sss;
    BlurKernel sssKernel;
    bool textureSpace = false;  // the frame declares texture-space passes (then ts and tsKernel are planned)
    TsPlan ts;
    BlurKernel tsKernel;
    EnvironmentPlan environment;
};

// Whether the frame's AOV reads the SSS chain (screen- or texture-space): the
// final image, the diffuse AOV, and the specular AOV of the LEAN variants,
// whose specular comes after the chain that blurs the moments.
bool aovReadsSss(Aov aov, bool lean);

// `geometry` has one entry per scene character (its UV layouts are analysed
// on first need); `shadows` is what the cached maps were rendered from.
// Errors: a frame size outside 1 .. kMaxFrameDimension, an unknown profile,
// more profiles than slots, a blur kernel the settings cannot make.
Result<FramePlan> planFrame(const Scene& scene, SceneGeometry& geometry, const FrameRequest& request,
                            const ShadowCache& shadows);

// After the frame's graph ran: the shadow slots whose pass executed now hold
// their plan's map.
void recordShadowMaps(const FramePlan& plan, const graph::RenderGraph& graph, ShadowCache& shadows);

// Whether the frame's texture-space passes draw character `character` (its
// plan runs: visible, and not fallen back to screen space).
bool textureSpaceDraws(const FramePlan& plan, size_t character);

// The output texture's description for a plan: RGBA8 for Aov::Final, RGBA32F otherwise.
graph::TextureDesc frameOutputDesc(const FramePlan& plan);

}  // namespace dermis
