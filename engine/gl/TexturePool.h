#pragma once
// Transient render targets, recycled across passes and frames by description.
// A texture unused for kFramesToKeep frames is destroyed (e.g. after a resize).

#include "gl/GlObjects.h"
#include "graph/TextureDesc.h"

#include <cstdint>
#include <vector>

namespace dermis::gl {

GLenum internalFormat(graph::TextureFormat format);
// The bytes of one level of `desc` in its internal format (a driver may pad).
uint64_t textureBytes(const graph::TextureDesc& desc);

// Levels of a full mip chain down to 1x1 for a width x height base.
int fullMipLevelCount(uint32_t width, uint32_t height);

// Immutable single-level 2-D storage, clamp-to-edge, linear filtering for
// colour and nearest for depth and integer formats.
Texture createTexture2D(const graph::TextureDesc& desc, std::string_view label, int levels = 1);

class TexturePool {
public:
    static constexpr uint64_t kFramesToKeep = 8;

    GLuint acquire(const graph::TextureDesc& desc);
    void release(GLuint texture, const graph::TextureDesc& desc);
    // Ages free textures and destroys stale ones; returns the names it deleted
    // so framebuffers that refer to them can be dropped.
    std::vector<GLuint> endFrame();
    size_t textureCount() const { return mEntries.size(); }
    uint64_t bytes() const;  // textureBytes() of every texture held, in use or free

private:
    struct Entry {
        Texture texture;
        graph::TextureDesc desc;
        bool inUse = false;
        uint64_t lastUsedFrame = 0;
    };
    std::vector<Entry> mEntries;
    uint64_t mFrame = 0;
};

}  // namespace dermis::gl
