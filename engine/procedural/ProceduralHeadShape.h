#pragma once
// The procedural head's skull, face and neck as a signed distance field, and
// the landmarks that the maps colour (cheeks, lips, brows). Metres, origin at
// the centre of the head, +Y up, face toward +Z. Landmarks are given for the
// right side (+X); the head is mirror-symmetric in X.

#include <glm/glm.hpp>

namespace dermis {

namespace head {
inline const glm::vec3 kEyeM{0.033f, 0.012f, 0.073f};      // centre of the (closed) eye
inline const glm::vec3 kBrowM{0.034f, 0.035f, 0.089f};     // middle of the eyebrow
inline const glm::vec3 kCheekM{0.046f, -0.022f, 0.074f};   // the flush of the cheek
inline const glm::vec3 kNoseTipM{0.0f, -0.024f, 0.121f};
inline const glm::vec3 kMouthM{0.0f, -0.058f, 0.100f};     // the line between the lips
inline const glm::vec3 kChinM{0.0f, -0.098f, 0.078f};
constexpr float kLipHalfWidthM = 0.023f;
constexpr float kNeckBottomM = -0.19f;
}  // namespace head

// Negative inside. Not an exact distance (blends and tapers bend it), but
// continuous, with a gradient that points out of the surface.
float headSignedDistance(const glm::vec3& pM);

// The outward unit normal, from the field's gradient.
glm::vec3 headSurfaceNormal(const glm::vec3& pM);

}  // namespace dermis
