#pragma once
// Normal maps for levels of detail. A level shares the full mesh's vertices
// but interpolates their normals and tangents over larger triangles, so the
// material's tangent-space normal map, read in the level's frame, gives
// another shading normal than the full mesh's. This bakes, per level and
// material, the full mesh's shading normal (its interpolated frame times the
// normal map) re-expressed in the level's interpolated frame: the level then
// shades with the full mesh's normals wherever its UVs reach, and skinning
// carries over because the map stays in tangent space. The usual way to move
// detail from a fine mesh to a coarse one (Cohen, Olano & Manocha, "Appearance-
// Preserving Simplification", 1998), here with both meshes sharing one UV layout.

#include "core/Image.h"
#include "mesh/Model.h"

#include <vector>

namespace dermis {

// Rings of texels the baked map is grown by beyond the level's charts, so that
// filtering there reads the level's normals; further out the material's own
// map remains.
constexpr int kLodNormalGutterRings = 8;

// The map `normalMap` of material `material` for `level`, at its resolution;
// texels outside the level's triangles keep normalMap's values. flipV: the
// character samples its maps at (u, 1 - v) (Character::material.flipV).
// Empty when the material has no normal map or no triangles.
Image bakeLodNormalMap(const MeshData& mesh, const std::vector<Submesh>& fullRanges, const LodLevel& level, int material,
                       const Image& normalMap, bool flipV);

// bakeLodNormalMap for every level and material of `model` into
// LodLevel::normalMaps.
void bakeLodNormalMaps(Model& model, bool flipV);

}  // namespace dermis
