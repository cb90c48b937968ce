#pragma once
// A graph backend with no GPU (sokol-style): it hands out fake texture names
// from a pool and records every call, so tests can assert on what a frame did.

#include "graph/GraphBackend.h"

#include <string>
#include <vector>

namespace dermis::graph {

class TestBackend final : public GraphBackend {
public:
    BackendTexture acquireTexture(const TextureDesc& desc, std::string_view debugName) override;
    void releaseTexture(BackendTexture texture, const TextureDesc& desc) override;
    void beginPass(std::string_view passName) override;
    void endPass() override;

    std::vector<std::string> events;          // "acquire name", "begin pass", "end", "release name"
    std::vector<std::string> executedPasses;  // in order
    size_t texturesCreated = 0;               // pool misses
    size_t liveTextures = 0;

private:
    struct Pooled {
        BackendTexture texture;
        TextureDesc desc;
    };
    std::vector<Pooled> mFree;
    BackendTexture mNext = 1;
};

}  // namespace dermis::graph
