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
    // Into one period first, so that huge coordinates keep their precision and
    // fit an int: [0, 1) for repeat, [0, 2) for mirrored repeat (its period).
    float inRange = std::clamp(coordinate, 0.0f, 1.0f);
    if (wrap == TextureWrap::Repeat) inRange = coordinate - std::floor(coordinate);
    if (wrap == TextureWrap::MirroredRepeat) inRange = coordinate - 2.0f * std::floor(coordinate * 0.5f);
    const float texel = inRange * float(size) - 0.5f;
    const float firstTexel = std::floor(texel);
    const int first = static_cast<int>(firstTexel);
    const auto index = [&](int i) {
        if (wrap == TextureWrap::ClampToEdge) return std::clamp(i, 0, size - 1);
        if (wrap == TextureWrap::MirroredRepeat) {  // texels 0..size-1, then size-1..0, repeating
            const int period = 2 * size;
            const int r = ((i % period) + period) % period;
            return r < size ? r : period - 1 - r;
        }
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
