#include "reference/TextureSampling.h"

#include <cmath>

namespace dermis::reference {
namespace {

int wrap(int i, int size) {
    const int r = i % size;
    return r < 0 ? r + size : r;
}

}  // namespace

float srgbToLinear(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

Image decodeToLinear(const Image& image) {
    if (image.colourSpace == ColourSpace::Linear) return image;
    Image linear = image;
    linear.colourSpace = ColourSpace::Linear;
    for (glm::vec4& texel : linear.texels) {
        for (int c = 0; c < 3; ++c) texel[c] = srgbToLinear(texel[c]);
    }
    return linear;
}

glm::vec4 sampleBilinear(const Image& image, const glm::vec2& uv, const glm::vec4& fallback) {
    if (image.empty() || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return fallback;
    // Repeat first, so that huge coordinates keep their precision and fit an int.
    const glm::vec2 wrapped = uv - glm::floor(uv);
    const float x = wrapped.x * float(image.width) - 0.5f;
    const float y = wrapped.y * float(image.height) - 0.5f;
    const float x0f = std::floor(x);
    const float y0f = std::floor(y);
    const float fx = x - x0f;
    const float fy = y - y0f;
    const int x0 = wrap(static_cast<int>(x0f), image.width);
    const int y0 = wrap(static_cast<int>(y0f), image.height);
    const int x1 = wrap(x0 + 1, image.width);
    const int y1 = wrap(y0 + 1, image.height);
    const glm::vec4 top = glm::mix(image.at(x0, y0), image.at(x1, y0), fx);
    const glm::vec4 bottom = glm::mix(image.at(x0, y1), image.at(x1, y1), fx);
    return glm::mix(top, bottom, fy);
}

}  // namespace dermis::reference
