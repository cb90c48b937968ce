#include "reference/PixelSampling.h"

#include "core/Hash.h"
#include "raytrace/Sampling.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdint>

namespace dermis::reference {

int strataPerSide(int samplesPerPixel) {
    if (samplesPerPixel < 1 || samplesPerPixel > kMaxSamplesPerPixel) return 0;
    const int n = static_cast<int>(std::lround(std::sqrt(double(samplesPerPixel))));
    return n * n == samplesPerPixel ? n : 0;
}

std::vector<glm::vec2> subSampleOffsets(int x, int y, int samplesPerPixel) {
    const int n = strataPerSide(samplesPerPixel);
    if (n <= 1) return {glm::vec2(0.5f)};
    return raytrace::jitteredGrid(n, lowbias32(uint32_t(x) * 0x9e3779b9U ^ lowbias32(uint32_t(y))));
}

CameraRays::CameraRays(const Camera& camera, int width, int height) {
    const glm::mat4 worldFromView = glm::inverse(glm::lookAt(camera.positionM, camera.targetM, camera.up));
    const glm::mat3 rotation(worldFromView);
    const float tanHalfFov = std::tan(0.5f * glm::radians(camera.verticalFovDeg));
    const float aspect = float(width) / float(height);
    mOriginM = glm::vec3(worldFromView[3]);
    // ndc x = 2 px / width - 1 and ndc y = 1 - 2 py / height, scaled onto the z = -1 plane.
    mTopLeftDirection = rotation * glm::vec3(-tanHalfFov * aspect, tanHalfFov, -1.0f);
    mDirectionPerPixelX = rotation * glm::vec3(2.0f * tanHalfFov * aspect / float(width), 0.0f, 0.0f);
    mDirectionPerPixelY = rotation * glm::vec3(0.0f, -2.0f * tanHalfFov / float(height), 0.0f);
}

Ray CameraRays::through(float px, float py) const {
    return Ray{mOriginM, mTopLeftDirection + px * mDirectionPerPixelX + py * mDirectionPerPixelY};
}

bool offsetRayOnPlane(const Ray& ray, const glm::vec3& directionStep, const glm::vec3& pointM,
                      const glm::vec3& normal, glm::vec3* hitM) {
    const glm::vec3 direction = ray.direction + directionStep;
    const float denominator = glm::dot(normal, direction);
    if (denominator == 0.0f || !std::isfinite(denominator)) return false;
    const float t = glm::dot(normal, pointM - ray.origin) / denominator;
    if (!(t > 0.0f) || !std::isfinite(t)) return false;
    *hitM = ray.origin + t * direction;
    return true;
}

}  // namespace dermis::reference
