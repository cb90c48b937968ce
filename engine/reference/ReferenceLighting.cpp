#include "reference/ReferenceLighting.h"

#include "gpu/UniformBlocks.h"
#include "brdf/EnergyTable.h"
#include "raytrace/Sampling.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dermis::reference {
namespace {

// Shadow rays start this far off the surface, on the light's side of the
// triangle's plane: far below the narrowest profile width (80 um).
constexpr float kShadowOffsetM = 1e-5f;

float smoothstep(float edge0, float edge1, float x) {
    if (!(edge1 != edge0)) return x < edge0 ? 0.0f : 1.0f;
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Van der Corput's radical inverse in base 2: the second coordinate of the
// Hammersley set.
float radicalInverse2(uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return float(double(i) / 4294967296.0);
}

// A stratified (Hammersley) set on the unit square, taken onto the unit disc by
// the concentric map (Shirley & Chiu 1997), which keeps the strata's areas.
std::vector<glm::vec2> discSamples(int count) {
    std::vector<glm::vec2> samples;
    for (int i = 0; i < count; ++i)
        samples.push_back(raytrace::concentricDisc(
            glm::vec2((float(i) + 0.5f) / float(count), radicalInverse2(uint32_t(i)) + 0.5f / float(count))));
    return samples;
}

// A unit direction within the cone of half-angle asin(sinRadius) around `axis`,
// for the disc point `p`: uniform in solid angle when `p` is uniform over the
// disc, as cos(theta) = 1 - |p|^2 (1 - cos(radius)).
glm::vec3 coneDirection(const glm::vec3& axis, float sinRadius, const glm::vec2& p) {
    const glm::vec3 t = glm::normalize(glm::cross(axis, std::fabs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 b = glm::cross(axis, t);
    const double sinR = sinRadius;
    const double oneMinusCosR = sinR * sinR / (1.0 + std::sqrt(std::max(0.0, 1.0 - sinR * sinR)));
    const double r2 = double(glm::dot(p, p));
    if (r2 <= 0.0) return axis;
    const double oneMinusCos = r2 * oneMinusCosR;
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    const glm::vec2 unit = p / float(std::sqrt(r2));
    return glm::normalize(float(1.0 - oneMinusCos) * axis + float(sinTheta) * (unit.x * t + unit.y * b));
}

}  // namespace

ReferenceLighting::ReferenceLighting(const Scene& scene, const Bvh& occluders)
    : mOccluders(&occluders),
      mDiscSamples(discSamples(kAreaLightSamples)),
      mAmbient(scene.settings.ambient),
      mEnergyConservation(scene.settings.energyConservation),
      mEnergyTable(makeEnergyTable(kEnergyTableSize)) {
    const size_t count = std::min<size_t>(scene.lights.size(), DERMIS_MAX_LIGHTS);
    int shadowedCount = 0;
    for (size_t i = 0; i < count; ++i) {
        const Light& light = scene.lights[i];
        PreparedLight prepared;
        prepared.type = light.type == LightType::Directional ? DERMIS_LIGHT_DIRECTIONAL
                        : light.type == LightType::Spot      ? DERMIS_LIGHT_SPOT
                                                             : DERMIS_LIGHT_POINT;
        prepared.positionM = light.positionM;
        prepared.direction = glm::normalize(light.direction);
        prepared.radiance = light.colour * light.intensity;
        prepared.cosInner = std::cos(glm::radians(light.spotInnerDeg));
        prepared.cosOuter = std::cos(glm::radians(light.spotOuterDeg));
        prepared.shadowed = light.castsShadow && shadowedCount < DERMIS_MAX_SHADOWED_LIGHTS;
        prepared.sinAngularRadius = std::sin(glm::radians(0.5f * light.angularDiameterDeg));
        prepared.radiusM = light.radiusM;
        if (prepared.shadowed) ++shadowedCount;
        mLights.push_back(prepared);
    }
}

float ReferenceLighting::energyLeftForDiffuse(float cosTheta, float roughness, float rhoS) const {
    // Texel centres on the sample points: coordinate = value x (size - 1).
    const float last = float(kEnergyTableSize - 1);
    const float x = std::clamp(cosTheta, 0.0f, 1.0f) * last;
    const float y = std::clamp(roughness, 0.0f, 1.0f) * last;
    const int x0 = std::min(static_cast<int>(x), kEnergyTableSize - 2);
    const int y0 = std::min(static_cast<int>(y), kEnergyTableSize - 2);
    const float fx = x - float(x0);
    const float fy = y - float(y0);
    auto at = [&](int i, int j) { return mEnergyTable[size_t(j) * kEnergyTableSize + size_t(i)]; };
    const float rhoDt = (1.0f - fy) * ((1.0f - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                        fy * ((1.0f - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    return std::clamp(1.0f - rhoS * rhoDt, 0.0f, 1.0f);
}

glm::vec3 ReferenceLighting::irradiance(const SurfacePoint& point, LightVisibility* visibility) const {
    glm::vec3 e = mAmbient;
    const glm::vec3& n = point.shadingNormal;
    for (size_t i = 0; i < mLights.size(); ++i) {
        const PreparedLight& light = mLights[i];
        glm::vec3 l;
        glm::vec3 radiance = light.radiance;
        float rayLength = std::numeric_limits<float>::infinity();
        if (light.type == DERMIS_LIGHT_DIRECTIONAL) {
            l = -light.direction;
        } else {
            const glm::vec3 toLight = light.positionM - point.positionM;
            const float distanceSquaredM2 = std::max(glm::dot(toLight, toLight), 1e-6f);
            rayLength = std::sqrt(distanceSquaredM2);
            l = toLight / rayLength;
            radiance /= distanceSquaredM2;
            if (light.type == DERMIS_LIGHT_SPOT) {
                radiance *= smoothstep(light.cosOuter, light.cosInner, glm::dot(-l, light.direction));
            }
        }
        const float nDotL = glm::dot(n, l);
        if (!(nDotL > 0.0f)) continue;
        if (light.shadowed && i < 64) {
            const float visible = lightVisibility(i, point, l, rayLength, visibility);
            if (!(visible > 0.0f)) continue;
            radiance *= visible;
        }
        const float share = mEnergyConservation ? energyLeftForDiffuse(nDotL, point.roughness, point.rhoS) : 1.0f;
        e += radiance * (nDotL * share);
    }
    return e;
}

float ReferenceLighting::lightVisibility(size_t index, const SurfacePoint& point, const glm::vec3& l, float distanceM,
                                         LightVisibility* visibility) const {
    const PreparedLight& light = mLights[index];
    const float side = glm::dot(point.geometricNormal, l) >= 0.0f ? 1.0f : -1.0f;
    const glm::vec3 origin = point.positionM + point.geometricNormal * (side * kShadowOffsetM);
    // The light's angular radius seen from the point; a sphere around the point is a delta light.
    float sinRadius = light.sinAngularRadius;
    if (light.type != DERMIS_LIGHT_DIRECTIONAL) sinRadius = light.radiusM < distanceM ? light.radiusM / distanceM : 0.0f;
    const bool delta = !(sinRadius > 0.0f);
    const size_t rays = delta ? 1 : mDiscSamples.size();
    size_t unblocked = 0;
    for (size_t s = 0; s < rays; ++s) {
        const glm::vec3 direction = delta ? l : coneDirection(l, sinRadius, mDiscSamples[s]);
        float lengthM = distanceM;  // infinite for a directional light
        if (!delta && light.type != DERMIS_LIGHT_DIRECTIONAL) {
            // To the near side of the sphere along this direction.
            const float along = distanceM * glm::dot(direction, l);
            const float across2 = distanceM * distanceM - along * along;
            lengthM = along - std::sqrt(std::max(light.radiusM * light.radiusM - across2, 0.0f));
        } else if (light.type != DERMIS_LIGHT_DIRECTIONAL) {
            lengthM = distanceM - light.radiusM;
        }
        if (!mOccluders->anyHit(Ray{origin, direction}, 0.0f, lengthM)) ++unblocked;
    }
    if (visibility) {
        const uint64_t bit = uint64_t(1) << index;
        visibility->tested |= bit;
        if (unblocked == rays) visibility->visible |= bit;
        if (unblocked == 0) visibility->blocked |= bit;
    }
    return float(unblocked) / float(rays);
}

float ReferenceLighting::outgoingFactor(const SurfacePoint& point, const glm::vec3& towardsViewer) const {
    if (!mEnergyConservation) return 1.0f;
    return energyLeftForDiffuse(std::clamp(glm::dot(point.shadingNormal, towardsViewer), 0.0f, 1.0f), point.roughness,
                                point.rhoS);
}

}  // namespace dermis::reference
