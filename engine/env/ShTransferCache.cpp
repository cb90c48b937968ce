#include "env/ShTransferCache.h"

#include "core/CacheDirectory.h"
#include "core/CacheFile.h"
#include "core/ContentHash.h"
#include "core/Log.h"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace dermis {
namespace {

namespace fs = std::filesystem;

const CacheFileKind kShTransferFile{{'D', 'R', 'M', 'S', 'S', 'H', 'T', '1'}, kShTransferCacheVersion, "SH transfer"};

}  // namespace

uint64_t shTransferCacheKey(const MeshData& mesh, int raysPerVertex) {
    uint64_t hash = kFnvOffsetBasis;
    for (const Vertex& vertex : mesh.vertices) {
        hash = fnv1a(&vertex.position, sizeof vertex.position, hash);
        hash = fnv1a(&vertex.normal, sizeof vertex.normal, hash);
    }
    hash = fnv1a(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), hash);
    const uint32_t rays = uint32_t(raysPerVertex);
    hash = fnv1a(&rays, sizeof rays, hash);
    return fnv1a(&kShTransferCacheVersion, sizeof kShTransferCacheVersion, hash);
}

std::string shTransferCacheFileName(uint64_t key) { return cacheFileName("sh-transfer-", key); }

Result<ShTransferLoad> loadOrComputeShTransfer(const MeshData& mesh, const ShTransferOptions& options) {
    ShTransferLoad load;
    const uint64_t key = shTransferCacheKey(mesh, options.raysPerVertex);
    const fs::path dir = cacheDirectory();
    if (!dir.empty()) load.cacheFile = dir / shTransferCacheFileName(key);
    load.transfer.raysPerVertex = options.raysPerVertex;
    load.transfer.perVertex.resize(mesh.vertices.size());
    load.transfer.visibility.resize(mesh.vertices.size() * visibilityWords(options.raysPerVertex));
    load.transfer.buried.resize(mesh.vertices.size());
    const size_t transferBytes = load.transfer.perVertex.size() * sizeof(ShScalar9);
    const size_t visibilityBytes = load.transfer.visibility.size() * sizeof(uint32_t);
    const size_t buriedBytes = load.transfer.buried.size();
    if (readCacheFileOrWarn(load.cacheFile, kShTransferFile, key,
                            {{load.transfer.perVertex.data(), transferBytes},
                             {load.transfer.visibility.data(), visibilityBytes},
                             {load.transfer.buried.data(), buriedBytes}})) {
        load.fromCache = true;
        return load;
    }

    const auto start = std::chrono::steady_clock::now();
    Result<ShTransfer> computed = computeShTransfer(mesh, options);
    if (!computed) return computed.error();
    load.transfer = std::move(*computed);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rays = double(mesh.vertices.size()) * double(options.raysPerVertex);
    std::ostringstream line;
    line.precision(3);
    line << "SH transfer of " << (mesh.name.empty() ? std::string("a mesh") : mesh.name) << ": "
         << mesh.vertices.size() << " vertices x " << options.raysPerVertex << " rays in " << seconds << " s ("
         << (seconds > 0.0 ? rays / seconds * 1e-6 : 0.0) << " Mrays/s), "
         << std::count(load.transfer.buried.begin(), load.transfer.buried.end(), uint8_t(1))
         << " vertices inside the body";
    log::info(line.str());
    writeCacheFileOrWarn(load.cacheFile, kShTransferFile, key,
                         {{load.transfer.perVertex.data(), transferBytes},
                          {load.transfer.visibility.data(), visibilityBytes},
                          {load.transfer.buried.data(), buriedBytes}});
    return load;
}

}  // namespace dermis
