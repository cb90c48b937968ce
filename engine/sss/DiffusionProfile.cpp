#include "sss/DiffusionProfile.h"

#include <cmath>
#include <sstream>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kChannelNames[3] = {"red", "green", "blue"};

Error profileError(const std::string& name, const std::string& what) {
    return makeError("", "diffusion profile \"" + name + "\": " + what);
}

std::string formatWeight(const glm::vec3& w) {
    std::ostringstream out;
    out << "(" << w.r << ", " << w.g << ", " << w.b << ")";
    return out.str();
}

}  // namespace

double standardNormalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

Result<DiffusionProfile> DiffusionProfile::create(std::string name, std::vector<ProfileGaussian> gaussians) {
    if (gaussians.empty()) return profileError(name, "has no Gaussians");
    double sums[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < gaussians.size(); ++i) {
        const ProfileGaussian& g = gaussians[i];
        const std::string label = "Gaussian " + std::to_string(i + 1);
        if (!std::isfinite(g.varianceMm2) || g.varianceMm2 <= 0.0f)
            return profileError(name, label + " has variance " + std::to_string(g.varianceMm2) +
                                          " mm^2; variances must be finite and > 0");
        if (i > 0 && g.varianceMm2 <= gaussians[i - 1].varianceMm2)
            return profileError(name, label + " has variance " + std::to_string(g.varianceMm2) + " mm^2, not more than Gaussian " +
                                          std::to_string(i) + "'s " + std::to_string(gaussians[i - 1].varianceMm2) +
                                          " mm^2; variances must strictly increase");
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(g.weight[c]) || g.weight[c] < 0.0f)
                return profileError(name, label + " has weight " + formatWeight(g.weight) + "; weights must be finite and >= 0");
            sums[c] += double(g.weight[c]);
        }
    }
    for (int c = 0; c < 3; ++c) {
        if (!(sums[c] > 0.0) || !std::isfinite(sums[c]))
            return profileError(name, std::string("the ") + kChannelNames[c] +
                                          " weights sum to " + std::to_string(sums[c]) + "; every channel needs a finite, positive sum");
    }
    // Per-channel normalisation (Chappuis 2011 §2.1.4: the weights of each profile sum to 1).
    for (ProfileGaussian& g : gaussians)
        for (int c = 0; c < 3; ++c) g.weight[c] = static_cast<float>(double(g.weight[c]) / sums[c]);

    DiffusionProfile profile;
    profile.mName = std::move(name);
    profile.mGaussians = std::move(gaussians);
    return profile;
}

glm::vec3 DiffusionProfile::radialProfile(float radiusMm) const {
    const double r2 = double(radiusMm) * double(radiusMm);
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : mGaussians) {
        const double v = g.varianceMm2;
        sum += glm::dvec3(g.weight) * (std::exp(-r2 / (2.0 * v)) / (2.0 * kPi * v));  // G(v, r), Chappuis 2011 §2.1.4
    }
    return glm::vec3(sum);
}

glm::vec3 DiffusionProfile::edgeResponse(float xMm) const {
    // Integrating G(v, r) over the lit half-plane leaves the 1-D CDF across the edge (docs/reference.md).
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : mGaussians)
        sum += glm::dvec3(g.weight) * standardNormalCdf(double(xMm) / std::sqrt(double(g.varianceMm2)));
    return glm::vec3(sum);
}

float DiffusionProfile::largestStdDevMm() const {
    // The widest Gaussian that carries weight in some channel: an all-zero one is never blurred.
    for (auto it = mGaussians.rbegin(); it != mGaussians.rend(); ++it)
        if (it->weight.r > 0.0f || it->weight.g > 0.0f || it->weight.b > 0.0f) return std::sqrt(it->varianceMm2);
    return 0.0f;  // unreachable for a created profile: every channel has positive weight
}

}  // namespace dermis
