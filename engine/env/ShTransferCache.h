#pragma once
// A disk cache of per-vertex SH transfer (env/ShTransfer.h), keyed by the
// mesh's content, so a character's transfer is traced once per machine.
//
// Key: 64-bit FNV-1a over the raw bytes of every vertex's position and
// normal, the indices, the rays per vertex and kShTransferCacheVersion
// (bumped whenever the sampling or the file layout changes). Directory:
// core/CacheDirectory.h. File sh-transfer-<16 hex digits>.bin, laid out as
// core/CacheFile.h says, whose payload is vertex count x 9 float32 (the
// transfer, vertex by vertex), then vertex count x visibilityWords(rays)
// uint32 (which rays escaped), then vertex count bytes (1: buried). A file
// that fails any check (size, magic, version, key, payload hash) is ignored
// with one warning and recomputed; a directory that cannot be written gives a
// warning, never an error.

#include "core/Result.h"
#include "env/ShTransfer.h"
#include "mesh/Mesh.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace dermis {

constexpr uint32_t kShTransferCacheVersion = 4;

uint64_t shTransferCacheKey(const MeshData& mesh, int raysPerVertex);

// "sh-transfer-<key in 16 hex digits>.bin"
std::string shTransferCacheFileName(uint64_t key);

struct ShTransferLoad {
    ShTransfer transfer;
    bool fromCache = false;
    std::filesystem::path cacheFile;  // empty when there is no cache directory
};

// The cached transfer if a valid file exists, else computeShTransfer (timed
// in one info line) and an attempt to store it. Errors only for what
// computeShTransfer refuses.
Result<ShTransferLoad> loadOrComputeShTransfer(const MeshData& mesh, const ShTransferOptions& options = {});

}  // namespace dermis
