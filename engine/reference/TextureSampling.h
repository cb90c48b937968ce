#pragma once
// Texture reads as the GPU makes them for the renderer's maps: bilinear, GL_REPEAT,
// texel centres at (i + 0.5) / size, row 0 at v = 0 (engine/render/GpuScene.cpp
// uploads images top row first, so texture(uv) follows glTF's convention). One
// level (core/ImageSampling.h's sampleBilinear, GL_REPEAT on both axes by
// default); MipPyramid.h builds the levels and the trilinear read on it.

#include "core/Image.h"
#include "core/ImageSampling.h"

#include <glm/glm.hpp>

namespace dermis::reference {

// The sRGB transfer function's inverse (IEC 61966-2-1), as an sRGB texture format decodes.
float srgbToLinear(float encoded);

// A copy with RGB decoded to linear (alpha kept), marked ColourSpace::Linear; an
// image already linear is returned unchanged.
Image decodeToLinear(const Image& image);

using dermis::sampleBilinear;

}  // namespace dermis::reference
