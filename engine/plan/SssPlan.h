#pragma once
// What the screen-space SSS chain will do this frame, decided on the CPU
// from the scene alone (no GL), so the render graph can skip work by
// predicate and tests can check the decisions.
//
// Each (profile, width scale) in use (plan/SubmeshScattering.h) gets a slot
// 1..DERMIS_MAX_PROFILES, the stencil value of its submeshes' pixels. For each slot the chain blurs incrementally (Chappuis 2011
// §2.2.4): step i blurs the previous result by variance v_i - v_(i-1)
// (v_(-1) = 0) and adds w_i x result into the accumulation.
// A Gaussian whose standard deviation at the nearest SSS pixel is below
// SssSettings::minWidthPx is skipped: it counts as the identity, its weight
// starts the accumulation, so energy is kept. The chain then still holds the
// unblurred irradiance, so the first step that runs blurs by its whole v_i. At ordinary distances that is
// always Gaussian 0 (0.0064 mm^2, docs/screen-space.md: "the identity"); only extreme
// close-ups, where it spans pixels, blur it. With settings.gaussians < N the
// widest Gaussians are dropped and their weights folded into the widest one
// kept.

#include "mesh/Mesh.h"
#include "scene/QualityTable.h"
#include "scene/Scene.h"
#include "sss/BlurKernel.h"
#include "plan/SubmeshScattering.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

struct SssGaussianStep {
    int gaussian = 0;               // index into the profile's Gaussians
    float stepVarianceMm2 = 0.0f;   // blur of this step: v_i - v_(i-1), scaled by widthScale^2; v_i for the first blurred step
    bool readsIrradiance = false;   // the first step that blurs: its input is the unblurred irradiance
    glm::vec3 weight{0.0f};         // w_i (after folding dropped Gaussians)
    float widthPxAtNearest = 0.0f;  // std dev of Gaussian i in pixels at the nearest SSS pixel
    bool skipped = false;
};

struct SssSlotPlan {
    int slot = 0;  // 1..DERMIS_MAX_PROFILES
    // For pass names: the profile's name, with "#2", "#3" ... on the second
    // and later slots of one profile.
    std::string name;
    const DiffusionProfile* profile = nullptr;
    // How many of the chain's Gaussians are narrower than min_width_px at
    // the nearest pixel of the character that made the slot. Without an
    // error budget, characters at scales that skip different numbers take
    // different slots, so that a far head is not blurred by Gaussians only a
    // near one needs (planSss; docs/crowds.md).
    int narrowGaussians = 0;
    float widthScale = 1.0f;  // settings.sss.widthScale x the material's width_scale
    SssChoice choice;
    BlurKernel gaussianKernel;  // gaussians: the unit kernel of choice.taps taps
    glm::vec3 initWeight{0.0f};  // accumulation = initWeight x irradiance before the first step
    std::vector<SssGaussianStep> steps;  // one per Gaussian used, from the narrowest
    bool visible = false;            // some character with this profile may cover a pixel
    float nearestViewDepthM = 0.0f;  // of its visible characters' bounds, clamped to the near plane
    glm::ivec4 scissor{0};           // x, y, width, height in pixels (GL convention: y up)
    // Disjoint rectangles covering its visible characters' rectangles
    // (plan/ScreenRegions.h): the blurs draw one each.
    std::vector<glm::ivec4> regions;
};

// The slot's pixels scatter in the lighting pass: it is visible and its
// technique scatters there ("preintegrated"). The lighting pass draws them
// with the program that has that code, and only them.
bool scattersInLightingPass(const SssSlotPlan& slot);

// The slot's pixels are blurred by some pass this frame: not when it
// scatters in the lighting pass, nor when its technique is "gaussians" and
// every step is narrower than min_width_px (the chain is then the identity).
// Only a blurring pass reads the thin-edge fill (include/SssChain.glsl).
bool blursOnScreen(const SssSlotPlan& slot);

// How far from 1 a slot's initWeight may be for its chain to count as the
// irradiance itself. Profiles are normalised when made (DiffusionProfile::
// create), so their weights sum to 1 up to float rounding; a weight further
// off would mean "sss init" scales, and it runs.
constexpr float kIdentityInitWeightTolerance = 1e-5f;

// The choice a character's SSS submeshes render with, for reports.
struct CharacterSssChoice {
    bool hasSss = false;      // some submesh has a diffusion profile
    SssChoice choice;         // its first SSS submesh's slot's choice
    float pixelsPerMm = 0.0f;  // at its nearest visible depth; 0 when not visible
    // "settings" (no error budget), "table" (the quality table's row for its
    // scale), "finest" (above the table's largest scale) or "merged" (more
    // distinct choices than slots: it shares a finer slot).
    std::string source = "settings";
};

struct SssPlan {
    std::vector<SssSlotPlan> slots;
    std::vector<CharacterSssChoice> characterChoices;  // per scene character
    std::vector<std::vector<int>> slotsOfCharacter;  // per scene character, per submesh; 0 = opaque (no SSS)
    bool anyVisible() const;
    // Some visible slot's technique scatters in the lighting pass ("preintegrated").
    bool anyScattersInLighting() const;
    // Some slot is visible, and no visible slot's chain differs from the
    // irradiance: each scatters in the lighting pass, or blurs nothing on
    // screen (blursOnScreen) and starts at the whole irradiance (an initWeight
    // of 1 in every channel, within kIdentityInitWeightTolerance). No SSS pass
    // has work then, "sss init" included.
    bool chainIsIdentity() const;
    bool hasSss(size_t character) const;  // some submesh of it has a slot
    int slotOf(size_t character, size_t submesh) const;  // 0 (opaque) for a submesh it does not know
};

// The camera as the planner needs it.
struct ViewParams {
    glm::mat4 viewFromWorld{1.0f};
    glm::mat4 clipFromView{1.0f};
    float nearM = 0.05f;
    int widthPx = 1;
    int heightPx = 1;
    // Pixels per metre at 1 m view depth, vertically: heightPx / (2 tan(fov/2)).
    float pixelsPerMetreAtUnitDepth() const;
};

// characterBounds are world-space bounds, one per scene character;
// submeshMaterials the materials of each character's submeshes
// (a missing or empty entry: one submesh with the character's material).
// With settings.quality.error_budget > 0 each character's choice comes from
// the quality table by its pixels per mm at its nearest visible depth
// (QualityTable.h: the rule); when the distinct choices outgrow the slots, a
// character joins the slot of the same profile with the nearest finer choice
// (or makes the coarsest such slot finer), never a coarser one.
// Errors for an unknown profile name or more (profile, width scale) pairs than slots.
Result<SssPlan> planSss(const Scene& scene, const std::vector<Bounds>& characterBounds, const ViewParams& view,
                        const std::vector<std::vector<SubmeshMaterial>>& submeshMaterials = {});

// Whether a light lies behind the character as the camera sees it: the
// directions from the character's centre to the light and to the camera are
// more than 90 degrees apart. Back-normal transmittance is computed for
// such lights only.
bool isBackLight(const Light& light, const Bounds& characterBounds, const glm::vec3& cameraPositionM);

}  // namespace dermis
