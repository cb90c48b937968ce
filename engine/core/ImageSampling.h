#pragma once
// Bilinear reads of an Image as the GPU makes them: texel centres at
// (i + 0.5) / size, row 0 at v = 0, GL_REPEAT, GL_CLAMP_TO_EDGE or
// GL_MIRRORED_REPEAT per axis (glTF 2.0 samplers' three wrap modes).
// Shared by the CPU reference's texture reads (reference/TextureSampling.h)
// and the prefiltered environment map (env/PrefilteredEnvironment.h).

#include "core/Image.h"

#include <glm/glm.hpp>

namespace dermis {

enum class TextureWrap {
    Repeat,          // GL_REPEAT
    ClampToEdge,     // GL_CLAMP_TO_EDGE
    MirroredRepeat,  // GL_MIRRORED_REPEAT: every other period reversed
};

// Both axes of a map's sampler (glTF 2.0 sampler.wrapS, wrapT).
struct TextureWraps {
    TextureWrap s = TextureWrap::Repeat;
    TextureWrap t = TextureWrap::Repeat;
    bool operator==(const TextureWraps& o) const { return s == o.s && t == o.t; }
};

// Bilinear read at uv. An empty image, or a non-finite uv, reads as `fallback`.
glm::vec4 sampleBilinear(const Image& image, const glm::vec2& uv, const glm::vec4& fallback,
                         TextureWrap wrapU = TextureWrap::Repeat, TextureWrap wrapV = TextureWrap::Repeat);

}  // namespace dermis
