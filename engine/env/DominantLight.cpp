#include "env/DominantLight.h"

#include "core/Luminance.h"
#include "env/SphericalHarmonics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

namespace dermis {
namespace {

constexpr double kPi = 3.14159265358979323846;

float texelLuminance(const Image& map, int u, int v) { return relativeLuminance(glm::vec3(map.at(u, v))); }

// The four neighbours of a texel on the sphere: u wraps; above the top row
// (below the bottom row) lies the same row half a turn away, across the pole.
std::array<std::pair<int, int>, 4> neighbours(int u, int v, int width, int height) {
    const int across = (u + width / 2) % width;
    return {{{(u + 1) % width, v},
             {(u + width - 1) % width, v},
             v > 0 ? std::pair<int, int>{u, v - 1} : std::pair<int, int>{across, v},
             v + 1 < height ? std::pair<int, int>{u, v + 1} : std::pair<int, int>{across, v}}};
}

struct Region {
    std::vector<std::pair<int, int>> texels;
    double solidAngleSr = 0.0;
};

// The texels at or above `threshold` connected to (u0, v0), marked in `inRegion`.
Region growRegion(const Image& map, int u0, int v0, float threshold, std::vector<char>& inRegion) {
    Region region;
    const auto index = [&map](int u, int v) { return size_t(v) * size_t(map.width) + size_t(u); };
    inRegion[index(u0, v0)] = 1;
    region.texels.emplace_back(u0, v0);
    for (size_t next = 0; next < region.texels.size(); ++next) {
        const auto [u, v] = region.texels[next];
        region.solidAngleSr += latLongTexelSolidAngle(v, map.width, map.height);
        for (const auto& [nu, nv] : neighbours(u, v, map.width, map.height)) {
            if (inRegion[index(nu, nv)] || texelLuminance(map, nu, nv) < threshold) continue;
            inRegion[index(nu, nv)] = 1;
            region.texels.emplace_back(nu, nv);
        }
    }
    return region;
}

// The radiance left in the region: its border's mean, per channel no more
// than the region's dimmest texel, so that L - fill >= 0 everywhere in it.
glm::dvec3 regionFill(const Image& map, const Region& region, const std::vector<char>& inRegion) {
    std::vector<char> counted(inRegion.size(), 0);
    glm::dvec3 borderSum(0.0), regionMin(INFINITY);
    double borderSolidAngle = 0.0;
    for (const auto& [u, v] : region.texels) {
        regionMin = glm::min(regionMin, glm::dvec3(glm::vec3(map.at(u, v))));
        for (const auto& [nu, nv] : neighbours(u, v, map.width, map.height)) {
            const size_t i = size_t(nv) * size_t(map.width) + size_t(nu);
            if (inRegion[i] || counted[i]) continue;
            counted[i] = 1;
            const double solidAngle = latLongTexelSolidAngle(nv, map.width, map.height);
            borderSum += glm::dvec3(glm::vec3(map.at(nu, nv))) * solidAngle;
            borderSolidAngle += solidAngle;
        }
    }
    const glm::dvec3 borderMean = borderSolidAngle > 0.0 ? borderSum / borderSolidAngle : glm::dvec3(0.0);
    return glm::min(borderMean, regionMin);
}

ExtractedLight makeLight(const Image& map, const Region& region, const glm::dvec3& fill) {
    glm::dvec3 moment(0.0);
    for (const auto& [u, v] : region.texels) {
        const glm::dvec3 excess = glm::dvec3(glm::vec3(map.at(u, v))) - fill;
        moment += double(relativeLuminance(glm::vec3(excess))) * glm::dvec3(latLongDirection(u, v, map.width, map.height)) *
                  double(latLongTexelSolidAngle(v, map.width, map.height));
    }
    ExtractedLight light;
    const glm::dvec3 towards = glm::length(moment) > 0.0 ? glm::normalize(moment) : glm::dvec3(0.0, 1.0, 0.0);
    glm::dvec3 irradiance(0.0);
    for (const auto& [u, v] : region.texels) {
        const glm::dvec3 excess = glm::dvec3(glm::vec3(map.at(u, v))) - fill;
        const double cosine = glm::dot(glm::dvec3(latLongDirection(u, v, map.width, map.height)), towards);
        irradiance += excess * std::max(cosine, 0.0) * double(latLongTexelSolidAngle(v, map.width, map.height));
    }
    light.towardsLight = glm::vec3(towards);
    light.irradiance = glm::vec3(irradiance);
    light.solidAngleSr = float(region.solidAngleSr);
    light.angularDiameterDeg = coneAngularDiameterDeg(light.solidAngleSr);
    light.fill = glm::vec3(fill);
    light.texels = int(region.texels.size());
    return light;
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

float coneAngularDiameterDeg(float solidAngleSr) {
    const double cosHalf = std::clamp(1.0 - double(solidAngleSr) / (2.0 * kPi), -1.0, 1.0);
    return float(2.0 * std::acos(cosHalf) * 180.0 / kPi);
}

float meanLuminance(const Image& map) {
    double sum = 0.0, total = 0.0;
    for (int v = 0; v < map.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) sum += double(texelLuminance(map, u, v)) * solidAngle;
        total += solidAngle * map.width;
    }
    return total > 0.0 ? float(sum / total) : 0.0f;
}

float medianLuminance(const Image& map) {
    std::vector<std::pair<float, float>> luminanceAndSolidAngle;
    luminanceAndSolidAngle.reserve(map.texels.size());
    double total = 0.0;
    for (int v = 0; v < map.height; ++v) {
        const float solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) {
            luminanceAndSolidAngle.emplace_back(texelLuminance(map, u, v), solidAngle);
            total += solidAngle;
        }
    }
    std::sort(luminanceAndSolidAngle.begin(), luminanceAndSolidAngle.end());
    double below = 0.0;
    for (const auto& [luminance, solidAngle] : luminanceAndSolidAngle) {
        below += solidAngle;
        if (below >= 0.5 * total) return luminance;
    }
    return luminanceAndSolidAngle.empty() ? 0.0f : luminanceAndSolidAngle.back().first;
}

EnvironmentSplit extractDominantLights(const Image& map, const LightExtractionSettings& settings) {
    EnvironmentSplit split;
    split.remainder = map;
    const float threshold = settings.thresholdOverMean * meanLuminance(map);
    std::vector<char> inRegion(map.texels.size(), 0);
    std::vector<char> tooLarge(map.texels.size(), 0);  // the texels of regions found too large
    std::string skipped;
    while (int(split.lights.size()) < settings.maxLights) {
        int peakU = 0, peakV = 0;
        float peak = -1.0f;
        for (int v = 0; v < map.height; ++v)
            for (int u = 0; u < map.width; ++u)
                if (const float l = texelLuminance(split.remainder, u, v);
                    l > peak && !tooLarge[size_t(v) * size_t(map.width) + size_t(u)]) {
                    peak = l;
                    peakU = u;
                    peakV = v;
                }
        if (!(peak > 0.0f) || peak < threshold) {
            split.why = skipped + "no " + (skipped.empty() ? "" : "other ") + "texel reaches " +
                        formatNumber(settings.thresholdOverMean) + " x the mean luminance (" + formatNumber(threshold) +
                        "; the brightest is " + formatNumber(peak) + ")";
            break;
        }
        std::fill(inRegion.begin(), inRegion.end(), 0);
        const Region region = growRegion(split.remainder, peakU, peakV, threshold, inRegion);
        if (region.solidAngleSr > settings.maxSolidAngleSr) {
            // Not a compact light but part of the sky: kept, and the next brightest region tried.
            for (const auto& [u, v] : region.texels) tooLarge[size_t(v) * size_t(map.width) + size_t(u)] = 1;
            skipped += "a region of " + formatNumber(region.solidAngleSr) + " sr (more than " +
                       formatNumber(settings.maxSolidAngleSr) + ") is not a compact light; ";
            continue;
        }
        const glm::dvec3 fill = regionFill(split.remainder, region, inRegion);
        split.lights.push_back(makeLight(split.remainder, region, fill));
        for (const auto& [u, v] : region.texels) split.remainder.at(u, v) = glm::vec4(glm::vec3(fill), 1.0f);
    }
    return split;
}

}  // namespace dermis
