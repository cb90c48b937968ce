#pragma once
// Pre-integrated skin shading (Penner & Borshukov 2011, "Pre-Integrated Skin Shading",
// GPU Pro 2): the diffuse falloff of a lit sphere of radius r = 1 / kappa, pre-integrated
// over a diffusion profile (sss/DiffusionProfile.h), as a function of N.L = cos(theta) and
// the curvature kappa. A shader looks it up with N.L and the surface's curvature instead
// of blurring the irradiance.
//
// The model: a ring of radius r (the great circle through the light) lit by
// cos+(x) = max(cos x, 0), x the angle from the light, blurred along the ring:
//   D(theta, kappa) = sum_i w_i  integral_{-pi}^{pi} cos+(theta + x) g_i(x) dx
// per channel, where g_i is Gaussian i's 1-D marginal, a 1-D Gaussian of variance
// v_i widthScale^2 in ARC LENGTH s = r x along the ring, i.e. of angular standard
// deviation s_i = sqrt(v_i) widthScale kappa, cut at +-pi and normalised on the ring so
// that integral g_i dx = 1 (a white surface stays white).
// Why the marginal and not Penner & Borshukov's cross-section R(2 r sin(x / 2)): on a
// large sphere the irradiance varies only across the terminator, so the light a point
// gathers is the profile integrated ALONG the terminator, i.e. its 1-D marginal, which for
// a sum of Gaussians is sum_i w_i N(0, v_i). The cross-section R(d) = sum_i w_i G(v_i, d),
// renormalised as a 1-D kernel, weights Gaussian i by w_i / sqrt(v_i) instead of w_i:
// it over-weights the narrow Gaussians (by 34x for skin's narrowest against its widest).
// Consequences: kappa = 0 gives exactly max(cos theta, 0); convolution on the circle
// keeps the integral, so integral_0^pi D(theta) dtheta = 1 for every curvature (D is
// even in theta); near the terminator, where the ring is locally flat, Gaussian i gives
// s_i phi(delta / s_i) - delta Phi(-delta / s_i) at theta = pi/2 + delta.
// What the ring leaves out: on a true sphere the surface also curves away ACROSS the great
// circle, so a lit point's neighbours on both tangent axes see less light; to second order the
// sphere is darker on the lit side by max(cos theta, 0) sum_i w_i s_i^2 / 2 (skin's red: 2.8e-2
// at r = 5 mm, 1.7e-3 at 20 mm), and past the terminator it wraps slightly more light round
// (1.5e-3 at 5 mm). tests/unit/test_preintegrated_table.cpp measures both against a quadrature
// over the sphere.
//
// Evaluation (PreintegratedTable.cpp): the kernel of each Gaussian is cut at 8 standard
// deviations (mass 1.2e-15 beyond) and its cumulative integrals against cos x and sin x
// are tabulated on a fixed grid with a cubic-Hermite rule; cos(theta + x) = cos theta
// cos x - sin theta sin x then needs only those cumulants at the ends of the arc where
// it is positive, so the kink at the terminator costs nothing in accuracy and a row of
// the table costs one grid per Gaussian.
//
// The table: x = (N.L + 1) / 2, y = sqrt(kappa / DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM)
// (the square root spends the rows on the small curvatures, where most of a face lies:
// r = 1 mm at y = 1, 4 mm at y = 1/2, 16 mm at y = 1/4), texel centres x_i = (i + 1/2) / cosines,
// y_j = (j + 1/2) / curvatures. Shaders sample it with CLAMP_TO_EDGE and LINEAR at
// uv = (x, y).

#include "include/PreintegratedConstants.glsl"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

constexpr int kPreintegratedCosines = DERMIS_PREINTEGRATED_COSINES;
constexpr int kPreintegratedCurvatures = DERMIS_PREINTEGRATED_CURVATURES;
constexpr double kPreintegratedMaxCurvaturePerMm = DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM;

// D(theta, kappa) per channel, computed directly (not tabulated) in double precision.
// The Gaussians' widths are scaled by widthScale (the profile slot's). A widthScale
// that is not finite and > 0, a curvature that is not finite and > 0, or a NaN cosine
// mean no scattering: max(cosTheta, 0) (0 for a NaN). cosTheta is clamped to [-1, 1].
glm::vec3 preintegratedDiffuse(const DiffusionProfile& profile, float widthScale, float cosTheta, float curvaturePerMm);

struct PreintegratedTable {
    int cosines = kPreintegratedCosines;                                  // x: N.L from -1 to 1, texel centres
    int curvatures = kPreintegratedCurvatures;                            // y: sqrt(kappa / max), texel centres
    float maxCurvaturePerMm = float(kPreintegratedMaxCurvaturePerMm);     // kappa at y = 1
    std::vector<glm::vec3> texels;  // row-major: `curvatures` rows of `cosines` texels

    // Bilinear between texel centres, clamped at the edges: what a GPU sampler with
    // CLAMP_TO_EDGE and LINEAR returns at uv = (x, y) above (without its 8-bit weights).
    // NaN inputs read as 0; a table of the wrong size reads as max(cosTheta, 0).
    glm::vec3 at(float cosTheta, float curvaturePerMm) const;
};

// The table for one profile and width scale, with the default shape (include/PreintegratedConstants.glsl).
// Built at run time, on the calling thread: 3.4 ms for skin (six Gaussians) on one core.
PreintegratedTable makePreintegratedTable(const DiffusionProfile& profile, float widthScale);

}  // namespace dermis
