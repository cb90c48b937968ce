#include "stress/Invariants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dermis::stress {
namespace {

std::string format(const char* fmt, double a = 0, double b = 0, double c = 0, double d = 0, double e = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, fmt, a, b, c, d, e);
    return buffer;
}

float maxChannel(const glm::vec4& v) { return std::max(v.r, std::max(v.g, v.b)); }

// Common.glsl albedoPower: 1 for an exponent <= 0.
glm::vec3 albedoPower(const glm::vec3& albedo, float exponent) {
    if (exponent <= 0.0f) return glm::vec3(1.0f);
    return glm::pow(glm::max(albedo, glm::vec3(0.0f)), glm::vec3(exponent));
}

bool neighbourhoodHas(const Image& object, int x, int y, int character) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= object.width || ny >= object.height) continue;
            if (objectAt(object, nx, ny) == character) return true;
        }
    }
    return false;
}

}  // namespace

void InvariantTally::violation(std::string detail) {
    ++violated;
    if (details.size() < kMaxViolationDetails) details.push_back(std::move(detail));
}

void InvariantTally::add(const InvariantTally& other) {
    checked += other.checked;
    violated += other.violated;
    for (const std::string& d : other.details) {
        if (details.size() < kMaxViolationDetails) details.push_back(d);
    }
}

bool InvariantReport::anyViolated() const {
    return std::any_of(tallies.begin(), tallies.end(), [](const InvariantTally& t) { return t.violated > 0; });
}

void InvariantReport::add(const InvariantReport& other) {
    for (size_t i = 0; i < tallies.size(); ++i) tallies[i].add(other.tallies[i]);
}

int objectAt(const Image& object, int x, int y) {
    const float id = object.at(x, y).r;
    if (!(id >= 0.5f)) return -1;  // NaN counts as background: the check then names it
    return int(std::lround(id)) - 1;
}

void checkObjectCoversDepth(const Image& object, const Image& depth, int characters, InvariantTally& tally) {
    for (int y = 0; y < object.height; ++y) {
        for (int x = 0; x < object.width; ++x) {
            ++tally.checked;
            const bool covered = depth.at(x, y).a > 0.5f;
            const float id = object.at(x, y).r;
            const bool valid = covered ? (id >= 1.0f && id <= float(characters) && id == std::floor(id)) : id == 0.0f;
            if (!valid) {
                tally.violation(std::string(covered ? "covered" : "background") +
                                format(" pixel (%g, %g) has object id %g (characters: %g)", x, y, id, characters));
            }
        }
    }
}

void checkRaysMatchObject(const Image& object, const std::vector<RaySample>& rays, int characters,
                          InvariantTally& tally) {
    std::vector<int> raysSeeing(size_t(characters), 0);
    std::vector<bool> shown(size_t(characters), false);
    for (int y = 0; y < object.height; ++y) {
        for (int x = 0; x < object.width; ++x) {
            const int id = objectAt(object, x, y);
            if (id >= 0 && id < characters) shown[size_t(id)] = true;
        }
    }
    for (const RaySample& ray : rays) {
        if (ray.ambiguous) continue;
        ++tally.checked;
        if (ray.character >= 0) ++raysSeeing[size_t(ray.character)];
        const int engine = objectAt(object, ray.x, ray.y);
        if (engine == ray.character || neighbourhoodHas(object, ray.x, ray.y, ray.character)) continue;
        // Both characters at nearly the same depth: the depth buffer may keep either.
        if (ray.character >= 0 && engine >= 0 && size_t(engine) < ray.characterDepthM.size() &&
            std::abs(ray.characterDepthM[size_t(engine)] - ray.depthM) <= ray.depthToleranceM)
            continue;
        tally.violation(format("pixel (%g, %g): the ray sees character %g at depth %g m, the engine shows %g "
                               "(-1: background) and the 3x3 neighbourhood lacks the ray's",
                               ray.x, ray.y, ray.character, ray.depthM, engine));
    }
    for (int c = 0; c < characters; ++c) {
        if (raysSeeing[size_t(c)] < kLostCharacterRays) continue;
        ++tally.checked;
        if (!shown[size_t(c)])
            tally.violation(format("character %g is seen by %g rays but covers no pixel of the object image", c,
                                   raysSeeing[size_t(c)]));
    }
}

