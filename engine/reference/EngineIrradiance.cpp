#include "reference/EngineIrradiance.h"

#include <algorithm>
#include <cmath>

namespace dermis::reference {

Result<std::unique_ptr<EngineIrradiance>> EngineIrradiance::create(const CharacterSurface& surface,
                                                                     const Image& texture) {
    const std::string what = "engine irradiance of '" + surface.name() + "'";
    if (texture.width <= 0 || texture.height <= 0 ||
        texture.texels.size() != size_t(texture.width) * size_t(texture.height)) {
        return makeError(what, "the image's size does not match its texels");
    }
    for (const glm::vec4& t : texture.texels) {
        if (!std::isfinite(t.r) || !std::isfinite(t.g) || !std::isfinite(t.b) || !std::isfinite(t.a)) {
            return makeError(what, "a texel is not finite");
        }
    }
    std::unique_ptr<EngineIrradiance> engine(new EngineIrradiance());
    engine->mSurface = &surface;
    engine->mTexture = texture;
    const int w = texture.width, h = texture.height;
    engine->mHasValue.assign(texture.texels.size(), 0);
    for (size_t i = 0; i < texture.texels.size(); ++i) engine->mHasValue[i] = texture.texels[i].a > 0.0f;
    // Fill from the covered texels of the original only, so that fills do not chain.
    const int reach = kEmptyTexelReachTexels;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (texture.at(x, y).a > 0.0f) continue;
            int best = reach * reach + 1;
            glm::vec4 value(0.0f);
            for (int dy = -reach; dy <= reach; ++dy) {
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int sx = x + dx, sy = y + dy;
                    const int d2 = dx * dx + dy * dy;
                    if (sx < 0 || sy < 0 || sx >= w || sy >= h || d2 >= best || !(texture.at(sx, sy).a > 0.0f)) continue;
                    best = d2;
                    value = texture.at(sx, sy);
                }
            }
            if (best <= reach * reach) {
                engine->mTexture.at(x, y) = value;
                engine->mHasValue[size_t(y) * size_t(w) + size_t(x)] = 1;
            } else {
                ++engine->mUnfilledTexels;
            }
        }
    }
    return engine;
}

glm::vec3 EngineIrradiance::sampleAt(const glm::vec2& rawUv) const {
    const int w = mTexture.width, h = mTexture.height;
    if (!std::isfinite(rawUv.x) || !std::isfinite(rawUv.y)) {
        ++mEmptyReads;
        return glm::vec3(0.0f);
    }
    const float x = std::clamp(rawUv.x, 0.0f, 1.0f) * float(w) - 0.5f;
    const float y = std::clamp(rawUv.y, 0.0f, 1.0f) * float(h) - 0.5f;
    const float x0f = std::floor(x), y0f = std::floor(y);
    const float fx = x - x0f, fy = y - y0f;
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const int tx = std::clamp(static_cast<int>(x0f) + i, 0, w - 1);
            const int ty = std::clamp(static_cast<int>(y0f) + j, 0, h - 1);
            if (!mHasValue[size_t(ty) * size_t(w) + size_t(tx)]) continue;
            const float wt = (i ? fx : 1.0f - fx) * (j ? fy : 1.0f - fy);
            sum += wt * glm::vec3(mTexture.at(tx, ty));
            weight += wt;
        }
    }
    if (!(weight > 0.0f)) {
        ++mEmptyReads;
        return glm::vec3(0.0f);
    }
    return sum / weight;
}

glm::vec3 EngineIrradiance::valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility*) const {
    return sampleAt(mSurface->rawUvAt(triangle, b.x, b.y));
}

}  // namespace dermis::reference
