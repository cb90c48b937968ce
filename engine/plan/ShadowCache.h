#pragma once
// Shadow maps persist across frames. The cache remembers, per shadow slot,
// what its map was last rendered from (the map's size, the light's matrices
// and the kept casters with their transforms, plan/ShadowCasters.h); when the frame plan finds nothing changed,
// the shadow pass's predicate skips it and the map is reused as it is. No GL:
// the maps themselves are the frame resources' (render/FrameResources.h).

#include "graph/TextureDesc.h"
#include "gpu/UniformBlocks.h"

#include <array>
#include <vector>

namespace dermis {

class ShadowCache {
public:
    // What a map is rendered from: the light's block and the characters drawn
    // into it, `casters[i]` with transform `transforms[i]`.
    static std::vector<float> makeKey(const gpu::GpuLight& light, const std::vector<int>& casters,
                                      const std::vector<glm::mat4>& transforms);

    // Whether slot `slot` holds a map of this size rendered from `key`.
    bool isCurrent(int slot, const graph::TextureDesc& desc, const std::vector<float>& key) const;
    // Slot `slot`'s map was just rendered from `key` at this size.
    void record(int slot, const graph::TextureDesc& desc, std::vector<float> key);

private:
    struct Slot {
        graph::TextureDesc desc;
        std::vector<float> key;
        bool valid = false;
    };
    std::array<Slot, DERMIS_MAX_SHADOWED_LIGHTS> mSlots;
};

}  // namespace dermis