std::vector<glm::vec3> largestBlurInput(const Image& irradiance, const Image& transmittance, const Image& object,
                                        const std::vector<int>& groupOf, int groups) {
    std::vector<glm::vec3> largest(size_t(groups), glm::vec3(0.0f));
    for (int y = 0; y < object.height; ++y) {
        for (int x = 0; x < object.width; ++x) {
            const int c = objectAt(object, x, y);
            if (c < 0 || size_t(c) >= groupOf.size()) continue;
            const glm::vec3 input = glm::vec3(irradiance.at(x, y)) + glm::vec3(transmittance.at(x, y));
            glm::vec3& m = largest[size_t(groupOf[size_t(c)])];
            m = glm::max(m, input);
        }
    }
    return largest;
}

void checkEnergy(const EnergyInputs& in, InvariantTally& tally) {
    const Image& diffuse = *in.diffuse;
    for (int y = 0; y < diffuse.height; ++y) {
        for (int x = 0; x < diffuse.width; ++x) {
            const int c = objectAt(*in.object, x, y);
            if (c < 0 || size_t(c) >= in.groupOf.size()) continue;
            ++tally.checked;
            const glm::vec3 blurMax = in.groupBlurMax[size_t(in.groupOf[size_t(c)])];
            const glm::vec3 albedoOut = albedoPower(glm::vec3(in.albedo->at(x, y)), 1.0f - in.mix);
            const glm::vec3 bound = (1.0f + kEnergyRelative) * blurMax * albedoOut + kEnergyAbsolute;
            const glm::vec3 value = glm::vec3(diffuse.at(x, y));
            for (int i = 0; i < 3; ++i) {
                if (value[i] <= bound[i]) continue;  // NaN fails here too
                tally.violation(format("pixel (%g, %g) channel %g: diffuse %g > bound %g", x, y, i, value[i],
                                       bound[i]) +
                                format(" (largest blurred input %g x albedo^(1-mix) %g)", blurMax[i], albedoOut[i]));
                break;
            }
        }
    }
}

void checkNotBlack(const Image& object, const Image& albedo, const Image& diffuse, const Image& radiance, const Image& final,
                   const std::vector<RaySample>& rays, float exposure, int characters, InvariantTally& tally) {
    std::vector<int> litRays(size_t(characters), 0);
    std::vector<float> brightest(size_t(characters), 0.0f);
    std::vector<float> brightestDiffuse(size_t(characters), 0.0f);
    for (const RaySample& ray : rays) {
        if (!ray.lit || ray.ambiguous || ray.character < 0 || ray.character >= characters) continue;
        if (objectAt(object, ray.x, ray.y) != ray.character) continue;
        if (!(maxChannel(albedo.at(ray.x, ray.y)) > 0.0f)) continue;
        ++litRays[size_t(ray.character)];
        float& b = brightest[size_t(ray.character)];
        b = std::max(b, maxChannel(radiance.at(ray.x, ray.y)));
        float& d = brightestDiffuse[size_t(ray.character)];
        d = std::max(d, maxChannel(diffuse.at(ray.x, ray.y)));
    }
    for (int c = 0; c < characters; ++c) {
        if (litRays[size_t(c)] < kMinLitRays) continue;
        ++tally.checked;
        if (!(brightest[size_t(c)] > 0.0f))
            tally.violation(format("character %g: %g rays find it lit, but its radiance there is at most %g", c,
                                   litRays[size_t(c)], brightest[size_t(c)]));
        else if (!(brightestDiffuse[size_t(c)] > 0.0f))
            tally.violation(format("character %g: %g rays find it lit, but its diffuse light there is at most %g", c,
                                   litRays[size_t(c)], brightestDiffuse[size_t(c)]));
    }
    // ACES (Narkowicz) of 0.01 is 0.0038 linear, sRGB 0.049 = 12.5/255: far above 8-bit black.
    for (int y = 0; y < radiance.height; ++y) {
        for (int x = 0; x < radiance.width; ++x) {
            const float visible = maxChannel(radiance.at(x, y)) * exposure;
            if (!(visible >= kVisibleRadiance)) continue;
            ++tally.checked;
            const float shown = maxChannel(final.at(x, y));
            if (!(shown >= 0.5f / 255.0f))
                tally.violation(format("pixel (%g, %g): radiance x exposure %g but the final frame shows %g", x, y,
                                       visible, shown));
        }
    }
}

