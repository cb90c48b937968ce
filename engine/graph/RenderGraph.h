#pragma once
// The frame as a render graph, after Filament's FrameGraph.
//
// A pass is a name, a small Data struct of texture handles, a setup step that
// declares what it creates, reads and writes, and an execute step. Every frame
// the renderer declares all passes it might run; compile() then decides:
//
//  1. Scene predicates. A pass whose setup called skipIf(true, why) is
//     culled. Its writes to existing textures fall back to the previous
//     version (so a cached shadow map keeps its contents). A texture it would
//     have created falls back to the input it named with passThrough() (a
//     skipped blur "returns" its input), and otherwise does not exist: any
//     pass that reads it is culled too, with the same fall-backs.
//  2. Reference counts. Each texture version counts its readers; outputs
//     marked with markOutput() count one extra. A pass none of whose written
//     versions are read, and that has no side effect, is culled, and the
//     versions it read lose a reader. This repeats until nothing changes, so
//     a whole unused chain disappears.
//  3. Lifetimes. Each transient texture is acquired from the backend's pool
//     just before its first executed user and released after its last.
//
// execute() then runs the surviving passes in declaration order, each inside
// GraphBackend::beginPass/endPass, which own the timers and debug labels.
//
// Handles are versions: write() returns a new handle for the same texture, and
// readers of the old handle see the contents from before that write.

#include "core/Result.h"
#include "graph/GraphBackend.h"
#include "graph/TextureDesc.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dermis::graph {

struct TextureHandle {
    static constexpr uint32_t kInvalid = UINT32_MAX;
    uint32_t version = kInvalid;  // index of a version node
    bool isValid() const { return version != kInvalid; }
    bool operator==(const TextureHandle& o) const { return version == o.version; }
};

enum class CullReason : uint8_t {
    None,              // executed
    Predicate,         // its scene predicate said there is nothing to do
    MissingInput,      // it reads a texture that a culled pass would have made
    Unused,            // nothing reads what it writes
};

struct PassReport {
    std::string name;
    bool executed = false;
    CullReason reason = CullReason::None;
    std::string detail;  // the predicate's reason, or the missing input's name
};

class RenderGraph;

class PassBuilder {
public:
    TextureHandle create(const std::string& name, const TextureDesc& desc);  // created and written by this pass
    TextureHandle read(TextureHandle texture);
    TextureHandle write(TextureHandle texture);  // returns the new version
    // If this pass is culled before it runs (its predicate, or a missing
    // input), readers of `output` (created here) read `input` instead.
    void passThrough(TextureHandle output, TextureHandle input);
    void sideEffect();                            // never cull by reference count
    void skipIf(bool skip, const std::string& reason);
    const TextureDesc& desc(TextureHandle texture) const;

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t passIndex) : mGraph(graph), mPass(passIndex) {}
    RenderGraph& mGraph;
    uint32_t mPass;
};

class PassResources {
public:
    BackendTexture texture(TextureHandle texture) const;
    const TextureDesc& desc(TextureHandle texture) const;

private:
    friend class RenderGraph;
    explicit PassResources(const RenderGraph& graph) : mGraph(graph) {}
    const RenderGraph& mGraph;
};

class RenderGraph {
public:
    template <class Data>
    using Setup = std::function<void(PassBuilder&, Data&)>;
    template <class Data>
    using Execute = std::function<void(const PassResources&, const Data&)>;

    template <class Data>
    const Data& addPass(const std::string& name, Setup<Data> setup, Execute<Data> execute) {
        auto pass = std::make_unique<TypedPass<Data>>(std::move(execute));
        TypedPass<Data>& ref = *pass;
        const uint32_t index = addPassNode(name, std::move(pass));
        PassBuilder builder(*this, index);
        setup(builder, ref.data);
        return ref.data;
    }

    // A texture that lives outside the frame (a cached shadow map, the output).
    TextureHandle importTexture(const std::string& name, const TextureDesc& desc, BackendTexture texture);
    // The frame's consumer reads this version: it and its producers survive.
    void markOutput(TextureHandle texture);

    // Culls and plans lifetimes. Errors for misuse: an invalid handle, a write
    // to a version that is no longer the latest.
    Status compile();
    void execute(GraphBackend& backend);

    std::vector<PassReport> passReports() const;
    bool wasExecuted(const std::string& passName) const;
    std::string textureName(TextureHandle texture) const;

private:
    friend class PassBuilder;
    friend class PassResources;

    struct PassBase {
        virtual ~PassBase() = default;
        virtual void run(const PassResources& resources) = 0;
    };
    template <class Data>
    struct TypedPass final : PassBase {
        explicit TypedPass(Execute<Data> e) : execute(std::move(e)) {}
        void run(const PassResources& resources) override { execute(resources, data); }
        Data data{};
        Execute<Data> execute;
    };

    static constexpr uint32_t kNone = UINT32_MAX;

    struct PassNode {
        std::string name;
        std::unique_ptr<PassBase> pass;
        std::vector<uint32_t> reads;   // version indices
        std::vector<uint32_t> writes;  // version indices
        bool sideEffect = false;
        bool skip = false;
        std::string skipReason;
        uint32_t refCount = 0;
        CullReason culled = CullReason::None;
        std::string cullDetail;
    };
    struct ResourceNode {
        std::string name;
        TextureDesc desc;
        bool imported = false;
        BackendTexture texture = 0;
        uint32_t latestVersion = kNone;
        uint32_t firstPass = kNone;
        uint32_t lastPass = kNone;
    };
    struct VersionNode {
        uint32_t resource = kNone;
        uint32_t writer = kNone;     // pass index; kNone for an import
        uint32_t previous = kNone;   // the version this write replaced
        uint32_t aliasOf = kNone;    // set when its writer was skipped
        uint32_t passThrough = kNone;  // what a created version falls back to
        bool produced = false;       // an import, or written by a surviving pass
        uint32_t readers = 0;
        bool output = false;
    };

    uint32_t addPassNode(const std::string& name, std::unique_ptr<PassBase> pass);
    uint32_t newVersion(uint32_t resource, uint32_t writer, uint32_t previous);
    uint32_t resolve(uint32_t version) const;
    bool checkHandle(TextureHandle texture, const char* what);
    void applyPredicates();
    void cullUnreferenced();
    void planLifetimes();

    std::vector<PassNode> mPasses;
    std::vector<ResourceNode> mResources;
    std::vector<VersionNode> mVersions;
    std::vector<Error> mErrors;
    bool mCompiled = false;
};

}  // namespace dermis::graph
