#include "env/RingingFreeSh.h"

#include "core/Luminance.h"
#include "env/DominantLight.h"

namespace dermis {

Sh9 projectLatLongWithoutRinging(const Image& map) {
    const double maxUnwindowedPower = kShUnwindowedPowerFraction * 4.0 * 3.14159265358979323846 * medianLuminance(map);
    // One pass, no copies of the map: each texel's radiance x solid angle
    // split into the part projected as it is and the windowed part.
    std::array<glm::dvec3, kShCoefficients> sum{};
    for (int v = 0; v < map.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) {
            const glm::dvec3 power = glm::dvec3(glm::vec3(map.at(u, v))) * solidAngle;
            const double luminancePower = relativeLuminance(glm::vec3(power));
            const double hotShare = luminancePower > maxUnwindowedPower ? 1.0 - maxUnwindowedPower / luminancePower : 0.0;
            const auto y = shBasis(latLongDirection(u, v, map.width, map.height));
            for (int i = 0; i < kShCoefficients; ++i) {
                const int band = i == 0 ? 0 : i < 4 ? 1 : 2;
                const double weight = 1.0 - hotShare + hotShare * double(kShNonNegativeWindow[size_t(band)]);
                sum[size_t(i)] += power * (weight * double(y[size_t(i)]));
            }
        }
    }
    Sh9 out;
    for (int i = 0; i < kShCoefficients; ++i) out.coefficients[size_t(i)] = glm::vec3(sum[size_t(i)]);
    return out;
}

}  // namespace dermis
