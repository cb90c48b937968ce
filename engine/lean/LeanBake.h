#pragma once
// LEAN maps (Olano & Baker 2010, "LEAN Mapping", I3D, §3-4) baked from a
// tangent-space normal map, with their whole mip chain.
//
// Per texel, with n the unit normal (x along the tangent, y along the
// bitangent, +Y up the image as in OpenGL, decoded as n = texel * 2 - 1):
//   bump centre        B = (n.x / n.z, n.y / n.z)        (the slope of the facet)
//   second moments     M = (B.x^2, B.y^2, B.x B.y)
// Both are linear in the distribution of slopes, so averaging texels is exact:
// over any footprint the mean slope is E[B] and the slope covariance is
//   Sigma = [E[M.xx] - E[B.x]^2, E[M.xy] - E[B.x]E[B.y]; ., E[M.yy] - E[B.y]^2]
// (Olano & Baker eq. 9). Every mip level here is the area average of level 0,
// and hardware trilinear filtering is a further average, so both stay exact.
//
// Layout, per mip level (documented in content/scenes/README.md too):
//   lean1 = (B.x, B.y, M.xx, M.yy)
//   lean2 = (M.xy, base variance, 0, 1)
// The base variance is the slope variance per axis of the roughness below the
// map's resolution: a Beckmann surface of roughness m has the slope
// distribution exp(-|s|^2 / m^2) / (pi m^2), a Gaussian of variance m^2 / 2 per
// axis (Walter et al. 2007, eq. 28 in slope form). The renderer adds the
// material's own m^2 / 2 to it, so a map baked with roughness 0 (the default)
// leaves the material's roughness in charge.

#include "core/Image.h"
#include "core/Result.h"

#include <functional>
#include <string>
#include <vector>

namespace dermis {

// n.z is clamped up to this before dividing, so |B| <= sqrt(1 - z^2) / z ~ 16:
// a normal map texel that lies in (or below) the surface stays finite.
constexpr float kLeanMinNormalZ = 1.0f / 16.0f;

struct LeanMaps {
    std::vector<Image> lean1;  // per mip level, level 0 first: (B.x, B.y, M.xx, M.yy)
    std::vector<Image> lean2;  // per mip level: (M.xy, base variance, 0, 1)

    int levels() const { return static_cast<int>(lean1.size()); }
};

// One texel's moments from an encoded normal (texel * 2 - 1, normalised; a
// zero vector counts as the flat normal (0, 0, 1)).
glm::vec4 leanFirstMoments(const glm::vec3& encodedNormal);  // (B.x, B.y, M.xx, M.yy)
float leanCrossMoment(const glm::vec3& encodedNormal);       // M.xy

// The number of levels of a full chain: down to 1x1, halving (rounded down).
int leanMipLevelCount(int width, int height);

// One level down: each texel is the area average of the texels its footprint
// covers (odd sizes give fractional weights), so a level's mean equals level
// 0's mean exactly.
Image leanDownsample(const Image& level);

// Bakes both maps with the full chain. `baseRoughness` is a Beckmann m in
// [0, 1]. Errors for an empty image or a roughness out of range.
Result<LeanMaps> bakeLeanMaps(const Image& normalMap, float baseRoughness = 0.0f);

// The same levels, handed to `onLevel` in pieces and not kept, for the GPU
// upload (the memory budget, docs/testing.md "Memory"): level 0 in
// bands of at most kLeanBandRows rows starting at `firstRow`, level 1
// accumulated from those bands as they are made, and each later level whole
// (firstRow 0) from the one before. So no full-size float copy of level 0 is ever held: the peak is
// a quarter-size level instead of two full-size ones. The levels equal
// bakeLeanMaps's bit for bit.
constexpr int kLeanBandRows = 64;
using LeanLevelSink = std::function<void(int level, int firstRow, const Image& lean1, const Image& lean2)>;
Status bakeLeanLevels(const Image& normalMap, float baseRoughness, const LeanLevelSink& onLevel);

// Writes PREFIX_lean1.exr and PREFIX_lean2.exr, 32-bit float, every mip level
// as an OpenEXR mip-map (read back with loadMipChain).
Status saveLeanMaps(const std::string& prefix, const LeanMaps& maps);

// Every mip level of an image file (one level for a file without mips).
Result<std::vector<Image>> loadMipChain(const std::string& path);

}  // namespace dermis
