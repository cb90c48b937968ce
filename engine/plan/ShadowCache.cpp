#include "plan/ShadowCache.h"

#include <cstring>

namespace dermis {

std::vector<float> ShadowCache::makeKey(const gpu::GpuLight& light, const std::vector<int>& casters,
                                        const std::vector<glm::mat4>& transforms) {
    constexpr size_t kLightFloats = sizeof(gpu::GpuLight) / sizeof(float);
    std::vector<float> key(kLightFloats + casters.size() * 17);
    std::memcpy(key.data(), &light, sizeof light);
    for (size_t i = 0; i < casters.size() && i < transforms.size(); ++i) {
        float* entry = key.data() + kLightFloats + i * 17;
        entry[0] = float(casters[i]);
        std::memcpy(entry + 1, &transforms[i], sizeof(glm::mat4));
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
