#include "BumpMap.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace dermis::test {

Image bumpNormalMap(int size, int terms, float minPeriodTexels, float maxPeriodTexels, float slopeStdDev,
                    unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    struct Wave {
        glm::vec2 frequency;  // cycles per map
        float phase;
    };
    std::vector<Wave> waves;
    while (static_cast<int>(waves.size()) < terms) {
        const float angle = glm::two_pi<float>() * unit(random);
        const float period = minPeriodTexels + (maxPeriodTexels - minPeriodTexels) * unit(random);
        const glm::vec2 f = glm::round(glm::vec2(std::cos(angle), std::sin(angle)) * (float(size) / period));
        if (f == glm::vec2(0.0f)) continue;
        waves.push_back({f, glm::two_pi<float>() * unit(random)});
    }
    // A slope term c * cos(...) along the unit direction contributes c^2/4 to
    // each axis's variance on average over directions; sum to slopeStdDev^2.
    const float amplitude = slopeStdDev * std::sqrt(4.0f / float(terms));
    Image image;
    image.width = size;
    image.height = size;
    image.texels.resize(static_cast<size_t>(size) * static_cast<size_t>(size));
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            glm::vec2 slope(0.0f);
            for (const Wave& w : waves) {
                const float t = glm::two_pi<float>() * (w.frequency.x * (x + 0.5f) + w.frequency.y * (y + 0.5f)) / size;
                slope += amplitude * glm::normalize(w.frequency) * std::cos(t + w.phase);
            }
            const glm::vec3 n = glm::normalize(glm::vec3(slope, 1.0f));
            image.at(x, y) = glm::vec4(n * 0.5f + 0.5f, 1.0f);
        }
    }
    return image;
}

}  // namespace dermis::test
