#include "render/LightSetup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

glm::vec3 anyPerpendicularUp(const glm::vec3& direction) {
    return std::fabs(direction.y) < 0.95f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

}  // namespace

LightSetup setupLights(const std::vector<Light>& lights, const Bounds& sceneBounds, const ShadowSettings& shadows) {
    LightSetup setup;
    const glm::vec3 centre = sceneBounds.centre();
    const float radiusM = std::max(0.5f * glm::length(sceneBounds.size()), 1e-3f);
    const int count = std::min<int>(static_cast<int>(lights.size()), DERMIS_MAX_LIGHTS);
    setup.lightCount = count;
    for (int i = 0; i < count; ++i) {
        const Light& light = lights[static_cast<size_t>(i)];
        gpu::GpuLight& g = setup.block.lights[i];
        const glm::vec3 direction = glm::normalize(light.direction);
        const int type = static_cast<int>(light.type);  // DERMIS_LIGHT_* (scene/SceneEnums.h)
        glm::vec3 positionM = light.positionM;
        if (type == DERMIS_LIGHT_DIRECTIONAL) positionM = centre - direction * (radiusM * 2.0f);

        g.radiance = glm::vec4(light.colour * light.intensity, 0.0f);
        g.spot = glm::vec4(std::cos(glm::radians(light.spotInnerDeg)), std::cos(glm::radians(light.spotOuterDeg)), 0, 0);
        g.directionShadow = glm::vec4(direction, -1.0f);
        g.positionType = glm::vec4(positionM, float(type));

        const bool canShadow = light.castsShadow && type != DERMIS_LIGHT_POINT &&
                               static_cast<int>(setup.shadowedLights.size()) < DERMIS_MAX_SHADOWED_LIGHTS;
        if (!canShadow) continue;

        const glm::mat4 lightFromWorld = glm::lookAt(positionM, positionM + direction, anyPerpendicularUp(direction));
        // Depth range along the axis that encloses the scene's bounding sphere.
        const float centreDepthM = glm::dot(centre - positionM, direction);
        const float nearM = std::max(centreDepthM - radiusM, 0.01f);
        const float farM = std::max(centreDepthM + radiusM, nearM + 0.01f);
        glm::mat4 clipFromLight;
        float texelM = 0.0f;
        if (type == DERMIS_LIGHT_DIRECTIONAL) {
            clipFromLight = glm::ortho(-radiusM, radiusM, -radiusM, radiusM, nearM, farM);
            texelM = 2.0f * radiusM / float(shadows.mapSize);
        } else {
            const float halfAngleRad = glm::radians(std::clamp(light.spotOuterDeg, 1.0f, 89.0f));
            clipFromLight = glm::perspective(2.0f * halfAngleRad, 1.0f, nearM, farM);
            texelM = 2.0f * std::tan(halfAngleRad) / float(shadows.mapSize);  // per metre of depth
        }
        g.shadowClipFromWorld = clipFromLight * lightFromWorld;
        g.shadowParams = glm::vec4(shadows.biasConstantM, shadows.biasSlopeTexels, texelM, float(shadows.filter));
        g.shadowDepth = glm::vec4(nearM, farM, type == DERMIS_LIGHT_DIRECTIONAL ? 1.0f : 0.0f, 0.0f);
        g.directionShadow.w = float(setup.shadowedLights.size());
        setup.shadowedLights.push_back(i);
    }
    return setup;
}

}  // namespace dermis
