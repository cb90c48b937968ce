// The built-in diffusion profiles and their registry.
#include "sss/DiffusionProfile.h"

#include <cassert>
#include <cmath>

namespace dermis {

namespace {

DiffusionProfile makeBuiltin(const char* name, std::vector<ProfileGaussian> gaussians) {
    Result<DiffusionProfile> profile = DiffusionProfile::create(name, std::move(gaussians));
    assert(profile.ok());
    return std::move(profile).value();
}

}  // namespace

const DiffusionProfile& skinProfile() {
    // Chappuis 2011 fig. 2.7 (d'Eon & Luebke's fit of Donner & Jensen's three-layer skin model).
    static const DiffusionProfile kSkin = makeBuiltin("skin", {
        {0.0064f, {0.233f, 0.455f, 0.649f}},
        {0.0484f, {0.100f, 0.336f, 0.344f}},
        {0.187f, {0.118f, 0.198f, 0.000f}},
        {0.567f, {0.113f, 0.007f, 0.007f}},
        {1.99f, {0.358f, 0.004f, 0.000f}},
        {7.41f, {0.078f, 0.000f, 0.000f}},
    });
    return kSkin;
}

const DiffusionProfile& marbleProfile() {
    // The shape of the classical dipole profile R_d(r) of marble (Jensen et al. 2001, "A Practical
    // Model for Subsurface Light Transport", §2.4 and table 2: sigma_s' = (2.19, 2.62, 3.00) /mm,
    // sigma_a = (0.0021, 0.0041, 0.0071) /mm, eta = 1.5), each channel divided by its closed-form
    // total diffuse reflectance (0.830, 0.791, 0.753) so that it integrates to 1; the albedo
    // texture carries the colour.
    //
    // Fitted once, offline, by a throwaway program (not in the tree): variances on a fixed
    // geometric series v_i = 0.036 * 4.1^i mm^2 (first term and ratio by a grid search that
    // minimised the worst channel's error), weights per channel by non-negative least squares
    // on r * R(r) at 2000 midpoints of 0..20 mm, with sum(w) = 1 as a heavily weighted extra
    // row, then rounded to 4 decimals. Relative L2 error of r * R(r) over 0..20 mm, after
    // create()'s renormalisation: red 1.5%, green 1.2%, blue 1.5% (asserted below 2% by
    // tests/unit/test_diffusion_profile.cpp, which evaluates the dipole itself).
    constexpr float kWeights[6][3] = {
        {0.0467f, 0.0915f, 0.1397f},
        {0.2005f, 0.2198f, 0.2206f},
        {0.1654f, 0.1634f, 0.1757f},
        {0.2093f, 0.2392f, 0.2558f},
        {0.2277f, 0.2084f, 0.1727f},
        {0.1504f, 0.0778f, 0.0354f},
    };
    constexpr double kFirstVarianceMm2 = 0.036;
    constexpr double kVarianceRatio = 4.1;
    static const DiffusionProfile kMarble = [&] {
        std::vector<ProfileGaussian> gaussians;
        for (int i = 0; i < 6; ++i) {
            const float varianceMm2 = static_cast<float>(kFirstVarianceMm2 * std::pow(kVarianceRatio, i));
            gaussians.push_back({varianceMm2, {kWeights[i][0], kWeights[i][1], kWeights[i][2]}});
        }
        return makeBuiltin("marble", std::move(gaussians));
    }();
    return kMarble;
}

std::vector<std::string> profileNames() { return {"skin", "marble"}; }

Result<const DiffusionProfile*> findProfile(const std::string& name) {
    if (name == "skin") return &skinProfile();
    if (name == "marble") return &marbleProfile();
    std::string known;
    for (const std::string& n : profileNames()) known += (known.empty() ? "" : ", ") + n;
    return makeError("", "unknown diffusion profile \"" + name + "\" (known: " + known + ")");
}

}  // namespace dermis
