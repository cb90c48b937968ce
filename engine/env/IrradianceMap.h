#pragma once
// The exact diffuse irradiance of an environment map at every normal
// (docs/environment.md, "Diffuse light: the irradiance map"):
//   E(n) = sum over texels of L(w) max(n.w, 0) dw,
// the cosine convolution that nine SH coefficients only approximate
// (Ramamoorthi & Hanrahan 2001 bound their error by the clamped cosine's
// bands past 2: under one 25 degree soft box they miss a sphere's irradiance
// by 9% of its peak, EnvironmentLightFrame.ASoftBoxLightsASphereAsTheFormFactorSays).
// Stored as a small lat-long map the shaders read bilinearly
// (shaders/include/Environment.glsl, environmentIrradiance).
//
// The convolution is brute force over the map's power gathered into the bins
// of a kIrradianceBinRows-row lat-long grid (texels of 2.8 degrees), each
// bin as the first moment sum of P w of its texels (P power, w direction).
// That is exact for every normal whose horizon does not cut the bin, so a sun
// smaller than a texel keeps both its power and its direction; a bin that the
// horizon cuts is lit as if its power sat at its moment's direction.

#include "core/Image.h"

#include <vector>

namespace dermis {

// Rows of the irradiance map (columns: twice as many), and of the bins its map is gathered into.
inline constexpr int kIrradianceMapHeight = 64;
inline constexpr int kIrradianceBinRows = 64;

// `radiance`: a lat-long map (width = 2 height) of linear radiance.
// Texel (u, v) of the result holds E at the normal latLongDirection(u, v).
Image makeIrradianceMap(const Image& radiance, int threads = 0);

// The cosine powers E_k(n) = sum over texels of L(w) max(n.w, 0)^k dw for
// k = 1 .. kIrradiancePowers (E_1 is makeIrradianceMap's), in the same layout,
// from the same bins: a bin of power P and first moment M adds
// P (n.M / P)^k where n.M > 0, exact for k = 1 and, for k > 1, within the
// spread of cosines over a bin of 2.8 degrees. With a cubic in the cosine
// they give the diffuse light a specular lobe leaves, per direction
// (render/GpuEnvironment.h, rhoDtCubicFits).
inline constexpr int kIrradiancePowers = 4;
std::vector<Image> makeIrradiancePowerMaps(const Image& radiance, int threads = 0);

// E at normal n read back as the shaders read it: bilinear between texel
// centres, u wrapping, v clamped to the first and last rows.
glm::vec3 sampleIrradianceMap(const Image& irradiance, const glm::vec3& normal);

}  // namespace dermis
