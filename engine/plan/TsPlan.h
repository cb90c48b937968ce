#pragma once
// What the texture-space SSS mode will do this frame, per character, decided
// on the CPU from the scene, the view and each mesh's UV layout (no GL), so
// the render graph skips work by predicate and tests can check the decisions.
//
// Per SSS surface (Chappuis 2011 §2.2.2): the submeshes of one character
// that share a (profile, width scale) (plan/SubmeshScattering.h), with
// their own irradiance texture, blurs and gather; a character with one
// profile has one surface, its opaque submeshes none.
//  - visible: its bounds may cover a pixel (plan/ScreenFootprint.h). An
//    invisible character's texture-space passes are all skipped.
//  - size: the irradiance texture's side, a power of two within
//    [ts.min_size, ts.max_size]: the one nearest to one texel per screen
//    pixel at the character's nearest point, but no larger than the one
//    nearest to kTexelsPerCoveredPixel covered texels per pixel of its screen
//    rectangle, unclipped (texels x UV coverage = the texels that hold
//    surface; a character partly off screen is sized for all of it). The
//    first alone follows the UV layout: an atlas whose charts fill a tenth of
//    the square asks for ten times the texels its surface needs, and a
//    character seen small but with a near point close to the camera asks
//    for a texture far larger than its pixels. The second makes the cost
//    follow the screen coverage (docs/texture-space.md, "Texture size").
//  - Gaussians: step i blurs texture i-1 by v_i - v_(i-1) into texture i
//    (texture -1 is the irradiance texture, v_(-1) = 0). A step whose
//    Gaussian is narrower than half a texel where the layout is densest is
//    skipped: its texture is the previous one. At ordinary sizes that is
//    always Gaussian 0 (0.0064 mm^2 for skin), which Chappuis 2011 §2.2.4 takes
//    as the irradiance itself, so a six-Gaussian profile takes five blurs;
//    only close-ups where it spans texels blur it. sss.gaussians and
//    sss.width_scale mean what they mean in screen space (plan/SssPlan.h):
//    the widest Gaussians are dropped with their weights folded into the
//    widest kept; widths are scaled.
//  - TSM: the shadow-casting light behind the character (as the camera sees
//    it) whose modified translucent shadow map carries light through thin
//    regions (Chappuis 2011 §2.5), with a projection fitted to the character.
//    Chappuis 2011 applies it for one light; so does this (the irradiance
//    texture's alpha holds one thickness). It needs ts.tsm and
//    transmittance.enabled, which means "light through thin regions" in
//    both modes.
//  - fall-back: a character whose UV layout cannot hold its light (more than
//    kMaxUvlessSurfaceFraction of its surface on triangles with no UV area,
//    as a mesh without TEXCOORD_0 has everywhere, or more than
//    kMaxUvOverlapFraction of its covered texels covered twice, as mirrored
//    or stacked charts are) is not run in texture
//    space: its passes are skipped with the reason, and the frame blurs it
//    with the screen-space chain instead (frame/FrameDeclaration.cpp), which
//    the texture-space accumulation then starts from. The renderer warns once
//    per character (frame/Renderer.cpp).

#include "core/Result.h"
#include "plan/LightSetup.h"
#include "plan/SssPlan.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

// What the planner needs of one character besides the scene.
struct TsCharacterInput {
    Bounds worldBounds;
    float mmPerUv = 0.0f;       // typical world length of one UV unit, mm (UvLayout::medianStretch, scaled)
    float denseMmPerUv = 0.0f;  // the same where the layout is densest (UvLayout::denseStretch, scaled)
    float uvlessSurfaceFraction = 0.0f;  // UvLayout::uvlessSurfaceFraction
    float uvOverlapFraction = 0.0f;      // UvLayout::uvOverlapFraction
    float uvCoverageFraction = 1.0f;     // UvLayout::uvCoverageFraction
    std::vector<SubmeshMaterial> submeshMaterials;  // per submesh; empty: one submesh, the character's material
};

