#include "raytrace/Sampling.h"

#include "core/Hash.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace dermis::raytrace {

float unitFloatFromHash(uint32_t hash) { return float(hash >> 8) * (1.0f / 16777216.0f); }

std::vector<glm::vec2> jitteredGrid(int strataPerSide, uint32_t seed) {
    const int n = strataPerSide;
    std::vector<glm::vec2> points;
    points.reserve(size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const uint32_t h = lowbias32(seed ^ uint32_t(j * n + i) * 0x85ebca6bU);
            const glm::vec2 jitter(unitFloatFromHash(h), unitFloatFromHash(lowbias32(h)));
            points.push_back((glm::vec2(float(i), float(j)) + jitter) / float(n));
        }
    }
    return points;
}

glm::vec2 concentricDisc(const glm::vec2& unitSquare) {
    const float a = 2.0f * unitSquare.x - 1.0f;
    const float b = 2.0f * unitSquare.y - 1.0f;
    const float quarterPi = 0.25f * glm::pi<float>();
    float r = 0.0f;
    float phi = 0.0f;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = quarterPi * (b / a);
    } else if (b != 0.0f) {
        r = b;
        phi = 2.0f * quarterPi - quarterPi * (a / b);
    }
    return glm::vec2(r * std::cos(phi), r * std::sin(phi));
}

}  // namespace dermis::raytrace
