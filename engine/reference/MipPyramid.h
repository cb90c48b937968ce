#pragma once
// A map's mip pyramid and its trilinear read, as the renderer's textures are
// sampled (engine/render/GpuScene.cpp: glGenerateTextureMipmap, then
// GL_LINEAR_MIPMAP_LINEAR with the map's wrap modes). Levels halve (floor) down to 1x1;
// each texel of level k+1 is a bilinear tap of level k at its centre, which for
// even sizes is the 2x2 box of glGenerateMipmap. Level 0 is the image as given
// (sRGB maps are decoded first, as the GPU filters sRGB textures in linear).
// The level of detail is the GPU's (OpenGL 4.5 §8.14.1): lambda = log2 of the
// longer of the two pixel-step UV derivatives, in level-0 texels.

#include "core/Image.h"
#include "core/ImageSampling.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis::reference {

// How far the map UV moves across one pixel, along the image's x and y.
struct MapFootprint {
    glm::vec2 uvPerPixelX{0.0f};
    glm::vec2 uvPerPixelY{0.0f};
};

class MipPyramid {
public:
    MipPyramid() = default;
    explicit MipPyramid(Image level0, TextureWraps wraps = {});

    bool empty() const { return mLevels.empty(); }
    size_t levelCount() const { return mLevels.size(); }
    const Image& level(size_t i) const { return mLevels[i]; }
    const TextureWraps& wraps() const { return mWraps; }

    // lambda for this footprint (unclamped; <= 0 reads level 0).
    float levelOfDetail(const MapFootprint& footprint) const;
    // Bilinear at level 0: the reference's sample points (no footprint).
    glm::vec4 sample(const glm::vec2& uv, const glm::vec4& fallback) const;
    // Trilinear at the footprint's level of detail.
    glm::vec4 sample(const glm::vec2& uv, const MapFootprint& footprint, const glm::vec4& fallback) const;

private:
    std::vector<Image> mLevels;
    TextureWraps mWraps;
};

}  // namespace dermis::reference
