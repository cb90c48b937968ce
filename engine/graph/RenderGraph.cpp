#include "graph/RenderGraph.h"

#include <algorithm>
#include <cassert>
#include <vector>

namespace dermis::graph {

// ---- PassBuilder -----------------------------------------------------------

TextureHandle PassBuilder::create(const std::string& name, const TextureDesc& desc) {
    auto& resources = mGraph.mResources;
    const auto resource = static_cast<uint32_t>(resources.size());
    RenderGraph::ResourceNode node;
    node.name = name;
    node.desc = desc;
    resources.push_back(node);
    const uint32_t version = mGraph.newVersion(resource, mPass, RenderGraph::kNone);
    mGraph.mPasses[mPass].writes.push_back(version);
    return TextureHandle{version};
}

TextureHandle PassBuilder::read(TextureHandle texture) {
    if (!mGraph.checkHandle(texture, "read")) return texture;
    mGraph.mPasses[mPass].reads.push_back(texture.version);
    return texture;
}

TextureHandle PassBuilder::write(TextureHandle texture) {
    if (!mGraph.checkHandle(texture, "write")) return texture;
    const uint32_t resource = mGraph.mVersions[texture.version].resource;
    if (mGraph.mResources[resource].latestVersion != texture.version) {
        mGraph.mErrors.push_back(makeError(mGraph.mPasses[mPass].name,
                                           "writes an old version of '" + mGraph.mResources[resource].name + "'"));
        return texture;
    }
    const uint32_t version = mGraph.newVersion(resource, mPass, texture.version);
    mGraph.mPasses[mPass].writes.push_back(version);
    return TextureHandle{version};
}

void PassBuilder::passThrough(TextureHandle output, TextureHandle input) {
    if (!mGraph.checkHandle(output, "pass through") || !mGraph.checkHandle(input, "pass through")) return;
    auto& version = mGraph.mVersions[output.version];
    if (version.writer != mPass || version.previous != RenderGraph::kNone) {
        mGraph.mErrors.push_back(makeError(mGraph.mPasses[mPass].name, "passThrough() needs a texture this pass creates"));
        return;
    }
    version.passThrough = input.version;
}

void PassBuilder::sideEffect() { mGraph.mPasses[mPass].sideEffect = true; }

void PassBuilder::skipIf(bool skip, const std::string& reason) {
    auto& pass = mGraph.mPasses[mPass];
    if (skip && !pass.skip) {
        pass.skip = true;
        pass.skipReason = reason;
    }
}

const TextureDesc& PassBuilder::desc(TextureHandle texture) const {
    return mGraph.mResources[mGraph.mVersions.at(texture.version).resource].desc;
}

// ---- PassResources ---------------------------------------------------------

BackendTexture PassResources::texture(TextureHandle texture) const {
    return mGraph.mResources[mGraph.mVersions.at(mGraph.resolve(texture.version)).resource].texture;
}

const TextureDesc& PassResources::desc(TextureHandle texture) const {
    return mGraph.mResources[mGraph.mVersions.at(mGraph.resolve(texture.version)).resource].desc;
}

// ---- RenderGraph -----------------------------------------------------------

uint32_t RenderGraph::addPassNode(const std::string& name, std::unique_ptr<PassBase> pass) {
    // Timings, traces and cull reports key passes by name, and two passes of
    // one name merged their samples (two SSS slots of one profile read as one
    // pass, at the median of both): a repeated name gets "#2", "#3" ...
    auto taken = [&](const std::string& candidate) {
        return std::any_of(mPasses.begin(), mPasses.end(), [&](const PassNode& p) { return p.name == candidate; });
    };
    std::string unique = name;
    for (int n = 2; taken(unique); ++n) unique = name + "#" + std::to_string(n);
    PassNode node;
    node.name = unique;
    node.pass = std::move(pass);
    mPasses.push_back(std::move(node));
    return static_cast<uint32_t>(mPasses.size() - 1);
}

uint32_t RenderGraph::newVersion(uint32_t resource, uint32_t writer, uint32_t previous) {
    VersionNode version;
    version.resource = resource;
    version.writer = writer;
    version.previous = previous;
    mVersions.push_back(version);
    const auto index = static_cast<uint32_t>(mVersions.size() - 1);
    mResources[resource].latestVersion = index;
    return index;
}

bool RenderGraph::checkHandle(TextureHandle texture, const char* what) {
    if (texture.isValid() && texture.version < mVersions.size()) return true;
    const std::string passName = mPasses.empty() ? std::string("graph") : mPasses.back().name;
    mErrors.push_back(makeError(passName, std::string("tries to ") + what + " an invalid texture handle"));
    return false;
}

TextureHandle RenderGraph::importTexture(const std::string& name, const TextureDesc& desc, BackendTexture texture) {
    ResourceNode node;
    node.name = name;
    node.desc = desc;
    node.imported = true;
    node.texture = texture;
    mResources.push_back(node);
    const uint32_t version = newVersion(static_cast<uint32_t>(mResources.size() - 1), kNone, kNone);
    mVersions[version].produced = true;
    return TextureHandle{version};
}

void RenderGraph::markOutput(TextureHandle texture) {
    if (checkHandle(texture, "output")) mVersions[texture.version].output = true;
}

uint32_t RenderGraph::resolve(uint32_t version) const {
    while (mVersions[version].aliasOf != kNone) version = mVersions[version].aliasOf;
    return version;
}

std::string RenderGraph::textureName(TextureHandle texture) const {
    if (!texture.isValid() || texture.version >= mVersions.size()) return "<invalid>";
    return mResources[mVersions[texture.version].resource].name;
}

void RenderGraph::applyPredicates() {
    // Passes were declared in dependency order (a handle exists only after
    // its writer), so one forward sweep settles every pass.
    for (uint32_t p = 0; p < mPasses.size(); ++p) {
        PassNode& pass = mPasses[p];
        if (pass.skip) {
            pass.culled = CullReason::Predicate;
            pass.cullDetail = pass.skipReason;
        } else {
            for (uint32_t read : pass.reads) {
                if (!mVersions[resolve(read)].produced) {
                    pass.culled = CullReason::MissingInput;
                    pass.cullDetail = mResources[mVersions[read].resource].name;
                    break;
                }
            }
        }
        for (uint32_t written : pass.writes) {
            VersionNode& version = mVersions[written];
            if (pass.culled == CullReason::None) {
                version.produced = true;
            } else if (version.previous != kNone) {
                version.aliasOf = version.previous;  // contents stay as they were
            } else if (version.passThrough != kNone && mVersions[resolve(version.passThrough)].produced) {
                version.aliasOf = version.passThrough;
            }
        }
    }
}

void RenderGraph::cullUnreferenced() {
    for (uint32_t p = 0; p < mPasses.size(); ++p) {
        if (mPasses[p].culled != CullReason::None) continue;
        for (uint32_t read : mPasses[p].reads) ++mVersions[resolve(read)].readers;
    }
    for (VersionNode& version : mVersions) {
        if (version.output) ++mVersions[resolve(static_cast<uint32_t>(&version - mVersions.data()))].readers;
    }
    std::vector<uint32_t> unread;
    for (uint32_t p = 0; p < mPasses.size(); ++p) {
        PassNode& pass = mPasses[p];
        if (pass.culled != CullReason::None) continue;
        pass.refCount = static_cast<uint32_t>(pass.writes.size());
        for (uint32_t written : pass.writes) {
            if (mVersions[written].readers == 0) unread.push_back(written);
        }
    }
    while (!unread.empty()) {
        const uint32_t version = unread.back();
        unread.pop_back();
        const uint32_t writer = mVersions[version].writer;
        if (writer == kNone) continue;
        PassNode& pass = mPasses[writer];
        if (pass.culled != CullReason::None || pass.refCount == 0) continue;
        if (--pass.refCount > 0 || pass.sideEffect) continue;
        pass.culled = CullReason::Unused;
        for (uint32_t read : pass.reads) {
            const uint32_t source = resolve(read);
            if (--mVersions[source].readers == 0) unread.push_back(source);
        }
    }
    // A pass that writes nothing and has no side effect can never be observed.
    for (PassNode& pass : mPasses) {
        if (pass.culled == CullReason::None && pass.writes.empty() && !pass.sideEffect) pass.culled = CullReason::Unused;
    }
}

void RenderGraph::planLifetimes() {
    for (uint32_t p = 0; p < mPasses.size(); ++p) {
        const PassNode& pass = mPasses[p];
        if (pass.culled != CullReason::None) continue;
        auto touch = [&](uint32_t version) {
            ResourceNode& resource = mResources[mVersions[resolve(version)].resource];
            if (resource.firstPass == kNone) resource.firstPass = p;
            resource.lastPass = p;
        };
        for (uint32_t v : pass.reads) touch(v);
        for (uint32_t v : pass.writes) touch(v);
    }
}

Status RenderGraph::compile() {
    if (!mErrors.empty()) return mErrors.front();
    if (mCompiled) return makeError("render graph", "compiled twice");
    applyPredicates();
    cullUnreferenced();
    planLifetimes();
    mCompiled = true;
    return success();
}

void RenderGraph::execute(GraphBackend& backend) {
    assert(mCompiled);
    const PassResources resources(*this);
    for (uint32_t p = 0; p < mPasses.size(); ++p) {
        PassNode& pass = mPasses[p];
        if (pass.culled != CullReason::None) continue;
        for (ResourceNode& resource : mResources) {
            if (!resource.imported && resource.firstPass == p) {
                resource.texture = backend.acquireTexture(resource.desc, resource.name);
            }
        }
        backend.beginPass(pass.name);
        pass.pass->run(resources);
        backend.endPass();
        for (uint32_t written : pass.writes) {
            const ResourceNode& resource = mResources[mVersions[written].resource];
            backend.passWrote(pass.name, resource.name, resource.texture, resource.desc);
        }
        for (ResourceNode& resource : mResources) {
            if (!resource.imported && resource.lastPass == p) {
                backend.releaseTexture(resource.texture, resource.desc);
                resource.texture = 0;
            }
        }
    }
}

std::vector<PassReport> RenderGraph::passReports() const {
    std::vector<PassReport> reports;
    reports.reserve(mPasses.size());
    for (const PassNode& pass : mPasses) {
        reports.push_back(PassReport{pass.name, pass.culled == CullReason::None, pass.culled, pass.cullDetail});
    }
    return reports;
}

bool RenderGraph::wasExecuted(const std::string& passName) const {
    for (const PassNode& pass : mPasses) {
        if (pass.name == passName) return pass.culled == CullReason::None;
    }
    return false;
}

}  // namespace dermis::graph
