#include "reference/ReferenceLighting.h"

#include "gpu/UniformBlocks.h"
#include "brdf/EnergyTable.h"

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

}  // namespace

ReferenceLighting::ReferenceLighting(const Scene& scene, const Bvh& occluders)
    : mOccluders(&occluders),
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
        prepared.shadowed = light.castsShadow && prepared.type != DERMIS_LIGHT_POINT &&
                            shadowedCount < DERMIS_MAX_SHADOWED_LIGHTS;
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
            const float side = glm::dot(point.geometricNormal, l) >= 0.0f ? 1.0f : -1.0f;
            const Ray ray{point.positionM + point.geometricNormal * (side * kShadowOffsetM), l};
            const bool blocked = mOccluders->anyHit(ray, 0.0f, rayLength);
            if (visibility) {
                visibility->tested |= uint64_t(1) << i;
                if (!blocked) visibility->visible |= uint64_t(1) << i;
            }
            if (blocked) continue;
        }
        const float share = mEnergyConservation ? energyLeftForDiffuse(nDotL, point.roughness, point.rhoS) : 1.0f;
        e += radiance * (nDotL * share);
    }
    return e;
}

float ReferenceLighting::outgoingFactor(const SurfacePoint& point, const glm::vec3& towardsViewer) const {
    if (!mEnergyConservation) return 1.0f;
    return energyLeftForDiffuse(std::clamp(glm::dot(point.shadingNormal, towardsViewer), 0.0f, 1.0f), point.roughness,
                                point.rhoS);
}

}  // namespace dermis::reference
