#pragma once
// The single pre-integrated 1-D kernel of Separable Subsurface Scattering
// (Jimenez et al. 2015), computed on the CPU from any diffusion profile (as the
// authors' SeparableSSS code does) for one horizontal and one vertical pass.
//
// The 1-D kernel is the marginal of the 2-D radial profile R (its line
// integral across the blur direction), K(x) = integral R(sqrt(x^2 + y^2)) dy.
// For R = sum_i w_i G(v_i, r) that is K(x) = sum_i w_i g(v_i, x), g the 1-D
// Gaussian of the same variance. Two passes give K(x) K(y): exactly R for one
// Gaussian, a rank-1 approximation of R for a sum (Jimenez et al. 2015);
// docs/screen-space.md, "Separable kernel", has its measured error for skin.
//
// Taps (ascending offsets, symmetric about 0, centre tap in the middle) are
// placed by the power law of the authors' SeparableSSS code, x_k = range
// sign(t_k) |t_k|^2 with t_k uniform in [-1, 1], which packs them near 0 where
// K is large; not by inverting the marginal's CDF, because the three channels,
// whose marginals differ in width, share one set of offsets. Each tap's RGB
// weight is K integrated exactly over its cell (midpoint to midpoint; the
// outer cells reach to +-infinity so no energy is lost), normalised per
// channel to sum to 1. (The authors' code weights a tap by the profile at the
// tap times its interval instead.)

#include "core/Limits.h"
#include "core/Result.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <array>

namespace dermis {

// The default range in standard deviations of the profile's widest Gaussian.
constexpr float kSeparableRangeStdDevs = 3.0f;
// The power law's exponent (EXPONENT in the authors' SeparableSSS code).
constexpr float kSeparableOffsetExponent = 2.0f;

struct SeparableTap {
    float offsetMm = 0.0f;
    glm::vec3 weight{0.0f};
};

struct SeparableKernel {
    std::array<SeparableTap, kMaxSeparableSamples> taps{};  // the first `count` are used, ascending offsets
    int count = 0;
    float rangeMm = 0.0f;  // the outermost taps sit at +-rangeMm
};

// kSeparableRangeStdDevs times the profile's largest standard deviation (8.17 mm for skin).
float separableRangeMm(const DiffusionProfile& profile);

// Errors for an even sample count or one outside [kMinSeparableSamples, kMaxSeparableSamples],
// and for a range that is not finite and > 0.
Result<SeparableKernel> makeSeparableKernel(const DiffusionProfile& profile, int samples, float rangeMm);
// The same with rangeMm = separableRangeMm(profile).
Result<SeparableKernel> makeSeparableKernel(const DiffusionProfile& profile, int samples);

// K(x) per channel, 1/mm: the 1-D marginal the kernel integrates.
glm::vec3 separableMarginal(const DiffusionProfile& profile, float xMm);

}  // namespace dermis
