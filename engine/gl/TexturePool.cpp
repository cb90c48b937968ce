#include "gl/TexturePool.h"

#include <algorithm>

namespace dermis::gl {

GLenum internalFormat(graph::TextureFormat format) {
    using graph::TextureFormat;
    switch (format) {
        case TextureFormat::Rgba8Srgb: return GL_SRGB8_ALPHA8;
        case TextureFormat::Rgba8: return GL_RGBA8;
        case TextureFormat::Rgba16F: return GL_RGBA16F;
        case TextureFormat::Rg16F: return GL_RG16F;
        case TextureFormat::R16F: return GL_R16F;
        case TextureFormat::R32F: return GL_R32F;
        case TextureFormat::R32UI: return GL_R32UI;
        case TextureFormat::Rgba32F: return GL_RGBA32F;
        case TextureFormat::R8: return GL_R8;
        case TextureFormat::Depth24Stencil8: return GL_DEPTH24_STENCIL8;
        case TextureFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
        case TextureFormat::Rgba32UI: return GL_RGBA32UI;
    }
    return GL_RGBA8;
}

uint64_t textureBytes(const graph::TextureDesc& desc) {
    using graph::TextureFormat;
    uint64_t texelBytes = 4;
    switch (desc.format) {
        case TextureFormat::R8: texelBytes = 1; break;
        case TextureFormat::R16F: texelBytes = 2; break;
        case TextureFormat::Rgba8Srgb:
        case TextureFormat::Rgba8:
        case TextureFormat::Rg16F:
        case TextureFormat::R32F:
        case TextureFormat::R32UI:
        case TextureFormat::Depth24Stencil8:
        case TextureFormat::Depth32F: texelBytes = 4; break;
        case TextureFormat::Rgba16F: texelBytes = 8; break;
        case TextureFormat::Rgba32F:
        case TextureFormat::Rgba32UI: texelBytes = 16; break;
    }
    return uint64_t(desc.width) * desc.height * texelBytes;
}

int fullMipLevelCount(uint32_t width, uint32_t height) {
    int levels = 1;
    for (uint32_t size = std::max(width, height); size > 1; size >>= 1) ++levels;
    return levels;
}

Texture createTexture2D(const graph::TextureDesc& desc, std::string_view label, int levels) {
    Texture texture = createTexture(GL_TEXTURE_2D, label);
    glTextureStorage2D(texture.get(), levels, internalFormat(desc.format), static_cast<GLsizei>(desc.width),
                       static_cast<GLsizei>(desc.height));
    // Integer textures are incomplete with linear filtering.
    const bool nearest = graph::isDepthFormat(desc.format) || graph::isIntegerFormat(desc.format);
    glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
    glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

GLuint TexturePool::acquire(const graph::TextureDesc& desc) {
    for (Entry& entry : mEntries) {
        if (!entry.inUse && entry.desc == desc) {
            entry.inUse = true;
            entry.lastUsedFrame = mFrame;
            return entry.texture.get();
        }
    }
    Entry entry;
    entry.texture = createTexture2D(desc, "texture pool (unused)");  // the graph names it for each pass that uses it
    entry.desc = desc;
    entry.inUse = true;
    entry.lastUsedFrame = mFrame;
    mEntries.push_back(std::move(entry));
    return mEntries.back().texture.get();
}

void TexturePool::release(GLuint texture, const graph::TextureDesc& desc) {
    for (Entry& entry : mEntries) {
        if (entry.texture.get() == texture && entry.desc == desc) {
            entry.inUse = false;
            entry.lastUsedFrame = mFrame;
            return;
        }
    }
}

uint64_t TexturePool::bytes() const {
    uint64_t total = 0;
    for (const Entry& entry : mEntries) total += textureBytes(entry.desc);
    return total;
}

std::vector<GLuint> TexturePool::endFrame() {
    ++mFrame;
    std::vector<GLuint> destroyed;
    for (const Entry& e : mEntries) {
        if (!e.inUse && mFrame - e.lastUsedFrame > kFramesToKeep) destroyed.push_back(e.texture.get());
    }
    mEntries.erase(std::remove_if(mEntries.begin(), mEntries.end(),
                                  [&](const Entry& e) { return !e.inUse && mFrame - e.lastUsedFrame > kFramesToKeep; }),
                   mEntries.end());
    return destroyed;
}

}  // namespace dermis::gl
