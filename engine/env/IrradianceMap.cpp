#include "env/IrradianceMap.h"

#include "env/SphericalHarmonics.h"
#include "raytrace/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dermis {

std::vector<Image> makeIrradiancePowerMaps(const Image& radiance, int threads) {
    // Each map texel's power, per channel, goes into the bin of a coarser
    // lat-long grid holding its centre, as its power P and first moment
    // sum P_i w_i: a bin whose texels all lie above n's horizon then gives
    // exactly sum P_i max(n.w_i, 0) = n . sum P_i w_i, so only the bins the
    // horizon cuts are approximate.
    struct Bin {
        std::array<glm::dvec3, 3> moment{};
        glm::dvec3 power{0.0};
    };
    const int binRows = std::min(kIrradianceBinRows, radiance.height);
    const int binColumns = 2 * binRows;
    std::vector<Bin> bins(size_t(binColumns) * size_t(binRows));
    for (int v = 0; v < radiance.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, radiance.width, radiance.height);
        const int binV = v * binRows / radiance.height;
        for (int u = 0; u < radiance.width; ++u) {
            const glm::dvec3 direction(latLongDirection(u, v, radiance.width, radiance.height));
            const glm::vec4 texel = radiance.at(u, v);
            Bin& bin = bins[size_t(binV) * size_t(binColumns) + size_t(u * binColumns / radiance.width)];
            for (int c = 0; c < 3; ++c) {
                bin.moment[size_t(c)] += direction * (double(texel[c]) * solidAngle);
                bin.power[c] += double(texel[c]) * solidAngle;
            }
        }
    }
    bins.erase(std::remove_if(bins.begin(), bins.end(), [](const Bin& b) { return b.power == glm::dvec3(0.0); }),
               bins.end());
    std::vector<Image> out(static_cast<size_t>(kIrradiancePowers));
    for (Image& image : out) {
        image.width = 2 * kIrradianceMapHeight;
        image.height = kIrradianceMapHeight;
        image.texels.assign(size_t(image.width) * size_t(image.height), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    raytrace::parallelFor(size_t(kIrradianceMapHeight), threads, [&](size_t row) {
        const int v = int(row);
        for (int u = 0; u < out[0].width; ++u) {
            const glm::dvec3 normal(latLongDirection(u, v, out[0].width, out[0].height));
            std::array<glm::dvec3, kIrradiancePowers> sums{};
            for (const Bin& bin : bins) {
                for (int c = 0; c < 3; ++c) {
                    const double lit = glm::dot(normal, bin.moment[size_t(c)]);  // P times the bin's mean cosine
                    if (!(lit > 0.0)) continue;
                    const double meanCosine = std::min(lit / bin.power[c], 1.0);
                    double term = lit;
                    for (int k = 0; k < kIrradiancePowers; ++k) {
                        sums[size_t(k)][c] += term;
                        term *= meanCosine;
                    }
                }
            }
            for (int k = 0; k < kIrradiancePowers; ++k) out[size_t(k)].at(u, v) = glm::vec4(glm::vec3(sums[size_t(k)]), 1.0f);
        }
    });
    return out;
}

Image makeIrradianceMap(const Image& radiance, int threads) { return makeIrradiancePowerMaps(radiance, threads).front(); }

glm::vec3 sampleIrradianceMap(const Image& irradiance, const glm::vec3& normal) {
    const glm::vec2 uv = latLongUv(normal);
    const float x = uv.x * float(irradiance.width) - 0.5f;
    const float y = std::clamp(uv.y * float(irradiance.height) - 0.5f, 0.0f, float(irradiance.height - 1));
    const int x0 = int(std::floor(x)), y0 = std::min(int(y), irradiance.height - 2);
    const float fx = x - float(x0), fy = y - float(y0);
    auto at = [&](int u, int v) {
        return glm::vec3(irradiance.at(((u % irradiance.width) + irradiance.width) % irradiance.width, v));
    };
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace dermis
