#include "env/IrradianceMap.h"

#include "env/SphericalHarmonics.h"
#include "raytrace/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dermis {

Image makeIrradianceMap(const Image& radiance, int threads) {
    // Each map texel's power, per channel, goes into the bin of a coarser
    // lat-long grid holding its centre, as a first moment sum P_i w_i: a bin
    // whose texels all lie above n's horizon then gives exactly
    // sum P_i max(n.w_i, 0) = n . sum P_i w_i, so only the bins the horizon
    // cuts are approximate.
    const int binRows = std::min(kIrradianceBinRows, radiance.height);
    const int binColumns = 2 * binRows;
    std::vector<std::array<glm::dvec3, 3>> moments(size_t(binColumns) * size_t(binRows));
    for (int v = 0; v < radiance.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, radiance.width, radiance.height);
        const int binV = v * binRows / radiance.height;
        for (int u = 0; u < radiance.width; ++u) {
            const glm::dvec3 direction(latLongDirection(u, v, radiance.width, radiance.height));
            const glm::vec4 texel = radiance.at(u, v);
            auto& moment = moments[size_t(binV) * size_t(binColumns) + size_t(u * binColumns / radiance.width)];
            for (int c = 0; c < 3; ++c) moment[size_t(c)] += direction * (double(texel[c]) * solidAngle);
        }
    }
    moments.erase(std::remove_if(moments.begin(), moments.end(),
                                 [](const std::array<glm::dvec3, 3>& m) {
                                     return m[0] == glm::dvec3(0.0) && m[1] == glm::dvec3(0.0) && m[2] == glm::dvec3(0.0);
                                 }),
                  moments.end());
    Image out;
    out.width = 2 * kIrradianceMapHeight;
    out.height = kIrradianceMapHeight;
    out.texels.assign(size_t(out.width) * size_t(out.height), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    raytrace::parallelFor(size_t(out.height), threads, [&](size_t row) {
        const int v = int(row);
        for (int u = 0; u < out.width; ++u) {
            const glm::dvec3 normal(latLongDirection(u, v, out.width, out.height));
            glm::dvec3 sum(0.0);
            for (const auto& moment : moments) {
                for (int c = 0; c < 3; ++c) sum[c] += std::max(glm::dot(normal, moment[size_t(c)]), 0.0);
            }
            out.at(u, v) = glm::vec4(glm::vec3(sum), 1.0f);
        }
    });
    return out;
}

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
