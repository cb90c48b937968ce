#include "graph/TestBackend.h"

namespace dermis::graph {

BackendTexture TestBackend::acquireTexture(const TextureDesc& desc, std::string_view debugName) {
    events.push_back("acquire " + std::string(debugName));
    ++liveTextures;
    for (size_t i = 0; i < mFree.size(); ++i) {
        if (mFree[i].desc == desc) {
            const BackendTexture texture = mFree[i].texture;
            mFree.erase(mFree.begin() + static_cast<std::ptrdiff_t>(i));
            return texture;
        }
    }
    ++texturesCreated;
    return mNext++;
}

void TestBackend::releaseTexture(BackendTexture texture, const TextureDesc& desc) {
    events.push_back("release " + std::to_string(texture));
    --liveTextures;
    mFree.push_back(Pooled{texture, desc});
}

void TestBackend::beginPass(std::string_view passName) {
    events.push_back("begin " + std::string(passName));
    executedPasses.emplace_back(passName);
}

void TestBackend::endPass() { events.push_back("end"); }

}  // namespace dermis::graph
