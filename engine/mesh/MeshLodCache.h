#pragma once
// A disk cache of levels of detail (mesh/MeshLod.h), keyed by the mesh's
// content, so that a mesh's levels are simplified and measured once per
// machine (1.4 s for the procedural head, most of it the measured error).
//
// Key: 64-bit FNV-1a over every vertex's position, the indices, the draw
// ranges, kLodCacheVersion and the constants of mesh/MeshLod.h. Directory:
// core/CacheDirectory.h. File lod-<16 hex digits>.bin, laid out as
// core/CacheFile.h says, whose payload is: u32 level count; per level u32
// index count, u32 range count, f32 errorObject; then per level its indices
// (u32) and ranges (Submesh, three 32-bit fields). A file that fails any
// check (those of core/CacheFile.h, or sizes, indices or ranges that do not
// fit the mesh) is ignored with one warning and the levels are made again;
// a directory that cannot be written gives a warning, never an error. The
// levels' normal maps (mesh/LodNormalMaps.h) are not cached.

#include "mesh/Model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

constexpr uint32_t kLodCacheVersion = 1;

uint64_t lodCacheKey(const MeshData& mesh, const std::vector<Submesh>& ranges);

// The levels from the cache, or makeLodLevels and an attempt to store them.
// fromCache (optional) says which.
std::vector<LodLevel> loadOrMakeLodLevels(const MeshData& mesh, const std::vector<Submesh>& ranges,
                                          bool* fromCache = nullptr);

// The payload's bytes for `levels`, and back; the reader returns false for
// bytes that do not describe levels over a mesh of vertexCount vertices.
std::vector<uint8_t> encodeLodLevels(const std::vector<LodLevel>& levels);
bool decodeLodLevels(const std::vector<uint8_t>& bytes, size_t vertexCount, std::vector<LodLevel>& levels);

}  // namespace dermis
