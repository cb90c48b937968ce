#include "plan/ShadowCasters.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

glm::vec3 corner(const Bounds& b, int i) {
    return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

// A box as a directional light's map sees it: a rectangle on the map's plane
// and a depth interval along the light.
struct LightSpaceBox {
    glm::vec2 min{INFINITY};
    glm::vec2 max{-INFINITY};
    float nearM = INFINITY;
    float farM = -INFINITY;
};

LightSpaceBox toLightSpace(const Bounds& b, const glm::vec3& axisU, const glm::vec3& axisV, const glm::vec3& direction) {
    LightSpaceBox out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p = corner(b, i);
        const glm::vec2 onPlane(glm::dot(p, axisU), glm::dot(p, axisV));
        out.min = glm::min(out.min, onPlane);
        out.max = glm::max(out.max, onPlane);
        out.nearM = std::min(out.nearM, glm::dot(p, direction));
        out.farM = std::max(out.farM, glm::dot(p, direction));
    }
    return out;
}

// Whether `caster` can shade `receiver` under a directional light of
// tan(angular radius) `tanRadius` whose map has texels `texelM` across.
bool shadesDirectional(const LightSpaceBox& caster, const LightSpaceBox& receiver, float tanRadius, float texelM) {
    if (!(caster.nearM < receiver.farM)) return false;
    const float marginM = (receiver.farM - caster.nearM) * tanRadius + kFilterMarginTexels * texelM;
    return caster.min.x <= receiver.max.x + marginM && caster.max.x >= receiver.min.x - marginM &&
           caster.min.y <= receiver.max.y + marginM && caster.max.y >= receiver.min.y - marginM;
}

float distanceToSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float lengthSquared = glm::dot(ab, ab);
    const float t = lengthSquared > 0.0f ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

float boundingRadius(const Bounds& b) { return 0.5f * glm::length(b.size()); }

// Whether `caster` can shade `receiver` from a spot or point light at
// `lightM` of radius `lightRadiusM` whose texels span `texelPerM` per metre of depth.
bool shadesFromPoint(const Bounds& caster, const Bounds& receiver, const glm::vec3& lightM, float lightRadiusM,
                     float texelPerM) {
    const float receiverRadiusM = boundingRadius(receiver);
    const float filterM = kFilterMarginTexels * texelPerM * (glm::length(receiver.centre() - lightM) + receiverRadiusM);
    const float capsuleRadiusM = receiverRadiusM + lightRadiusM + filterM;
    return distanceToSegment(caster.centre(), lightM, receiver.centre()) <= capsuleRadiusM + boundingRadius(caster);
}

}  // namespace

ShadowCasters chooseShadowCasters(const gpu::GpuLight& light, const std::vector<Bounds>& bounds,
                                  const std::vector<bool>& visible) {
    const size_t count = std::min(bounds.size(), visible.size());
    ShadowCasters out;
    out.culledBecause.assign(count, "");
    const bool directional = int(light.type) == DERMIS_LIGHT_DIRECTIONAL;
    const glm::vec3 direction = light.direction;
    // The map's axes, as the shader takes them: the first two rows of its clip matrix.
    const glm::mat4& m = light.shadowClipFromWorld;
    const glm::vec3 axisU = glm::normalize(glm::vec3(m[0][0], m[1][0], m[2][0]));
    const glm::vec3 axisV = glm::normalize(glm::vec3(m[0][1], m[1][1], m[2][1]));
    std::vector<LightSpaceBox> boxes;
    if (directional) {
        for (size_t c = 0; c < count; ++c) boxes.push_back(toLightSpace(bounds[c], axisU, axisV, direction));
    }
    const bool anyReceiver = std::find(visible.begin(), visible.begin() + std::ptrdiff_t(count), true) !=
                             visible.begin() + std::ptrdiff_t(count);
    for (size_t c = 0; c < count; ++c) {
        bool keep = visible[c];
        for (size_t r = 0; r < count && !keep; ++r) {
            if (!visible[r]) continue;
            keep = directional ? shadesDirectional(boxes[c], boxes[r], light.size, light.shadowTexelM)
                               : shadesFromPoint(bounds[c], bounds[r], light.positionM, light.size,
                                                 light.shadowTexelM);
        }
        if (!keep) {
            out.culledBecause[c] = !anyReceiver  ? "no character on screen to receive its shadow"
                                   : directional ? "its light-space footprint meets no visible character's, or lies beyond them"
                                                 : "it is outside every visible character's shadow volume from the light";
            continue;
        }
        out.reach = out.kept.empty() ? bounds[c]
                                     : Bounds{glm::min(out.reach.min, bounds[c].min), glm::max(out.reach.max, bounds[c].max)};
        out.kept.push_back(static_cast<int>(c));
    }
    return out;
}

}  // namespace dermis
