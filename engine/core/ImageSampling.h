#pragma once
// Bilinear reads of an Image as the GPU makes them: texel centres at
// (i + 0.5) / size, row 0 at v = 0, GL_REPEAT or GL_CLAMP_TO_EDGE per axis.
// Shared by the CPU reference's texture reads (reference/TextureSampling.h)
// and the prefiltered environment map (env/PrefilteredEnvironment.h).

#include "core/Image.h"

#include <glm/glm.hpp>

namespace dermis {

enum class TextureWrap {
    Repeat,       // GL_REPEAT
    ClampToEdge,  // GL_CLAMP_TO_EDGE
};

// Bilinear read at uv. An empty image, or a non-finite uv, reads as `fallback`.
glm::vec4 sampleBilinear(const Image& image, const glm::vec2& uv, const glm::vec4& fallback,
                         TextureWrap wrapU = TextureWrap::Repeat, TextureWrap wrapV = TextureWrap::Repeat);

}  // namespace dermis
