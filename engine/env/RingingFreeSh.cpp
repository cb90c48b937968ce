#include "env/RingingFreeSh.h"

#include "core/Luminance.h"
#include "env/DominantLight.h"

namespace dermis {

namespace {

// The share of each texel's power above the cap: 0 below it.
class HotShare {
public:
    explicit HotShare(const Image& map)
        : mMaxUnwindowedPower(kShUnwindowedPowerFraction * 4.0 * 3.14159265358979323846 * medianLuminance(map)) {}
    double of(const glm::dvec3& power) const {
        const double luminancePower = relativeLuminance(glm::vec3(power));
        return luminancePower > mMaxUnwindowedPower ? 1.0 - mMaxUnwindowedPower / luminancePower : 0.0;
    }

private:
    double mMaxUnwindowedPower;
};

}  // namespace

SplitSh projectLatLongSplit(const Image& map) {
    const HotShare hotShareOf(map);
    // One pass, no copies of the map: each texel's radiance x solid angle
    // split into the part projected as it is and the windowed part.
    std::array<glm::dvec3, kShCoefficients> smooth{}, hot{};
    for (int v = 0; v < map.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) {
            const glm::dvec3 power = glm::dvec3(glm::vec3(map.at(u, v))) * solidAngle;
            const double hotShare = hotShareOf.of(power);
            const auto y = shBasis(latLongDirection(u, v, map.width, map.height));
            for (int i = 0; i < kShCoefficients; ++i) {
                const int band = i == 0 ? 0 : i < 4 ? 1 : 2;
                smooth[size_t(i)] += power * ((1.0 - hotShare) * double(y[size_t(i)]));
                hot[size_t(i)] += power * (hotShare * double(kShNonNegativeWindow[size_t(band)]) * double(y[size_t(i)]));
            }
        }
    }
    SplitSh out;
    for (int i = 0; i < kShCoefficients; ++i) {
        out.smooth.coefficients[size_t(i)] = glm::vec3(smooth[size_t(i)]);
        out.hot.coefficients[size_t(i)] = glm::vec3(hot[size_t(i)]);
    }
    return out;
}

Sh9 SplitSh::total() const {
    Sh9 out;
    for (int i = 0; i < kShCoefficients; ++i)
        out.coefficients[size_t(i)] = smooth.coefficients[size_t(i)] + hot.coefficients[size_t(i)];
    return out;
}

Sh9 projectLatLongWithoutRinging(const Image& map) { return projectLatLongSplit(map).total(); }

Image smoothPartOfLatLong(const Image& map) {
    const HotShare hotShareOf(map);
    Image smooth = map;
    for (int v = 0; v < map.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) {
            glm::vec4& texel = smooth.at(u, v);
            const double keep = 1.0 - hotShareOf.of(glm::dvec3(glm::vec3(texel)) * solidAngle);
            texel = glm::vec4(glm::vec3(texel) * float(keep), texel.a);
        }
    }
    return smooth;
}

}  // namespace dermis
