#include "render/ShadowCache.h"

#include "gl/TexturePool.h"

#include <cstring>

namespace dermis {

ShadowCache::Slot& ShadowCache::slot(int index, int mapSize) {
    Slot& s = mSlots[static_cast<size_t>(index)];
    const graph::TextureDesc desc{static_cast<uint32_t>(mapSize), static_cast<uint32_t>(mapSize),
                                  graph::TextureFormat::R32F};
    if (!s.depthM.isValid() || s.desc != desc) {
        s.depthM = gl::createTexture2D(desc);
        // Outside the map means "unoccluded": clamp to a far border.
        glTextureParameteri(s.depthM.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(s.depthM.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        s.desc = desc;
        s.valid = false;
        s.key.clear();
    }
    return s;
}

std::vector<float> ShadowCache::makeKey(const gpu::GpuLight& light, const std::vector<glm::mat4>& casters) {
    std::vector<float> key(sizeof(gpu::GpuLight) / sizeof(float) + casters.size() * 16);
    std::memcpy(key.data(), &light, sizeof light);
    for (size_t i = 0; i < casters.size(); ++i) {
        std::memcpy(key.data() + sizeof(gpu::GpuLight) / sizeof(float) + i * 16, &casters[i], sizeof(glm::mat4));
    }
    return key;
}

bool ShadowCache::isCurrent(int index, const std::vector<float>& key) const {
    const Slot& s = mSlots[static_cast<size_t>(index)];
    return s.valid && s.key == key;
}

}  // namespace dermis
