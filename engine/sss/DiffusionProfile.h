#pragma once
// The one diffusion-profile type (docs/screen-space.md, "Diffusion profiles"): a sum
// of Gaussians R(r) = sum_i w_i G(v_i, r), G(v, r) = exp(-r^2 / 2v) / (2 pi v)
// (Chappuis 2011 §2.1.4), variances in mm^2, RGB weights normalised per channel
// so each channel sums to 1 (a white surface stays white after scattering).
// It serves both SSS modes, the transmittance, the CPU reference and user
// profiles.

#include "core/Result.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace dermis {

// Burley's normalized diffusion (Christensen & Burley 2015; sss/BurleyProfile.h has the
// profile, its CDF and the fit). Here so that a profile made from it can keep them.
struct BurleyParameters {
    glm::vec3 albedo{0.0f};                // surface albedo A per channel, in [0, 1]
    glm::vec3 scatteringDistanceMm{0.0f};  // mean free path l per channel, > 0
};

struct ProfileGaussian {
    float varianceMm2 = 0.0f;
    glm::vec3 weight{0.0f};
};

class DiffusionProfile {
public:
    // Validates (at least one Gaussian, variances finite, > 0 and strictly
    // increasing, weights finite and >= 0, every channel's sum > 0) and
    // normalises the weights per channel.
    static Result<DiffusionProfile> create(std::string name, std::vector<ProfileGaussian> gaussians);

    const std::string& name() const { return mName; }
    const std::vector<ProfileGaussian>& gaussians() const { return mGaussians; }
    size_t size() const { return mGaussians.size(); }

    // R(r) per channel, r in mm (units 1/mm^2; integrates to 1 over the plane).
    glm::vec3 radialProfile(float radiusMm) const;
    // Response across a straight edge between unlit (x < 0) and unit-lit
    // (x > 0) half-planes: sum_i w_i Phi(x / sqrt(v_i)) (docs/reference.md).
    glm::vec3 edgeResponse(float xMm) const;
    float largestStdDevMm() const;

    // The Burley parameters the Gaussians were fitted to (sss/BurleyProfile.h,
    // fitBurleyGaussians), if any: the disk technique samples that exact profile,
    // every other consumer the fit.
    const std::optional<BurleyParameters>& burley() const { return mBurley; }
    void setBurley(const BurleyParameters& parameters) { mBurley = parameters; }

private:
    std::string mName;
    std::vector<ProfileGaussian> mGaussians;
    std::optional<BurleyParameters> mBurley;
};

// The standard normal CDF, Phi(z) = erfc(-z / sqrt 2) / 2 (erfc keeps the left tail accurate).
double standardNormalCdf(double z);

// d'Eon & Luebke's six-Gaussian fit of the three-layer skin model (Chappuis 2011 fig. 2.7).
const DiffusionProfile& skinProfile();
// A marble-like profile: wider and whiter (see ProfileLibrary.cpp for its source).
const DiffusionProfile& marbleProfile();

// The built-in profiles by name ("skin", "marble"); the error lists the known names.
Result<const DiffusionProfile*> findProfile(const std::string& name);
std::vector<std::string> profileNames();

}  // namespace dermis
