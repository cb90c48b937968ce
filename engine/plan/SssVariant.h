#pragma once
// Vila Verde 2015's three versions of the screen-space frame (§5.1), as the render
// graph reads them from SssSettings:
//
//   variant  blur edges  specular                               LEAN targets
//   c        control     KS from the unblurred normal (lighting)  none: not declared, not blurred
//   lcb      control     LEAN lobe from the blurred moments      G-buffer, blurred with the irradiance
//   lbb      bilateral   LEAN lobe from the blurred moments      G-buffer, blurred with the irradiance
//
// SssSettings::blur names the edge handling when it is not SssBlur::Variant
// (a benchmark's fetch-only floor, or a mix the thesis did not try).

#include "plan/SssPlan.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace dermis {

// The LEAN moments the SSS chain blurs with the irradiance as extra targets:
// the G-buffer's "lean moments" (RGBA16F). The cross moment rides in the
// irradiance's alpha (the lighting pass copies it from the G-buffer).
constexpr size_t kLeanSssTargets = 1;

// Whether the frame carries LEAN moments (G-buffer targets, their blur, the
// LEAN specular pass): variants lcb and lbb of the screen-space mode.
bool frameUsesLean(const RenderSettings& settings);

// The blur's edge handling: Bilateral, Control or FetchOnly (never Variant).
SssBlur sssBlurEdges(const SssSettings& settings);

// The scalar weight the LEAN moments receive for a Gaussian whose RGB weight
// is `rgb`: the mean of the channels. Why (shaders/include/SssChain.glsl):
// the profile's weights are normalised per channel, so the means also sum to
// one and the accumulated moments stay a convex combination of moments: the
// covariance M - B B^T of a mixture is positive semi-definite. One scalar for
// every moment channel keeps B and M from the same mixture, and the lobe is
// white, so no channel is preferred.
float sssMomentWeight(const glm::vec3& rgb);

// The steps of a slot's d'Eon chain that carry the LEAN moments
// (shaders/include/SssBlur.glsl, WHERE THE MOMENTS STOP): those whose
// Gaussian's width, sqrt of its accumulated variance (widthScale applied), is
// at most `maxWidthMm`, and always the first step that blurs; every step when
// maxWidthMm <= 0. Steps [0, lastStep] carry them; the moments' accumulation
// in lastStep takes `weight`, its own scalar weight plus every later step's,
// so the weights still sum to one.
struct SssMomentCut {
    size_t lastStep = 0;
    float weight = 0.0f;
};
SssMomentCut sssMomentCut(const std::vector<SssGaussianStep>& steps, float maxWidthMm);

}  // namespace dermis
