#include "gl/NonFiniteCounter.h"

#include <cmath>
#include <vector>

namespace dermis::gl {
namespace {

bool isFloatFormat(graph::TextureFormat format) {
    using graph::TextureFormat;
    return format == TextureFormat::Rgba16F || format == TextureFormat::Rg16F || format == TextureFormat::R16F ||
           format == TextureFormat::R32F || format == TextureFormat::Rgba32F;
}

}  // namespace

PassInspector NonFiniteCounter::inspector() {
    return [this](std::string_view pass, std::string_view texture, GLuint name, const graph::TextureDesc& desc) {
        inspect(pass, texture, name, desc);
    };
}

void NonFiniteCounter::inspect(std::string_view pass, std::string_view texture, GLuint name,
                               const graph::TextureDesc& desc) {
    if (!isFloatFormat(desc.format) || name == 0) return;
    std::vector<float> texels(size_t(desc.width) * desc.height * 4);
    glGetTextureImage(name, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    TargetStats& stats = mTargets[std::string(pass) + "/" + std::string(texture)];
    stats.texels += uint64_t(desc.width) * desc.height;
    for (size_t i = 0; i < texels.size(); i += 4) {
        bool bad = false;
        for (size_t c = 0; c < 4; ++c) {
            const float v = texels[i + c];
            if (!std::isfinite(v)) {
                bad = true;
            } else {
                stats.largest = std::max(stats.largest, double(std::fabs(v)));
            }
        }
        stats.nonFinite += bad ? 1 : 0;
    }
}

uint64_t NonFiniteCounter::totalNonFinite() const {
    uint64_t n = 0;
    for (const auto& [key, stats] : mTargets) n += stats.nonFinite;
    return n;
}

double NonFiniteCounter::largest() const {
    double largest = 0.0;
    for (const auto& [key, stats] : mTargets) largest = std::max(largest, stats.largest);
    return largest;
}

}  // namespace dermis::gl
