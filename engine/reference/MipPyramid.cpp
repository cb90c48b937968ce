#include "reference/MipPyramid.h"

#include "reference/TextureSampling.h"

#include <algorithm>
#include <cmath>

namespace dermis::reference {
namespace {

Image halve(const Image& source) {
    Image next;
    next.width = std::max(1, source.width / 2);
    next.height = std::max(1, source.height / 2);
    next.colourSpace = source.colourSpace;
    next.texels.resize(size_t(next.width) * size_t(next.height));
    for (int y = 0; y < next.height; ++y) {
        for (int x = 0; x < next.width; ++x) {
            const glm::vec2 uv((float(x) + 0.5f) / float(next.width), (float(y) + 0.5f) / float(next.height));
            next.at(x, y) = sampleBilinear(source, uv, glm::vec4(0.0f));
        }
    }
    return next;
}

}  // namespace

MipPyramid::MipPyramid(Image level0, TextureWraps wraps) : mWraps(wraps) {
    if (level0.empty()) return;
    mLevels.push_back(std::move(level0));
    while (mLevels.back().width > 1 || mLevels.back().height > 1) mLevels.push_back(halve(mLevels.back()));
}

float MipPyramid::levelOfDetail(const MapFootprint& footprint) const {
    const glm::vec2 size(float(mLevels[0].width), float(mLevels[0].height));
    const float rho = std::max(glm::length(footprint.uvPerPixelX * size), glm::length(footprint.uvPerPixelY * size));
    return std::log2(rho);
}

glm::vec4 MipPyramid::sample(const glm::vec2& uv, const glm::vec4& fallback) const {
    if (empty()) return fallback;
    return sampleBilinear(mLevels[0], uv, fallback, mWraps.s, mWraps.t);
}

glm::vec4 MipPyramid::sample(const glm::vec2& uv, const MapFootprint& footprint, const glm::vec4& fallback) const {
    if (empty()) return fallback;
    const float lambda = levelOfDetail(footprint);
    // NaN (a degenerate footprint) reads level 0, like a zero footprint; +inf the last level.
    if (!(lambda > 0.0f)) return sampleBilinear(mLevels[0], uv, fallback, mWraps.s, mWraps.t);
    const float last = float(mLevels.size() - 1);
    const float d = std::min(lambda, last);
    const auto lower = static_cast<size_t>(std::floor(d));
    const size_t upper = std::min(lower + 1, mLevels.size() - 1);
    const float blend = d - float(lower);
    const glm::vec4 a = sampleBilinear(mLevels[lower], uv, fallback, mWraps.s, mWraps.t);
    if (blend == 0.0f || upper == lower) return a;
    return glm::mix(a, sampleBilinear(mLevels[upper], uv, fallback, mWraps.s, mWraps.t), blend);
}

}  // namespace dermis::reference
