#include "env/EnvironmentMap.h"

#include "env/SphericalHarmonics.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <string>

namespace dermis {

namespace {

Image emptyLatLong(int height) {
    Image map;
    map.height = height;
    map.width = 2 * height;
    map.colourSpace = ColourSpace::Linear;
    map.texels.resize(size_t(map.width) * size_t(map.height));
    return map;
}

// 1 inside the box's cap, 0 outside, a smoothstep across its edge.
float softBoxCoverage(const SoftBox& box, const glm::vec3& direction, float edgeDeg) {
    const float angleDeg = glm::degrees(std::acos(std::clamp(glm::dot(direction, glm::normalize(box.direction)), -1.0f, 1.0f)));
    const float t = std::clamp((box.radiusDeg + 0.5f * edgeDeg - angleDeg) / std::max(edgeDeg, 1e-3f), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

Status checkEnvironmentMap(const Image& map, const std::string& name) {
    if (map.width != 2 * map.height) {
        return makeError(name, std::to_string(map.width) + "x" + std::to_string(map.height) +
                                   " is not a latitude-longitude map: its width must be twice its height");
    }
    if (map.height < kMinEnvironmentHeight) {
        return makeError(name, "is " + std::to_string(map.width) + "x" + std::to_string(map.height) + "; at least " +
                                   std::to_string(2 * kMinEnvironmentHeight) + "x" + std::to_string(kMinEnvironmentHeight) +
                                   " is needed");
    }
    size_t bad = 0;
    int firstX = -1, firstY = -1;
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const glm::vec4& t = map.at(x, y);
            const bool ok = std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b) && t.r >= 0.0f && t.g >= 0.0f &&
                            t.b >= 0.0f;
            if (ok) continue;
            if (bad++ == 0) {
                firstX = x;
                firstY = y;
            }
        }
    }
    if (bad > 0) {
        return makeError(name, std::to_string(bad) + " texels are not finite non-negative radiance (the first at x " +
                                   std::to_string(firstX) + ", y " + std::to_string(firstY) + ")");
    }
    return success();
}

Result<Image> loadEnvironmentMap(const std::string& path) {
    int sanitised = 0;
    auto map = loadImage(path, ColourSpace::Linear, &sanitised);
    if (!map.ok()) return map.error();
    // loadImage replaces non-finite texels by 0: an environment map with any is refused instead.
    if (sanitised > 0) {
        return makeError(path, std::to_string(sanitised) + " texels are not finite (NaN or infinite radiance)");
    }
    if (const Status checked = checkEnvironmentMap(*map, path); !checked.ok()) return checked.error();
    return map;
}

Image makeProceduralSky(const ProceduralSky& sky, int height) {
    Image map = emptyLatLong(height);
    const glm::vec3 sun = glm::normalize(sky.sunDirection);
    const double cosSun = std::cos(glm::radians(double(sky.sunRadiusDeg)));
    std::vector<std::pair<int, int>> sunTexels;
    double sunTexelsSolidAngle = 0.0;
    for (int v = 0; v < map.height; ++v) {
        for (int u = 0; u < map.width; ++u) {
            const glm::vec3 d = latLongDirection(u, v, map.width, map.height);
            glm::vec3 radiance = sky.ground;
            if (d.y >= 0.0f) {
                // Zenith to horizon along the elevation, squared for a brighter band near the horizon.
                const float t = 1.0f - d.y;
                radiance = glm::mix(sky.zenith, sky.horizon, t * t);
            }
            map.at(u, v) = glm::vec4(radiance, 1.0f);
            if (glm::dot(d, sun) >= cosSun) {
                sunTexels.emplace_back(u, v);
                sunTexelsSolidAngle += latLongTexelSolidAngle(v, map.width, map.height);
            }
        }
    }
    // A sun smaller than a texel covers no texel centre: it goes into the texel
    // holding its direction. Either way its texels carry the disc's power,
    // radiance x its solid angle 2 pi (1 - cos r), so the light it gives does
    // not depend on the map's size.
    if (sunTexels.empty()) {
        const double theta = std::acos(std::clamp(double(sun.y), -1.0, 1.0));
        double phi = std::atan2(double(sun.x), double(sun.z));
        if (phi < 0.0) phi += 2.0 * 3.14159265358979323846;
        const int u = std::min(map.width - 1, int(phi / (2.0 * 3.14159265358979323846) * map.width));
        const int v = std::min(map.height - 1, int(theta / 3.14159265358979323846 * map.height));
        sunTexels.emplace_back(u, v);
        sunTexelsSolidAngle = latLongTexelSolidAngle(v, map.width, map.height);
    }
    const double discSolidAngle = 2.0 * 3.14159265358979323846 * (1.0 - cosSun);
    const glm::vec3 texelRadiance = sky.sunRadiance * float(discSolidAngle / sunTexelsSolidAngle);
    for (const auto& [u, v] : sunTexels) map.at(u, v) = glm::vec4(texelRadiance, 1.0f);
    return map;
}


Image makeProceduralStudio(const ProceduralStudio& studio, int height) {
    Image map = emptyLatLong(height);
    for (int v = 0; v < map.height; ++v) {
        for (int u = 0; u < map.width; ++u) {
            const glm::vec3 d = latLongDirection(u, v, map.width, map.height);
            glm::vec3 radiance = d.y >= 0.0f ? studio.walls : studio.floor;
            for (const SoftBox* box : {&studio.key, &studio.fill, &studio.rim}) {
                radiance = glm::mix(radiance, box->radiance, softBoxCoverage(*box, d, studio.edgeDeg));
            }
            map.at(u, v) = glm::vec4(radiance, 1.0f);
        }
    }
    return map;
}

Result<Image> makeBuiltInEnvironment(const std::string& name, int height) {
    if (name == "sky") {
        ProceduralSky sky;
        // A 0.53 degree sun of this radiance gives 2.0 irradiance facing it; the sky gives about 2.
        sky.sunRadiance = glm::vec3(30000.0f, 28500.0f, 25500.0f);
        return makeProceduralSky(sky, height);
    }
    if (name == "studio") return makeProceduralStudio(ProceduralStudio{}, height);
    if (name == "uniform") {
        Image map = emptyLatLong(height);
        std::fill(map.texels.begin(), map.texels.end(), glm::vec4(1.0f));
        return map;
    }
    return makeError(name, "unknown built-in environment (known: sky, studio or uniform)");
}

}  // namespace dermis
