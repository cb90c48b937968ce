#include "reference/SampleValues.h"

namespace dermis::reference {

glm::vec3 albedoPower(const glm::vec3& albedo, float exponent) {
    if (exponent <= 0.0f) return glm::vec3(1.0f);
    if (exponent == 1.0f) return glm::max(albedo, glm::vec3(0.0f));
    if (exponent == 0.5f) return glm::sqrt(glm::max(albedo, glm::vec3(0.0f)));
    return glm::pow(glm::max(albedo, glm::vec3(0.0f)), glm::vec3(exponent));
}

glm::vec3 ExactLightingValues::valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const {
    const SurfacePoint point = mSurface->pointAt(triangle, b.x, b.y);
    return mLighting->irradiance(point, visibility, mSampleSet) * albedoPower(point.albedo, mMix);
}

}  // namespace dermis::reference
