#pragma once
// Shadow maps persist across frames. Each slot remembers what it was
// rendered from (the light's matrices, the map size and every caster's
// transform); when nothing changed, the shadow pass's predicate skips it and
// the map is reused as it is.

#include "gl/GlObjects.h"
#include "graph/TextureDesc.h"
#include "render/UniformBlocks.h"

#include <array>
#include <vector>

namespace dermis {

class ShadowCache {
public:
    struct Slot {
        gl::Texture depthM;  // R32F linear light depth
        graph::TextureDesc desc;
        std::vector<float> key;  // what it was rendered from
        bool valid = false;
    };

    // Ensures slot `slot` has a map of this size; returns it.
    Slot& slot(int slot, int mapSize);
    static std::vector<float> makeKey(const gpu::GpuLight& light, const std::vector<glm::mat4>& casters);
    bool isCurrent(int slot, const std::vector<float>& key) const;

private:
    std::array<Slot, DERMIS_MAX_SHADOWED_LIGHTS> mSlots;
};

}  // namespace dermis
