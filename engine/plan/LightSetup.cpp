#include "plan/LightSetup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

glm::vec3 anyPerpendicularUp(const glm::vec3& direction) {
    return std::fabs(direction.y) < 0.95f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// The smallest depth of a box's corners along `axis`, from `origin`.
float nearestDepthAlong(const Bounds& box, const glm::vec3& origin, const glm::vec3& axis) {
    float nearest = INFINITY;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z);
        nearest = std::min(nearest, glm::dot(p - origin, axis));
    }
    return nearest;
}

float distanceToBox(const Bounds& box, const glm::vec3& p) {
    return glm::length(glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f)));
}

}  // namespace

uint32_t cubeShadowFaceSize(int mapSize) { return static_cast<uint32_t>(std::max(mapSize / 2, 1)); }

LightSetup setupLights(const std::vector<Light>& lights, const Bounds& receivers, const ShadowSettings& shadows,
                       const std::vector<Bounds>& casterReach) {
    LightSetup setup;
    const glm::vec3 centre = receivers.centre();
    const float radiusM = std::max(0.5f * glm::length(receivers.size()), 1e-3f);
    const int count = std::min<int>(static_cast<int>(lights.size()), DERMIS_MAX_LIGHTS);
    setup.lightCount = count;
    setup.sources.assign(lights.begin(), lights.begin() + count);
    for (int i = 0; i < count; ++i) {
        const Light& light = lights[static_cast<size_t>(i)];
        gpu::GpuLight& g = setup.block.lights[i];
        const glm::vec3 direction = glm::normalize(light.direction);
        const int type = static_cast<int>(light.type);  // DERMIS_LIGHT_* (scene/SceneEnums.h)
        const bool hasReach = static_cast<size_t>(i) < casterReach.size();
        const Bounds& reach = hasReach ? casterReach[static_cast<size_t>(i)] : receivers;
        glm::vec3 positionM = light.positionM;
        if (type == DERMIS_LIGHT_DIRECTIONAL) {
            // Casters nearer the light than the receivers' sphere move the origin back by as much.
            const float beyondM = std::max(-nearestDepthAlong(reach, centre, direction) - radiusM, 0.0f);
            positionM = centre - direction * (radiusM * 2.0f + beyondM);
        }

        g.radiance = light.colour * light.intensity;
        g.spotCosInner = std::cos(glm::radians(light.spotInnerDeg));
        g.spotCosOuter = std::cos(glm::radians(light.spotOuterDeg));
        g.direction = direction;
        g.shadowSlot = -1.0f;
        g.positionM = positionM;
        g.type = float(type);
        g.size = type == DERMIS_LIGHT_DIRECTIONAL ? std::tan(glm::radians(0.5f * light.angularDiameterDeg)) : light.radiusM;

        const bool canShadow =
            light.castsShadow && static_cast<int>(setup.shadowedLights.size()) < DERMIS_MAX_SHADOWED_LIGHTS;
        if (!canShadow) continue;
        g.shadowBiasM = shadows.biasConstantM;
        g.shadowSlopeBiasTexels = shadows.biasSlopeTexels;
        g.shadowFilter = float(shadows.filter);
        g.shadowSlot = float(setup.shadowedLights.size());
        setup.shadowedLights.push_back(i);
        const bool delta = !(g.size > 0.0f);
        const ShadowCode needs = shadows.filter != ShadowFilter::Pcss        ? ShadowCode::EveryFilter
                                 : delta && type == DERMIS_LIGHT_POINT ? ShadowCode::EveryFilter
                                 : delta                               ? ShadowCode::HardEdges
                                                                       : ShadowCode::SoftEdges;
        setup.shadowCode = std::max(setup.shadowCode, needs);
        if (type == DERMIS_LIGHT_POINT) {
            // Cube faces: every caster lies beyond the nearer of the receivers' sphere and
            // the casters' box, and a face's axial depth is at least 1/sqrt(3) of the distance.
            const float distanceM = glm::length(centre - positionM);
            const float nearestM = std::min(distanceM - radiusM, distanceToBox(reach, positionM));
            const float nearM = std::max(nearestM * 0.5f, 1e-3f);
            g.shadowNearM = nearM;
            g.shadowFarM = std::max(distanceM + radiusM, nearM + 0.01f);
            g.shadowTexelM = 2.0f / float(cubeShadowFaceSize(shadows.mapSize));  // per metre of distance
            g.cubeShadow = 1.0f;
            g.shadowClipFromWorld = glm::mat4(1.0f);  // unused: the faces' projections are the shaders'
            continue;
        }

        const glm::mat4 lightFromWorld = glm::lookAt(positionM, positionM + direction, anyPerpendicularUp(direction));
        // Depth range along the axis that encloses the receivers' bounding sphere and the casters.
        const float centreDepthM = glm::dot(centre - positionM, direction);
        const float nearestM = std::min(centreDepthM - radiusM, nearestDepthAlong(reach, positionM, direction));
        const float nearM = std::max(nearestM, 0.01f);
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
        g.shadowTexelM = texelM;
        g.shadowNearM = nearM;
        g.shadowFarM = farM;
        g.shadowOrthographic = type == DERMIS_LIGHT_DIRECTIONAL ? 1.0f : 0.0f;
    }
    return setup;
}

}  // namespace dermis
