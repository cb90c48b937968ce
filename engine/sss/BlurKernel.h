#pragma once
// Separable Gaussian blur kernels, computed on the CPU and uploaded (as
// Jimenez's SeparableSSS does). A kernel of N taps (N odd) samples a unit
// Gaussian at offsets spread symmetrically over [-extent, +extent] standard
// deviations; shaders scale the offsets by the Gaussian's width in pixels.
// Weights are the Gaussian integrated over each tap's interval, normalised to
// sum to 1 (so a uniform input stays uniform for every tap count).

#include "core/Limits.h"
#include "core/Result.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

struct BlurKernel {
    std::vector<float> offsetsSigma;  // ascending, symmetric, centre 0
    std::vector<float> weights;       // sum 1
};

// Errors for an even count or one outside [kMinBlurTaps, kMaxBlurTaps].
Result<BlurKernel> makeGaussianKernel(int taps, float extentSigma = 3.0f);

// Writes the kernel into a uniform block's tap array (x: offset in standard
// deviations, y: weight), at most kMaxBlurTaps taps, and returns how many it
// wrote: the one fill of the screen- and texture-space blurs.
int writeKernelTaps(const BlurKernel& kernel, glm::vec4 (&taps)[kMaxBlurTaps]);

// The kernel's variance in units of sigma^2, sum_i w_i x_i^2. It exceeds 1 (about 1 + h^2/12 for
// tap spacing h, Sheppard's correction: 1.08 for Chappuis 2011's 7 taps over +-3 sigma), so a pass
// that must blur by exactly variance v can scale the offsets by sqrt(v / kernelVarianceSigma2).
float kernelVarianceSigma2(const BlurKernel& kernel);

}  // namespace dermis
