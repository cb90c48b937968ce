#include "core/ImageSampling.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

struct AxisTaps {
    int first = 0;
    int second = 0;
    float fraction = 0.0f;  // the second tap's weight
};

AxisTaps axisTaps(float coordinate, int size, TextureWrap wrap) {
    // Repeat first, so that huge coordinates keep their precision and fit an int.
    const float inRange = wrap == TextureWrap::Repeat ? coordinate - std::floor(coordinate) : std::clamp(coordinate, 0.0f, 1.0f);
    const float texel = inRange * float(size) - 0.5f;
    const float firstTexel = std::floor(texel);
    const int first = static_cast<int>(firstTexel);
    const auto index = [&](int i) {
        if (wrap == TextureWrap::ClampToEdge) return std::clamp(i, 0, size - 1);
        const int r = i % size;
        return r < 0 ? r + size : r;
    };
    return {index(first), index(first + 1), texel - firstTexel};
}

}  // namespace

glm::vec4 sampleBilinear(const Image& image, const glm::vec2& uv, const glm::vec4& fallback, TextureWrap wrapU,
                         TextureWrap wrapV) {
    if (image.empty() || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return fallback;
    const AxisTaps x = axisTaps(uv.x, image.width, wrapU);
    const AxisTaps y = axisTaps(uv.y, image.height, wrapV);
    const glm::vec4 top = glm::mix(image.at(x.first, y.first), image.at(x.second, y.first), x.fraction);
    const glm::vec4 bottom = glm::mix(image.at(x.first, y.second), image.at(x.second, y.second), x.fraction);
    return glm::mix(top, bottom, y.fraction);
}

}  // namespace dermis
