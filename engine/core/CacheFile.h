#pragma once
// One file of a disk cache (core/CacheDirectory.h): what Dermis computes once
// per machine and reads back in later processes.
//
// Layout, native byte order: a 48-byte header, then the payload.
//   magic (8 bytes, the kind of file), version u32, 0 u32,
//   key u64 (what the payload was computed from), payload size u64 (bytes),
//   payload hash u64 (core/ContentHash.h over the payload), 0 u64.
// A reader checks all of it; a file that fails any check is reported, never
// half-used. Files are written to a temporary name in the same directory and
// renamed, so a reader never sees half a file.

#include "core/Result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dermis {

struct CacheFileKind {
    std::array<char, 8> magic;
    uint32_t version;
    std::string name;  // in messages: "SH transfer", "procedural head maps"
};

struct ConstBytes {
    const void* data;
    size_t size;
};

struct MutableBytes {
    void* data;
    size_t size;
};

// "<prefix><key in 16 hex digits>.bin"
std::string cacheFileName(const std::string& prefix, uint64_t key);

Status writeCacheFile(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                      const std::vector<ConstBytes>& parts);

// Fills `parts` (whose sizes together must be the payload's) from `file`, or
// says why the file cannot be used; `parts` may be partly written then.
Status readCacheFile(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                     const std::vector<MutableBytes>& parts);

// The same for a payload whose size only the file knows (at most maxBytes).
Status readCacheFile(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                     std::vector<uint8_t>& payload, uint64_t maxBytes);

// What a cache does around the two: reads `file` when it exists, warning
// once ("ignoring the <name> cache: <why>; recomputing") when it cannot be
// used. True when `parts` hold the file's payload. Reading marks the file as
// used now, for removeLeastRecentlyUsed.
bool readCacheFileOrWarn(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                         const std::vector<MutableBytes>& parts);
bool readCacheFileOrWarn(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                         std::vector<uint8_t>& payload, uint64_t maxBytes);

// Writes `file`, warning ("<name> not cached: <why>") when it cannot; an
// empty path (no cache directory) warns that nothing is cached.
void writeCacheFileOrWarn(const std::filesystem::path& file, const CacheFileKind& kind, uint64_t key,
                          const std::vector<ConstBytes>& parts);

// Removes the files named "<prefix>*.bin" in `directory` beyond the `keep`
// most recently used (read or written), so that caches keyed by the program
// itself do not grow with every rebuild. Returns how many it removed.
int removeLeastRecentlyUsed(const std::filesystem::path& directory, const std::string& prefix, int keep);

}  // namespace dermis
