#include "procedural/HeadMapsCache.h"

#include "core/CacheDirectory.h"
#include "core/CacheFile.h"
#include "core/ContentHash.h"
#include "core/Log.h"
#include "procedural/ProceduralTextures.h"

#include <chrono>
#include <cstdio>

namespace dermis {
namespace {

const CacheFileKind kHeadMapsFile{{'D', 'R', 'M', 'S', 'H', 'E', 'A', 'D'}, kHeadMapsCacheVersion,
                                  "procedural head maps"};
constexpr const char* kFilePrefix = "procedural-head-maps-";

Image blankImage(int size, ColourSpace colourSpace) {
    Image image;
    image.width = size;
    image.height = size;
    image.colourSpace = colourSpace;
    image.texels.resize(size_t(size) * size_t(size));
    return image;
}

}  // namespace

HeadMaps loadOrBakeHeadMaps(const HeadMesh& head, int albedoSize, int normalSize) {
    HeadMaps maps;
    const uint64_t program = programContentHash();
    const std::filesystem::path directory = cacheDirectory();
    const uint64_t key = ContentHash()
                             .number(program)
                             .number(uint64_t(albedoSize))
                             .number(uint64_t(normalSize))
                             .number(kHeadMapsCacheVersion)
                             .value();
    if (program != 0 && !directory.empty()) maps.cacheFile = directory / cacheFileName(kFilePrefix, key);

    if (!maps.cacheFile.empty()) {
        maps.albedo = blankImage(albedoSize, ColourSpace::Srgb);
        maps.normal = blankImage(normalSize, ColourSpace::Linear);
        if (readCacheFileOrWarn(maps.cacheFile, kHeadMapsFile, key,
                                {{maps.albedo.texels.data(), maps.albedo.texels.size() * sizeof(glm::vec4)},
                                 {maps.normal.texels.data(), maps.normal.texels.size() * sizeof(glm::vec4)}})) {
            maps.fromCache = true;
            return maps;
        }
    }

    const auto start = std::chrono::steady_clock::now();
    maps.albedo = makeHeadAlbedoMap(head, albedoSize);
    maps.normal = makeHeadNormalMap(head, normalSize);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char line[160];
    std::snprintf(line, sizeof line, "baked the procedural head's maps (%d^2 albedo, %d^2 normals) in %.1f s", albedoSize,
                  normalSize, seconds);
    log::info(line);
    if (maps.cacheFile.empty()) return maps;
    writeCacheFileOrWarn(maps.cacheFile, kHeadMapsFile, key,
                         {{maps.albedo.texels.data(), maps.albedo.texels.size() * sizeof(glm::vec4)},
                          {maps.normal.texels.data(), maps.normal.texels.size() * sizeof(glm::vec4)}});
    removeLeastRecentlyUsed(directory, kFilePrefix, kHeadMapsCacheFilesKept);
    return maps;
}

}  // namespace dermis
