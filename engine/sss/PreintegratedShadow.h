#pragma once
// Pre-integrated shadows (Penner & Borshukov 2011, "Pre-Integrated Skin Shading", GPU Pro 2,
// "pre-integrated shadows"): the light that scatters across a shadow edge, looked up from how
// much of a small disc around the receiver the shadow map sees lit, instead of blurring the
// shadowed irradiance. The technique "preintegrated" (PreintegratedTable.h) uses it.
//
// The model: a straight shadow edge, lit on the side x > 0 (x in mm, across the edge).
//  - The light's own penumbra is PCSS's (include/Shadows.glsl): a disc of half-width h
//    (mm, at the receiver) sliding over the hard edge, visibility V(x) = A(x / h), where
//      A(d) = 1 - (acos d - d sqrt(1 - d^2)) / pi,  d clamped to [-1, 1],
//    is the lit share of a unit disc whose centre lies d from the edge (h = 0: a step).
//  - Skin scatters V with the profile: across a straight edge the 2-D profile acts
//    through its 1-D marginal, sum_i w_i N(0, sigma_i^2) (PreintegratedTable.h says why), so
//      S(x) = sum_i w_i integral g_sigma_i(x - t) V(t) dt           (per channel)
//    which for h = 0 is sum_i w_i Phi(x / sigma_i).
//  - The shader does not know x. It measures the coverage c = A(x / R) of a wider disc
//    in the receiver's tangent plane, of radius R = k sigma sqrt(1 + q^2)
//    (k = DERMIS_PREINTEGRATED_SHADOW_STDDEVS = 2, q = h / (2 sigma)), against the hard map,
//    and the table turns c back into x = R A^-1(c), then into S(x) (rgb) and V(x) (alpha:
//    the unscattered visibility, for the specular). sigma is the widest standard deviation
//    among the Gaussians that carry at least 10% of some channel (skin: 1.41 mm; its widest,
//    2.72 mm, carries 7.8% of red). R spans k such standard deviations and k of the light's
//    penumbra (a disc of half-width h has standard deviation h / 2). The light that scatters
//    past the disc, about 2% of red's lit level for skin, is cut: coverage 0 and 1 (the disc
//    wholly in shadow or lit) read exactly 0 and 1, since far more pixels lie far from an
//    edge than just past the disc. Why not a wider disc: the disc lies in the tangent plane,
//    and on a face the plane leaves the surface within a few mm (include/Shadows.glsl,
//    surfaceDiscPcf); with k = 3 and skin's widest Gaussian (R = 8.2 mm) the default head's
//    total error was 4.44% against 3.95% with this disc (docs/results/techniques.md).
//  - In the scaled variables x / sigma, h / sigma and sigma_i / sigma the table depends
//    on the profile only through sigma_i / sigma and w_i: the width scale cancels.
//
// The table: x = c at texel centres c_i = i / (columns - 1), so that c = 0 and c = 1 lie on
// texel centres (sampled at u = (c (columns - 1) + 1/2) / columns); y = q / (1 + q) at
// texel centres (j + 1/2) / rows, so q from 1/31 to 31 at 16 rows. What the model leaves out:
// an edge that is not straight over the disc (a corner, a thin shadow), and the disc's
// DERMIS_PCSS_FILTER_SAMPLES taps, which quantise c in steps of 1/64.

#include "include/PreintegratedConstants.glsl"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

constexpr int kPreintegratedShadowCoverages = DERMIS_PREINTEGRATED_COSINES;
constexpr int kPreintegratedShadowRows = DERMIS_PREINTEGRATED_SHADOW_ROWS;
constexpr double kPreintegratedShadowStdDevs = DERMIS_PREINTEGRATED_SHADOW_STDDEVS;

// sigma above times widthScale (mm); 0 for an empty profile.
double preintegratedShadowSigmaMm(const DiffusionProfile& profile, float widthScale);

// S (rgb) and V (alpha) for a disc coverage c in [0, 1] and q = h / (2 sigma) >= 0, computed
// directly in double precision. c <= 0 gives 0, c >= 1 gives 1; NaN reads as 0.
glm::vec4 preintegratedShadow(const DiffusionProfile& profile, float coverage, float penumbraRatio);

struct PreintegratedShadowTable {
    int coverages = kPreintegratedShadowCoverages;
    int rows = kPreintegratedShadowRows;
    std::vector<glm::vec4> texels;  // row-major: `rows` rows of `coverages` texels

    // Bilinear between texel centres, clamped: what the shader's lookup returns.
    glm::vec4 at(float coverage, float penumbraRatio) const;
};

// About 12 ms for skin's six Gaussians on one core (built once per profile).
PreintegratedShadowTable makePreintegratedShadowTable(const DiffusionProfile& profile);

}  // namespace dermis
