#include "env/ShTransferCache.h"

#include "core/CacheDirectory.h"
#include "core/ContentHash.h"
#include "core/Log.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace dermis {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'D', 'R', 'M', 'S', 'S', 'H', 'T', '1'};

struct CacheHeader {
    char magic[8];
    uint32_t version;
    uint32_t raysPerVertex;
    uint64_t vertexCount;
    uint64_t key;
    uint64_t payloadHash;
};
static_assert(sizeof(CacheHeader) == 40, "the header is packed by layout, without padding");

uint64_t payloadHash(const ShTransfer& transfer) {
    return fnv1a(transfer.perVertex.data(), transfer.perVertex.size() * sizeof(ShScalar9));
}

// The transfer in `file`, or why the file cannot be used.
Result<ShTransfer> readCacheFile(const fs::path& file, const MeshData& mesh, int raysPerVertex, uint64_t key) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return makeError(file.string(), "cannot be opened");
    CacheHeader header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return makeError(file.string(), "shorter than its header");
    if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0) return makeError(file.string(), "not an SH transfer cache file");
    if (header.version != kShTransferCacheVersion)
        return makeError(file.string(), "version " + std::to_string(header.version) + ", expected " +
                                            std::to_string(kShTransferCacheVersion));
    if (header.key != key || header.vertexCount != mesh.vertices.size() || header.raysPerVertex != uint32_t(raysPerVertex))
        return makeError(file.string(), "made for another mesh or ray count");
    ShTransfer transfer;
    transfer.raysPerVertex = raysPerVertex;
    transfer.perVertex.resize(mesh.vertices.size());
    const auto payloadBytes = std::streamsize(transfer.perVertex.size() * sizeof(ShScalar9));
    if (!in.read(reinterpret_cast<char*>(transfer.perVertex.data()), payloadBytes))
        return makeError(file.string(), "truncated: shorter than its " + std::to_string(header.vertexCount) + " vertices");
    if (in.peek() != std::ifstream::traits_type::eof()) return makeError(file.string(), "longer than its vertices");
    if (payloadHash(transfer) != header.payloadHash) return makeError(file.string(), "corrupt: the payload hash differs");
    return transfer;
}

Status writeCacheFile(const fs::path& file, const ShTransfer& transfer, uint64_t key) {
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (error) return makeError(file.parent_path().string(), "cannot create the cache directory: " + error.message());
    CacheHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kShTransferCacheVersion;
    header.raysPerVertex = uint32_t(transfer.raysPerVertex);
    header.vertexCount = transfer.perVertex.size();
    header.key = key;
    header.payloadHash = payloadHash(transfer);
    // Unique per process and call, in the same directory so the rename is atomic.
    static std::atomic<unsigned> sTemporaryCounter{0};
    const fs::path temporary = file.string() + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(sTemporaryCounter++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(&header), sizeof header);
        out.write(reinterpret_cast<const char*>(transfer.perVertex.data()),
                  std::streamsize(transfer.perVertex.size() * sizeof(ShScalar9)));
        out.close();
        if (!out) {
            fs::remove(temporary, error);
            return makeError(temporary.string(), "cannot be written");
        }
    }
    fs::rename(temporary, file, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return makeError(file.string(), "cannot be renamed into place: " + error.message());
    }
    return success();
}

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


std::string shTransferCacheFileName(uint64_t key) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key));
    return std::string("sh-transfer-") + hex + ".bin";
}

Result<ShTransferLoad> loadOrComputeShTransfer(const MeshData& mesh, const ShTransferOptions& options) {
    ShTransferLoad load;
    const uint64_t key = shTransferCacheKey(mesh, options.raysPerVertex);
    const fs::path dir = cacheDirectory();
    if (!dir.empty()) load.cacheFile = dir / shTransferCacheFileName(key);
    std::error_code error;
    if (!load.cacheFile.empty() && fs::exists(load.cacheFile, error)) {
        Result<ShTransfer> cached = readCacheFile(load.cacheFile, mesh, options.raysPerVertex, key);
        if (cached) {
            load.transfer = std::move(*cached);
            load.fromCache = true;
            return load;
        }
        log::warn("ignoring the SH transfer cache: " + cached.error().message() + "; recomputing");
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
         << (seconds > 0.0 ? rays / seconds * 1e-6 : 0.0) << " Mrays/s)";
    log::info(line.str());

    if (load.cacheFile.empty()) {
        log::warn("no cache directory for the SH transfer (set DERMIS_CACHE_DIR, XDG_CACHE_HOME or HOME); not cached");
    } else if (Status written = writeCacheFile(load.cacheFile, load.transfer, key); !written) {
        log::warn("SH transfer not cached: " + written.error().message());
    }
    return load;
}

}  // namespace dermis