void checkScreenMatchesTexture(const Image& object, const Image& ssDiffuse, const Image& tsDiffuse,
                               InvariantTally& tally, float* relativeDifference) {
    auto interior = [&](int x, int y) {
        const int id = objectAt(object, x, y);
        if (id < 0) return false;
        for (int dy = -kSsTsInteriorPx; dy <= kSsTsInteriorPx; ++dy) {
            for (int dx = -kSsTsInteriorPx; dx <= kSsTsInteriorPx; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= object.width || ny >= object.height) return false;
                if (objectAt(object, nx, ny) != id) return false;
            }
        }
        return true;
    };
    float largest = 0.0f, difference = 0.0f;
    int pixels = 0, worstX = 0, worstY = 0;
    for (int y = 0; y < object.height; ++y) {
        for (int x = 0; x < object.width; ++x) {
            if (!interior(x, y)) continue;
            ++pixels;
            largest = std::max(largest, maxChannel(tsDiffuse.at(x, y)));
            const float d = maxChannel(glm::abs(ssDiffuse.at(x, y) - tsDiffuse.at(x, y)));
            if (!(d <= difference)) {
                difference = d;
                worstX = x;
                worstY = y;
            }
        }
    }
    if (pixels == 0) return;
    ++tally.checked;
    const float relative = largest > 0.0f ? difference / largest : (difference > 0.0f ? INFINITY : 0.0f);
    if (relativeDifference) *relativeDifference = relative;
    if (!(relative <= kSsTsBound))
        tally.violation(format("%g interior pixels: max |ss - ts| = %g at (%g, %g), %g of the largest ts value", pixels,
                               difference, worstX, worstY, relative) +
                        format(" (bound %g)", kSsTsBound));
}

void checkMoreLightDarkensNothing(const Image& before, const Image& after, const std::string& what,
                                  InvariantTally& tally) {
    ++tally.checked;
    int darker = 0;
    int worstX = 0, worstY = 0, worstChannel = 0;
    float worstBefore = 0.0f, worstAfter = 0.0f, worstShortfall = 0.0f;
    for (int y = 0; y < before.height; ++y) {
        for (int x = 0; x < before.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float b = before.at(x, y)[c];
                const float a = after.at(x, y)[c];
                const float floor = b * (1.0f - kMoreLightRelative) - kMoreLightAbsolute;
                if (a >= floor) continue;  // false for NaN
                ++darker;
                const float shortfall = std::isfinite(a) ? (b - a) / std::max(b, 1e-30f) : INFINITY;
                if (darker == 1 || shortfall > worstShortfall) {
                    worstShortfall = shortfall;
                    worstX = x, worstY = y, worstChannel = c;
                    worstBefore = b, worstAfter = a;
                }
            }
        }
    }
    if (darker > 0)
        tally.violation(what + format(": %g pixel channels darker; the worst, pixel (%g, %g) channel %g, fell from %g",
                                      darker, worstX, worstY, worstChannel, worstBefore) +
                        format(" to %g", worstAfter));
}

}  // namespace dermis::stress
