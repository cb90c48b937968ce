#pragma once
// The prefiltered environment map of the split-sum specular (Karis 2013,
// "Real Shading in Unreal Engine 4"): the renderer approximates the
// environment's Kelemen/Szirmay-Kalos specular as
//   L_spec(V) ~= rho_s rho_dt(N.V, m) Prefiltered(R, m) x specular occlusion,
// R the reflection of V about N, rho_dt the energy table's lobe albedo, and
//   Prefiltered(r, m) = sum L(l) D(h) (n.l) dw / sum D(h) (n.l) dw,
//   n = v = r, h = normalize(l + r), l over the hemisphere about r,
// D the Beckmann distribution of roughness m. This weight is Karis's: he
// importance-samples D (pdf D(h) (n.h) / (4 v.h) in l) and averages the
// samples weighted by n.l; with n = v the pdf's n.h / (4 v.h) is the
// constant 1/4, so his estimate converges to exactly this ratio. The KS
// lobe's Fresnel and 1 / |L + V|^2 factors are left to rho_dt, as Karis
// leaves F and G to his second sum.
//
// The map: a lat-long mip chain (env/SphericalHarmonics.h's layout) of
// kPrefilteredLevels levels, level k of (2 H / 2^k) x (H / 2^k) texels with
// H = kPrefilteredBaseHeight. Level 0 is the input resampled to that base
// (area-weighted, so radiance x solid angle is kept); level k >= 1 holds
// Prefiltered(r, m_k) at its texel centres, with the level <-> roughness
// mapping of shaders/include/SharedConstants.glsl. Each texel of level k is a
// brute-force sum over the texels of the base box-filtered down to level k's
// size (the lobe's standard deviation spans 3.6 of them), each weighted by its
// exact solid angle x D(h) (n.l); texels whose weight is below
// exp(-kLobeCutoffExponent) of the peak are skipped. Deterministic:
// no random samples.
//
// shaders/include/EnvironmentSpecular.glsl reads the chain on the GPU;
// PrefilteredEnvironment::radiance reads it on the CPU the same way.

#include "core/Image.h"
#include "include/SharedConstants.glsl"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

constexpr int kPrefilteredLevels = DERMIS_PREFILTERED_LEVELS;
constexpr int kPrefilteredBaseHeight = DERMIS_PREFILTERED_BASE_HEIGHT;
static_assert(kPrefilteredBaseHeight >> (kPrefilteredLevels - 1) >= 4, "the last level must be at least 8 x 4");

// The fractional level that holds roughness m (clamped to [0, levels - 1]),
// and its inverse; DERMIS_PREFILTERED_LEVEL_OF_ROUGHNESS is the definition.
float prefilteredLevelOfRoughness(float m);
float prefilteredRoughnessOfLevel(float level);

// A lat-long map resampled to width x height (width = 2 height) by the
// overlap of texel areas on the sphere: each output texel is the average of
// the input over its own solid angle, so sum L dw is kept exactly and no
// texel goes negative. Shrinking by an integer factor is a box filter;
// enlarging repeats texels (no interpolation).
Image resampleLatLongByArea(const Image& map, int width, int height);

class PrefilteredEnvironment {
public:
    PrefilteredEnvironment() = default;
    // `map`: a lat-long map of linear radiance with width = 2 height >= 8.
    // threads: 0 = all cores. progressLabel: empty for no progress bar.
    static PrefilteredEnvironment build(const Image& map, int threads = 0,
                                        const std::string& progressLabel = "prefiltering the environment");

    const std::vector<Image>& levels() const { return mLevels; }

    // Prefiltered(direction, m) read as EnvironmentSpecular.glsl reads it:
    // bilinear within a level (u repeats, v clamps), linear between the two
    // levels around prefilteredLevelOfRoughness(m). Black when empty.
    glm::vec3 radiance(const glm::vec3& direction, float m) const;

private:
    std::vector<Image> mLevels;
};

}  // namespace dermis
