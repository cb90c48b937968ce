#pragma once
// What the render graph needs from a graphics API. The GL backend
// (gl/GlGraphBackend.h) implements it with real textures, timer queries and
// debug groups; TestBackend (graph/TestBackend.h) records calls so that graph
// logic is tested without a GPU.

#include "graph/TextureDesc.h"

#include <cstdint>
#include <string_view>

namespace dermis::graph {

// An API object name (a GL texture name for the GL backend). 0 = none.
using BackendTexture = uint32_t;

class GraphBackend {
public:
    virtual ~GraphBackend() = default;

    // Transient textures: acquired before their first use in a frame and
    // released after their last, so the backend can recycle them from a pool.
    virtual BackendTexture acquireTexture(const TextureDesc& desc, std::string_view debugName) = 0;
    virtual void releaseTexture(BackendTexture texture, const TextureDesc& desc) = 0;

    // Bracket every executed pass: the one place that owns timers and labels.
    virtual void beginPass(std::string_view passName) = 0;
    virtual void endPass() = 0;

    // After a pass ran, once per texture it wrote (debug inspection, e.g.
    // counting non-finite texels). The default does nothing.
    virtual void passWrote(std::string_view passName, std::string_view textureName, BackendTexture texture,
                           const TextureDesc& desc) {
        (void)passName;
        (void)textureName;
        (void)texture;
        (void)desc;
    }
};

}  // namespace dermis::graph
