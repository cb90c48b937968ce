#include "sss/SeparableKernel.h"

#include <cmath>
#include <string>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Sum_i w_i Phi(x / sqrt v_i): the integral of K from -infinity to x (erfc keeps the left tail
// accurate, so the left half and the centre are taken from it and mirrored).
glm::dvec3 marginalCdf(const DiffusionProfile& profile, double xMm) {
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : profile.gaussians())
        sum += glm::dvec3(g.weight) * (0.5 * std::erfc(-xMm / std::sqrt(2.0 * double(g.varianceMm2))));
    return sum;
}

}  // namespace

float separableRangeMm(const DiffusionProfile& profile) { return kSeparableRangeStdDevs * profile.largestStdDevMm(); }

glm::vec3 separableMarginal(const DiffusionProfile& profile, float xMm) {
    const double x2 = double(xMm) * double(xMm);
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double v = g.varianceMm2;
        sum += glm::dvec3(g.weight) * (std::exp(-x2 / (2.0 * v)) / std::sqrt(2.0 * kPi * v));
    }
    return glm::vec3(sum);
}

Result<SeparableKernel> makeSeparableKernel(const DiffusionProfile& profile, int samples) {
    return makeSeparableKernel(profile, samples, separableRangeMm(profile));
}

Result<SeparableKernel> makeSeparableKernel(const DiffusionProfile& profile, int samples, float rangeMm) {
    if (samples < kMinSeparableSamples || samples > kMaxSeparableSamples || samples % 2 == 0)
        return makeError("", "a separable SSS kernel needs an odd sample count in [" + std::to_string(kMinSeparableSamples) +
                                 ", " + std::to_string(kMaxSeparableSamples) + "], got " + std::to_string(samples));
    if (!std::isfinite(rangeMm) || rangeMm <= 0.0f)
        return makeError("", "the " + std::to_string(samples) + "-sample separable SSS kernel's range must be finite and > 0 mm, got " +
                                 std::to_string(rangeMm));

    const int half = samples / 2;
    double offsets[kMaxSeparableSamples];
    for (int i = 0; i <= half; ++i) {
        const double t = double(half - i) / half;  // |t| of the left-half tap i
        offsets[i] = -double(rangeMm) * std::pow(t, double(kSeparableOffsetExponent));
        offsets[samples - 1 - i] = -offsets[i];
    }
    offsets[half] = 0.0;

    // Left half and centre from lower-tail CDF differences, mirrored to the right so the kernel is
    // exactly symmetric; the centre cell is 1 - 2 * (mass left of its lower edge).
    glm::dvec3 weights[kMaxSeparableSamples];
    glm::dvec3 below(0.0);
    for (int i = 0; i < half; ++i) {
        const glm::dvec3 upper = marginalCdf(profile, 0.5 * (offsets[i] + offsets[i + 1]));
        weights[i] = upper - below;
        weights[samples - 1 - i] = weights[i];
        below = upper;
    }
    weights[half] = glm::dvec3(1.0) - 2.0 * below;

    glm::dvec3 sum(0.0);
    for (int i = 0; i < samples; ++i) sum += weights[i];
    SeparableKernel kernel;
    kernel.count = samples;
    kernel.rangeMm = rangeMm;
    for (int i = 0; i < samples; ++i) {
        kernel.taps[size_t(i)].offsetMm = static_cast<float>(offsets[i]);
        kernel.taps[size_t(i)].weight = glm::vec3(weights[i] / sum);
    }
    return kernel;
}

}  // namespace dermis
