#include "gl/NonFiniteCounter.h"

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace dermis::gl {
namespace {

// For the depth key's layout (DERMIS_KEY_*); the blocks come along unused.
using mat4 = glm::mat4;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using ivec2 = glm::ivec2;
#include "include/UniformBlocks.glsl"

using graph::TextureFormat;

constexpr float kHalfMax = 65504.0f;  // largest finite fp16

bool isFloatFormat(TextureFormat format) {
    return format == TextureFormat::Rgba16F || format == TextureFormat::Rg16F || format == TextureFormat::R16F ||
           format == TextureFormat::R32F || format == TextureFormat::Rgba32F;
}
bool isHalfFormat(TextureFormat format) {
    return format == TextureFormat::Rgba16F || format == TextureFormat::Rg16F || format == TextureFormat::R16F;
}
bool isUnormFormat(TextureFormat format) {
    return format == TextureFormat::Rgba8 || format == TextureFormat::Rgba8Srgb || format == TextureFormat::R8;
}

// One texel's components, already as floats (the chain's halves decoded).
void addTexel(TargetStats& stats, const float* values, size_t count, bool half, bool unorm) {
    bool nonFinite = false;
    bool atHalfMax = false;
    for (size_t c = 0; c < count; ++c) {
        const float v = values[c];
        if (!std::isfinite(v)) {
            nonFinite = true;
            continue;
        }
        stats.largest = std::max(stats.largest, double(std::fabs(v)));
        if (half && std::fabs(v) == kHalfMax) atHalfMax = true;
        if (unorm && !(v >= 0.0f && v <= 1.0f)) ++stats.outOfRange;
        if (stats.lit && c < 3) stats.largestLit = std::max(stats.largestLit, double(std::fabs(v)));
    }
    ++stats.texels;
    stats.nonFinite += nonFinite ? 1 : 0;
    stats.atHalfMax += atHalfMax ? 1 : 0;
}

// Read with the format's own components: a shadow map (R32F, up to 8192^2)
// then moves a quarter of the bytes, with no conversion to RGBA.
void readFloats(TargetStats& stats, GLuint name, const graph::TextureDesc& desc) {
    const bool oneComponent =
        desc.format == TextureFormat::R32F || desc.format == TextureFormat::R16F || desc.format == TextureFormat::R8;
    const size_t components = oneComponent ? 1 : desc.format == TextureFormat::Rg16F ? 2 : 4;
    const GLenum layout = components == 1 ? GL_RED : components == 2 ? GL_RG : GL_RGBA;
    std::vector<float> texels(size_t(desc.width) * desc.height * components);
    glGetTextureImage(name, 0, layout, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    const bool half = isHalfFormat(desc.format);
    const bool unorm = isUnormFormat(desc.format);
    for (size_t i = 0; i < texels.size(); i += components) addTexel(stats, &texels[i], components, half, unorm);
}

// sssPack: uvec4(packHalf2x16(colour.rg), packHalf2x16(colour.ba), packHalf2x16(extra.rg),
// packHalf2x16(extra.ba)); packHalf2x16 puts its first value in the low 16 bits.
void readPackedHalves(TargetStats& stats, GLuint name, const graph::TextureDesc& desc) {
    std::vector<uint32_t> texels(size_t(desc.width) * desc.height * 4);
    glGetTextureImage(name, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, static_cast<GLsizei>(texels.size() * sizeof(uint32_t)),
                      texels.data());
    for (size_t i = 0; i < texels.size(); i += 4) {
        std::array<float, 8> halves{};
        for (size_t k = 0; k < 4; ++k) {
            const glm::vec2 pair = glm::unpackHalf2x16(texels[i + k]);
            halves[2 * k] = pair.x;
            halves[2 * k + 1] = pair.y;
        }
        addTexel(stats, halves.data(), halves.size(), true, false);
    }
}

// makeDepthKey: slot in the top 4 bits, view depth in units of 2^-20 m below;
// the background is DERMIS_BACKGROUND_KEY.
void readDepthKeys(TargetStats& stats, GLuint name, const graph::TextureDesc& desc) {
    std::vector<uint32_t> keys(size_t(desc.width) * desc.height);
    glGetTextureImage(name, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, static_cast<GLsizei>(keys.size() * sizeof(uint32_t)),
                      keys.data());
    const uint32_t depthMask = (1u << DERMIS_KEY_DEPTH_BITS) - 1u;
    for (uint32_t key : keys) {
        ++stats.texels;
        if (key == DERMIS_BACKGROUND_KEY) continue;
        const uint32_t slot = key >> DERMIS_KEY_DEPTH_BITS;
        if (slot > DERMIS_MAX_PROFILES) ++stats.outOfRange;
        stats.largest = std::max(stats.largest, double(key & depthMask) / DERMIS_KEY_UNITS_PER_M);
    }
}

}  // namespace

bool isLitTarget(std::string_view texture) {
    static const std::array<std::string_view, 10> kData = {"albedo", "normal", "depth", "ao", "shadow",
                                                           "lean moments", "lean cross", " tsm", " stretch",
                                                           "output"};
    for (std::string_view data : kData) {
        if (texture.find(data) != std::string_view::npos) return false;
    }
    return true;
}

PassInspector NonFiniteCounter::inspector() {
    return [this](std::string_view pass, std::string_view texture, GLuint name, const graph::TextureDesc& desc) {
        inspect(pass, texture, name, desc);
    };
}

void NonFiniteCounter::inspect(std::string_view pass, std::string_view texture, GLuint name,
                               const graph::TextureDesc& desc) {
    if (name == 0 || graph::isDepthFormat(desc.format)) return;
    TargetStats& stats = mTargets[std::string(pass) + "/" + std::string(texture)];
    stats.format = std::string(graph::formatName(desc.format));
    stats.lit = isLitTarget(texture) && desc.format != TextureFormat::R32UI;
    if (desc.format == TextureFormat::R32UI) {
        readDepthKeys(stats, name, desc);
    } else if (desc.format == TextureFormat::Rgba32UI) {
        readPackedHalves(stats, name, desc);
    } else if (isFloatFormat(desc.format) || isUnormFormat(desc.format)) {
        readFloats(stats, name, desc);
    }
}

uint64_t NonFiniteCounter::totalNonFinite() const {
    uint64_t n = 0;
    for (const auto& [key, stats] : mTargets) n += stats.nonFinite;
    return n;
}

uint64_t NonFiniteCounter::totalBad() const {
    uint64_t n = 0;
    for (const auto& [key, stats] : mTargets) n += stats.bad();
    return n;
}

uint64_t NonFiniteCounter::totalAtHalfMax() const {
    uint64_t n = 0;
    for (const auto& [key, stats] : mTargets) n += stats.atHalfMax;
    return n;
}

double NonFiniteCounter::largestLit() const {
    double largest = 0.0;
    for (const auto& [key, stats] : mTargets) largest = std::max(largest, stats.largestLit);
    return largest;
}

std::string firstFaultyPass(const std::vector<std::string>& passes, const std::vector<PassSanitised>& sanitised,
                            const NonFiniteCounter& targets) {
    for (const std::string& pass : passes) {
        for (const PassSanitised& p : sanitised) {
            if (p.pass == pass && p.counts.nonFinite() > 0) return pass;
        }
        for (const auto& [target, stats] : targets.targets()) {
            const bool ofPass = target.size() > pass.size() && target.compare(0, pass.size(), pass) == 0 &&
                                target[pass.size()] == '/';
            if (ofPass && stats.bad() > 0) return pass;
        }
    }
    return {};
}

}  // namespace dermis::gl
