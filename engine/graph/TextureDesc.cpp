#include "graph/TextureDesc.h"

namespace dermis::graph {

std::string_view formatName(TextureFormat format) {
    switch (format) {
        case TextureFormat::Rgba8Srgb: return "rgba8_srgb";
        case TextureFormat::Rgba8: return "rgba8";
        case TextureFormat::Rgba16F: return "rgba16f";
        case TextureFormat::Rg16F: return "rg16f";
        case TextureFormat::R16F: return "r16f";
        case TextureFormat::R32F: return "r32f";
        case TextureFormat::R32UI: return "r32ui";
        case TextureFormat::Rgba32F: return "rgba32f";
        case TextureFormat::R8: return "r8";
        case TextureFormat::Depth24Stencil8: return "d24s8";
        case TextureFormat::Depth32F: return "d32f";
        case TextureFormat::Rgba32UI: return "rgba32ui";
    }
    return "?";
}

bool isIntegerFormat(TextureFormat format) {
    return format == TextureFormat::R32UI || format == TextureFormat::Rgba32UI;
}

bool isDepthFormat(TextureFormat format) {
    return format == TextureFormat::Depth24Stencil8 || format == TextureFormat::Depth32F;
}

}  // namespace dermis::graph
