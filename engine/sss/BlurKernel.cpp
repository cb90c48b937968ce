#include "sss/BlurKernel.h"

#include "sss/DiffusionProfile.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace dermis {

int writeKernelTaps(const BlurKernel& kernel, glm::vec4 (&taps)[kMaxBlurTaps]) {
    const size_t count = std::min(kernel.weights.size(), size_t(kMaxBlurTaps));
    for (size_t i = 0; i < count; ++i) taps[i] = glm::vec4(kernel.offsetsSigma[i], kernel.weights[i], 0.0f, 0.0f);
    return static_cast<int>(count);
}

Result<BlurKernel> makeGaussianKernel(int taps, float extentSigma) {
    if (taps < kMinBlurTaps || taps > kMaxBlurTaps || taps % 2 == 0)
        return makeError("", "a blur kernel needs an odd tap count in [" + std::to_string(kMinBlurTaps) + ", " +
                                 std::to_string(kMaxBlurTaps) + "], got " + std::to_string(taps));
    if (!std::isfinite(extentSigma) || extentSigma <= 0.0f)
        return makeError("", "the " + std::to_string(taps) + "-tap blur kernel's extent must be finite and > 0 sigma, got " +
                                 std::to_string(extentSigma));

    // Each tap stands for its cell [x - h/2, x + h/2]; the outer cells reach to +-infinity so the
    // whole Gaussian is accounted for (Chappuis 2011 §2.2.4's 7-tap weights are this rule at extent 3).
    const int half = taps / 2;
    const double spacing = double(extentSigma) / half;
    BlurKernel kernel;
    kernel.offsetsSigma.resize(static_cast<size_t>(taps));
    kernel.weights.resize(static_cast<size_t>(taps));
    // The left half and the centre from lower tails (erfc keeps them accurate), mirrored to the
    // right so the kernel is exactly symmetric.
    std::vector<double> weights(static_cast<size_t>(taps));
    for (int i = 0; i <= half; ++i) {
        const double x = (i - half) * spacing;
        const double lower = i == 0 ? 0.0 : standardNormalCdf(x - 0.5 * spacing);
        const double upper = i == half ? 1.0 - standardNormalCdf(x - 0.5 * spacing) : standardNormalCdf(x + 0.5 * spacing);
        weights[static_cast<size_t>(i)] = upper - lower;
        weights[static_cast<size_t>(taps - 1 - i)] = upper - lower;
    }
    double sum = 0.0;
    for (double w : weights) sum += w;
    for (int i = 0; i < taps; ++i) {
        const size_t k = static_cast<size_t>(i);
        kernel.offsetsSigma[k] = static_cast<float>((i - half) * spacing);
        kernel.weights[k] = static_cast<float>(weights[k] / sum);
    }
    return kernel;
}

float kernelVarianceSigma2(const BlurKernel& kernel) {
    double variance = 0.0;
    for (size_t i = 0; i < kernel.weights.size(); ++i)
        variance += double(kernel.weights[i]) * double(kernel.offsetsSigma[i]) * double(kernel.offsetsSigma[i]);
    return static_cast<float>(variance);
}

}  // namespace dermis
