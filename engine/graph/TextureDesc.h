#pragma once
// What a render-graph texture is, independent of any graphics API.

#include <cstdint>
#include <string_view>

namespace dermis::graph {

enum class TextureFormat : uint8_t {
    Rgba8Srgb,   // albedo
    Rgba8,       // 8-bit data, tone-mapped output
    Rgba16F,     // lighting, LEAN moments
    Rg16F,
    R16F,
    R32F,        // linear depth (shadow maps)
    R32UI,       // packed keys (G-buffer depth key)
    Rgba32F,     // AOV read-back
    R8,          // AO
    Depth24Stencil8,
    Depth32F,
    Rgba32UI,    // eight halves packed in pairs (the LEAN variants' SSS chain)
};

std::string_view formatName(TextureFormat format);
bool isDepthFormat(TextureFormat format);
bool isIntegerFormat(TextureFormat format);  // needs nearest filtering and (u)int samplers

struct TextureDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    TextureFormat format = TextureFormat::Rgba8;

    bool operator==(const TextureDesc& o) const {
        return width == o.width && height == o.height && format == o.format;
    }
    bool operator!=(const TextureDesc& o) const { return !(*this == o); }
};

}  // namespace dermis::graph
