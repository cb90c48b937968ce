#pragma once
// The disk kernel of the screen-space disk technique (shaders/include/DiskSss.glsl,
// passes/SssDiskPass.cpp): N sample offsets in the tangent plane of a pixel and their
// RGB weights, computed on the CPU per profile slot, in the manner of Christensen &
// Burley 2015 §5 and Unity HDRP (Golubev 2018).
//
// Radii: the radial CDF F_c(r) (the fraction of the exitant light within r; closed
// form for Burley's normalized diffusion, sum_i w_i (1 - exp(-r^2 / 2 v_i)) for a
// sum of Gaussians) of the importance distribution, the mean of the three channels'
// F_m = (F_r + F_g + F_b) / 3, inverted numerically at stratified u_k = (k + 1/2) / N:
// r_k = F_m^-1(u_k). The mixture rather than one channel, because then every channel's
// ratio to it, f_c / f_m <= 3 (f = dF/dr), stays bounded: no channel's weight can pile
// onto the few samples near the centre, as it would for the narrow blue channel under
// red's (widest) distribution.
// Angles: the golden-angle spiral theta_k = k x 2.39996 rad (the shader rotates it per
// pixel).
// Weights: R_c(r_k) / pdf(r_k) with pdf the plane density f_m(r) / (2 pi r), i.e.
// f_c(r_k) / f_m(r_k), normalised per channel to sum to 1 (a white furnace stays white).
// A Burley profile (DiffusionProfile::burley()) is sampled exactly; any other by its
// Gaussians.

#include "core/Limits.h"
#include "core/Result.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <array>

namespace dermis {

constexpr double kGoldenAngleRad = 2.39996322972865332;  // pi (3 - sqrt 5)

struct DiskSample {
    float radiusMm = 0.0f;
    float angleRad = 0.0f;
    glm::vec3 weight{0.0f};
};

struct DiskKernel {
    std::array<DiskSample, kMaxDiskSamples> samples{};  // the first `count`, ascending radii
    int count = 0;
};

// The radial CDF F_c(r) and its density f_c(r) = dF_c/dr (1/mm) per channel: Burley's
// closed forms (sss/BurleyProfile.h) when the profile keeps its Burley parameters, the
// Gaussians' otherwise.
glm::dvec3 profileRadialCdf(const DiffusionProfile& profile, double radiusMm);
glm::dvec3 profileRadialDensity(const DiffusionProfile& profile, double radiusMm);

// The radius (mm) within which the importance distribution F_m holds `fraction` of the light.
double diskImportanceRadiusMm(const DiffusionProfile& profile, double fraction);

// Errors for a sample count outside [kMinDiskSamples, kMaxDiskSamples] or a width scale that
// is not finite and > 0. Radii are scaled by widthScale (the slot's).
Result<DiskKernel> makeDiskKernel(const DiffusionProfile& profile, int samples, float widthScale = 1.0f);

}  // namespace dermis
