#pragma once
// The procedural head's two maps (procedural/ProceduralTextures.h) take
// seconds to bake and come out the same in every process of one build. They
// are kept in the disk cache (core/CacheDirectory.h), in one file laid out as
// core/CacheFile.h says: the albedo's texels, then the normal map's, as
// float32 RGBA rows. Key: the program's own content (programContentHash,
// core/ContentHash.h, so any rebuild bakes again), the two sizes and
// kHeadMapsCacheVersion. Only the kHeadMapsCacheFilesKept most recently used
// files are kept (about 80 MB each), so rebuilds do not fill the disk.
// Without a cache directory, or when the program cannot be read, the maps
// are baked every time.

#include "core/Image.h"
#include "procedural/ProceduralHead.h"

#include <cstdint>
#include <filesystem>

namespace dermis {

constexpr uint32_t kHeadMapsCacheVersion = 1;
constexpr int kHeadMapsCacheFilesKept = 4;

struct HeadMaps {
    Image albedo;  // sRGB-encoded, makeHeadAlbedoMap
    Image normal;  // linear, makeHeadNormalMap
    bool fromCache = false;
    std::filesystem::path cacheFile;  // empty when nothing can be cached
};

HeadMaps loadOrBakeHeadMaps(const HeadMesh& head, int albedoSize, int normalSize);

}  // namespace dermis
