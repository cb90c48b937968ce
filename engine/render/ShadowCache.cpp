#include "render/ShadowCache.h"

#include <cstring>

namespace dermis {

std::vector<float> ShadowCache::makeKey(const gpu::GpuLight& light, const std::vector<glm::mat4>& casters) {
    std::vector<float> key(sizeof(gpu::GpuLight) / sizeof(float) + casters.size() * 16);
    std::memcpy(key.data(), &light, sizeof light);
    for (size_t i = 0; i < casters.size(); ++i) {
        std::memcpy(key.data() + sizeof(gpu::GpuLight) / sizeof(float) + i * 16, &casters[i], sizeof(glm::mat4));
    }
    return key;
}

bool ShadowCache::isCurrent(int index, const graph::TextureDesc& desc, const std::vector<float>& key) const {
    const Slot& s = mSlots[static_cast<size_t>(index)];
    return s.valid && s.desc == desc && s.key == key;
}

void ShadowCache::record(int index, const graph::TextureDesc& desc, std::vector<float> key) {
    Slot& s = mSlots[static_cast<size_t>(index)];
    s.desc = desc;
    s.key = std::move(key);
    s.valid = true;
}

}  // namespace dermis
