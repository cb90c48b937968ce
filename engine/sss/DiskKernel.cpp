#include "sss/DiskKernel.h"

#include "sss/BurleyProfile.h"

#include <cmath>
#include <string>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Bisection on log r: 200 halvings of a bracket at most 1e30 wide reach double precision.
constexpr int kBisectionSteps = 200;

double meanCdf(const DiffusionProfile& profile, double radiusMm) {
    const glm::dvec3 f = profileRadialCdf(profile, radiusMm);
    return (f.x + f.y + f.z) / 3.0;
}

}  // namespace

glm::dvec3 profileRadialCdf(const DiffusionProfile& profile, double radiusMm) {
    if (profile.burley()) return burleyRadialCdf(*profile.burley(), radiusMm);
    return gaussianRadialCdf(profile, radiusMm);
}

glm::dvec3 profileRadialDensity(const DiffusionProfile& profile, double radiusMm) {
    const double r = std::fmax(radiusMm, 0.0);
    if (profile.burley()) {
        // 2 pi r R(r) = (e^(-r/d) + e^(-r/(3d))) / (4d), finite at r = 0.
        const glm::dvec3 d = burleyShapeDistanceMm(*profile.burley());
        glm::dvec3 f;
        for (int c = 0; c < 3; ++c) f[c] = (std::exp(-r / d[c]) + std::exp(-r / (3.0 * d[c]))) / (4.0 * d[c]);
        return f;
    }
    glm::dvec3 f(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double v = double(g.varianceMm2);
        f += glm::dvec3(g.weight) * (r / v * std::exp(-r * r / (2.0 * v)));
    }
    return f;
}

double diskImportanceRadiusMm(const DiffusionProfile& profile, double fraction) {
    double low = 1e-12, high = 1.0;
    while (meanCdf(profile, high) < fraction && high < 1e18) high *= 2.0;
    for (int i = 0; i < kBisectionSteps && high / low > 1.0 + 1e-15; ++i) {
        const double middle = std::sqrt(low * high);
        (meanCdf(profile, middle) < fraction ? low : high) = middle;
    }
    return std::sqrt(low * high);
}

Result<DiskKernel> makeDiskKernel(const DiffusionProfile& profile, int samples, float widthScale) {
    if (samples < kMinDiskSamples || samples > kMaxDiskSamples)
        return makeError("", "disk kernel: " + std::to_string(samples) + " samples; the disk takes " +
                                 std::to_string(kMinDiskSamples) + " to " + std::to_string(kMaxDiskSamples));
    if (!(widthScale > 0.0f) || !std::isfinite(widthScale))
        return makeError("", "disk kernel: width scale " + std::to_string(widthScale) + "; it must be finite and > 0");
    DiskKernel kernel;
    kernel.count = samples;
    std::array<glm::dvec3, kMaxDiskSamples> weights{};
    glm::dvec3 sums(0.0);
    for (int k = 0; k < samples; ++k) {
        const double u = (k + 0.5) / samples;
        const double r = diskImportanceRadiusMm(profile, u);
        const glm::dvec3 f = profileRadialDensity(profile, r);
        const double importance = (f.x + f.y + f.z) / 3.0;
        const glm::dvec3 weight = f / importance;  // R_c / pdf = f_c / f_m, both over 2 pi r
        DiskSample& sample = kernel.samples[size_t(k)];
        sample.radiusMm = float(r * double(widthScale));
        sample.angleRad = float(std::fmod(k * kGoldenAngleRad, 2.0 * kPi));
        weights[size_t(k)] = weight;
        sums += weight;
    }
    for (int k = 0; k < samples; ++k) kernel.samples[size_t(k)].weight = glm::vec3(weights[size_t(k)] / sums);
    return kernel;
}

}  // namespace dermis
