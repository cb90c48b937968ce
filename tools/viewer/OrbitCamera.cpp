#include "viewer/OrbitCamera.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace dermis::viewer {
namespace {
constexpr float kRadiansPerPixel = 0.006f;
constexpr float kMaxPitch = 1.55f;  // about 89 degrees
constexpr float kDollyPerStep = 0.9f;

glm::vec3 anyPerpendicular(const glm::vec3& v) {
    const glm::vec3 other = std::abs(v.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(v, other));
}
}  // namespace

OrbitCamera::OrbitCamera(const Camera& camera) : mTarget(camera.targetM) {
    const float upLength = glm::length(camera.up);
    mUp = upLength > 0.0f ? camera.up / upLength : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 offset = camera.positionM - camera.targetM;
    mDistance = std::max(glm::length(offset), 1e-3f);
    const glm::vec3 direction = offset / mDistance;
    const float along = std::clamp(glm::dot(direction, mUp), -1.0f, 1.0f);
    mPitch = std::clamp(std::asin(along), -kMaxPitch, kMaxPitch);
    const glm::vec3 horizontal = direction - along * mUp;
    mAxisX = glm::length(horizontal) > 1e-4f ? glm::normalize(horizontal) : anyPerpendicular(mUp);
    mAxisZ = glm::cross(mAxisX, mUp);
    mMinDistance = std::max(camera.nearM * 1.05f, 1e-3f);
    mMaxDistance = std::max(camera.farM * 0.9f, mMinDistance);
    mDistance = std::clamp(mDistance, mMinDistance, mMaxDistance);
}

glm::vec3 OrbitCamera::eye() const {
    const glm::vec3 direction = std::cos(mPitch) * (std::cos(mYaw) * mAxisX + std::sin(mYaw) * mAxisZ) +
                                std::sin(mPitch) * mUp;
    return mTarget + mDistance * direction;
}

void OrbitCamera::orbit(float dxPx, float dyPx) {
    mYaw = std::remainder(mYaw + dxPx * kRadiansPerPixel, 2.0f * glm::pi<float>());
    mPitch = std::clamp(mPitch + dyPx * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dxPx, float dyPx, float viewportHeightPx, float verticalFovDeg) {
    if (viewportHeightPx <= 0.0f) return;
    const glm::vec3 forward = glm::normalize(mTarget - eye());
    const glm::vec3 right = glm::normalize(glm::cross(forward, mUp));
    const glm::vec3 up = glm::cross(right, forward);
    const float metresPerPixel = 2.0f * mDistance * std::tan(glm::radians(verticalFovDeg) * 0.5f) / viewportHeightPx;
    mTarget += (-dxPx * right + dyPx * up) * metresPerPixel;
}

void OrbitCamera::dolly(float steps) {
    mDistance = std::clamp(mDistance * std::pow(kDollyPerStep, steps), mMinDistance, mMaxDistance);
}

void OrbitCamera::applyTo(Camera& camera) const {
    camera.positionM = eye();
    camera.targetM = mTarget;
    camera.up = mUp;
}

}  // namespace dermis::viewer