// Texels holding surface per pixel of the character's screen rectangle. The
// texture holds the whole surface and the screen about half of it (the side
// facing the camera), so this is about two texels per visible pixel. 4 keeps
// well-packed layouts at the size texel density gives: the procedural head
// (84.7% UV coverage) at 640x360 asks for a side of 804 by density and 791 by
// coverage, the scan (91.6%) 711 and 732: the same powers of two as before.
constexpr float kTexelsPerCoveredPixel = 4.0f;

struct TsStep {
    int gaussian = 0;              // index into the profile's Gaussians
    float stepVarianceMm2 = 0.0f;  // blur of this step: (v_i - v_(i-1)) x width_scale^2
    float widthTexels = 0.0f;      // std dev of Gaussian i in texels where the layout is densest
    bool skipped = false;
};

struct TsCharacterPlan {
    int character = 0;   // index into Scene::characters
    std::string label;   // names its passes: "ts <label> ..."; the character's name, made unique, and
                         // the profile's when the character has several surfaces
    const DiffusionProfile* profile = nullptr;
    float widthScale = 1.0f;            // settings.sss.widthScale x the material's width_scale
    std::vector<size_t> submeshes;      // the character's submeshes this surface draws
    bool visible = false;  // on screen, with SSS enabled
    bool sssDisabled = false;  // settings.sss.enabled false: no pass runs, whatever the screen shows
    // Why it falls back to screen space; empty when texture space can run it.
    std::string fallback;
    bool runs() const { return visible && fallback.empty(); }
    // Why its passes are skipped ("" when they run).
    std::string skipReason() const;
    float nearestViewDepthM = 0.0f;
    int size = 0;        // irradiance texture side, texels (a power of two)
    // One per Gaussian used: rgb the weight (after folding), a the variance
    // (mm^2, width-scaled). Index i is blurred texture i.
    std::vector<glm::vec4> gaussians;
    std::vector<TsStep> steps;  // one per Gaussian used, from the narrowest
    int tsmLight = -1;          // index into Scene::lights; -1: no translucent shadow map
    int tsmSize = 0;            // its side, texels
    glm::mat4 tsmClipFromWorld{1.0f};
    glm::vec3 tsmOriginM{0.0f};  // depth in the TSM is measured from here...
    glm::vec3 tsmAxis{0.0f, 0.0f, -1.0f};
    bool tsmAlongAxis = true;    // ...along tsmAxis (directional lights) or as the distance (spot lights)
};

struct TsPlan {
    std::vector<TsCharacterPlan> characters;  // the SSS surfaces, in scene order
    bool anyRuns() const;              // a character is run in texture space
    bool anyVisibleFallback() const;   // a visible character falls back to screen space
};

// Smallest TSM side; the largest is min(irradiance size, kMaxTsmSize).
constexpr int kMinTsmSize = 256;
constexpr int kMaxTsmSize = 1024;
// A character with more of its surface than this on triangles without UV
// area falls back to screen space: those triangles get no texels, so the
// irradiance texture has no light for them (a sphere without TEXCOORD_0 in
// texture space had 26,413 of its 28,828 pixels under a quarter of the
// screen-space value). 1% leaves room for a few collapsed slivers in a real
// layout, which cost a few pixels of local (unscattered) light.
constexpr float kMaxUvlessSurfaceFraction = 0.01f;
// A character with more of its covered texels than this covered by two or
// more triangles falls back to screen space: each such texel holds the light
// of only one of them, so the others gather another place's light (a soldier
// whose body had 84.8% of its texels overlapped rendered 459 pixels far
// darker and 271 far brighter than screen space). The LeePerrySmith scan has
// 0.02%, the procedural head and sphere 0.
constexpr float kMaxUvOverlapFraction = 0.02f;
// A Gaussian step narrower than this (std dev, texels) is not blurred.
constexpr float kMinStepTexels = 0.5f;

// The power of two nearest (in log2) to `texels`, within [minSize, maxSize].
int tsTextureSize(float texels, int minSize, int maxSize);

// inputs has one entry per scene character. Errors for an unknown profile.
Result<TsPlan> planTextureSpace(const Scene& scene, const std::vector<TsCharacterInput>& inputs, const ViewParams& view,
                                const LightSetup& lights);

}  // namespace dermis
