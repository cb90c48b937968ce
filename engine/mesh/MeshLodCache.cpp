#include "mesh/MeshLodCache.h"

#include "core/CacheDirectory.h"
#include "core/CacheFile.h"
#include "core/ContentHash.h"
#include "core/Log.h"
#include "mesh/MeshLod.h"

#include <cstring>

namespace dermis {
namespace {

const CacheFileKind kLodFile{{'D', 'R', 'M', 'S', 'L', 'O', 'D', '1'}, kLodCacheVersion, "levels of detail"};
// A mesh's levels hold fewer indices than the mesh; this bounds a corrupt header's claim.
constexpr uint64_t kMaxLodPayloadBytes = uint64_t(1) << 31;

template <class T>
void append(std::vector<uint8_t>& bytes, const T* data, size_t count) {
    const auto* raw = reinterpret_cast<const uint8_t*>(data);
    bytes.insert(bytes.end(), raw, raw + count * sizeof(T));
}

// Reads `count` values at `offset`; false past the end.
template <class T>
bool take(const std::vector<uint8_t>& bytes, size_t& offset, T* out, size_t count) {
    const size_t size = count * sizeof(T);
    if (offset > bytes.size() || bytes.size() - offset < size) return false;
    if (size > 0) std::memcpy(out, bytes.data() + offset, size);
    offset += size;
    return true;
}

}  // namespace

uint64_t lodCacheKey(const MeshData& mesh, const std::vector<Submesh>& ranges) {
    uint64_t hash = kFnvOffsetBasis;
    for (const Vertex& vertex : mesh.vertices) hash = fnv1a(&vertex.position, sizeof vertex.position, hash);
    hash = fnv1a(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), hash);
    for (const Submesh& range : ranges) hash = fnv1a(&range, sizeof range, hash);
    const float constants[] = {float(kLodCacheVersion), float(kMaxLodLevels), kLodTriangleRatio, float(kMinLodTriangles),
                               kMaxLodRelativeError, float(kLodErrorSamplesPerEdge)};
    return fnv1a(constants, sizeof constants, hash);
}

std::vector<uint8_t> encodeLodLevels(const std::vector<LodLevel>& levels) {
    std::vector<uint8_t> bytes;
    const uint32_t count = uint32_t(levels.size());
    append(bytes, &count, 1);
    for (const LodLevel& level : levels) {
        const uint32_t sizes[2] = {uint32_t(level.indices.size()), uint32_t(level.ranges.size())};
        append(bytes, sizes, 2);
        append(bytes, &level.errorObject, 1);
    }
    for (const LodLevel& level : levels) {
        append(bytes, level.indices.data(), level.indices.size());
        append(bytes, level.ranges.data(), level.ranges.size());
    }
    return bytes;
}

bool decodeLodLevels(const std::vector<uint8_t>& bytes, size_t vertexCount, std::vector<LodLevel>& levels) {
    size_t offset = 0;
    uint32_t count = 0;
    if (!take(bytes, offset, &count, 1) || count > uint32_t(kMaxLodLevels)) return false;
    levels.assign(count, {});
    for (LodLevel& level : levels) {
        uint32_t sizes[2] = {0, 0};
        if (!take(bytes, offset, sizes, 2) || !take(bytes, offset, &level.errorObject, 1)) return false;
        if (sizes[0] % 3 != 0 || uint64_t(sizes[0]) * 4 > bytes.size()) return false;
        level.indices.resize(sizes[0]);
        level.ranges.resize(sizes[1] <= sizes[0] + 1 ? sizes[1] : 0);
        if (level.ranges.size() != sizes[1]) return false;
    }
    for (LodLevel& level : levels) {
        if (!take(bytes, offset, level.indices.data(), level.indices.size()) ||
            !take(bytes, offset, level.ranges.data(), level.ranges.size()))
            return false;
        for (uint32_t index : level.indices)
            if (index >= vertexCount) return false;
        for (const Submesh& range : level.ranges)
            if (uint64_t(range.firstIndex) + range.indexCount > level.indices.size()) return false;
    }
    return offset == bytes.size();
}

std::vector<LodLevel> loadOrMakeLodLevels(const MeshData& mesh, const std::vector<Submesh>& ranges, bool* fromCache) {
    if (fromCache) *fromCache = false;
    const uint64_t key = lodCacheKey(mesh, ranges);
    const std::filesystem::path directory = cacheDirectory();
    const std::filesystem::path file = directory.empty() ? std::filesystem::path() : directory / cacheFileName("lod-", key);
    std::vector<uint8_t> bytes;
    std::vector<LodLevel> levels;
    if (readCacheFileOrWarn(file, kLodFile, key, bytes, kMaxLodPayloadBytes)) {
        if (decodeLodLevels(bytes, mesh.vertices.size(), levels)) {
            if (fromCache) *fromCache = true;
            return levels;
        }
        // The header and hash passed: only a writer of another layout gets here.
        log::warn("ignoring the levels of detail cache: " + file.string() + " does not describe levels of this mesh; recomputing");
    }
    levels = makeLodLevels(mesh, ranges);
    bytes = encodeLodLevels(levels);
    writeCacheFileOrWarn(file, kLodFile, key, {{bytes.data(), bytes.size()}});
    return levels;
}

}  // namespace dermis
