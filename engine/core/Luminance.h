#pragma once
// The Rec. 709 luminance of linear RGB.

#include <glm/glm.hpp>

namespace dermis {

inline float relativeLuminance(const glm::vec3& rgb) { return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b; }

}  // namespace dermis
