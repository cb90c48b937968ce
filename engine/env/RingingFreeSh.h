#pragma once
// SH projection of an environment map whose irradiance no bright texel can
// make negative (docs/environment.md, "Hot texels and ringing").
//
// Nine coefficients ring: the band-limited irradiance of one texel of power
// P (radiance x solid angle) towards omega is, at a normal N with t = N.omega,
//   E(t) = P / 4 [1 + 2 w1 t + 5/8 w2 (3 t^2 - 1)]
// (Ramamoorthi & Hanrahan 2001, eq. 7-8, with band l scaled by a window w_l).
// Unwindowed (w = 1) it dips to -0.0396 P at t = -8/15, 122 degrees from the
// texel: a sun of 1000 in a dim map of 0.5 takes the whole map's light from
// the far side of a sphere, and the clamp at 0 turns added light into lost
// light. Windowing the bands (Sloan 2008, "Stupid Spherical Harmonics (SH)
// Tricks") removes the dip: E(t) >= 0 for every t iff
// w1^2 <= (15 w2 / 8)(1 - 5 w2 / 8) (the quadratic's discriminant), and the
// window that keeps the most of band 1 is w = (1, sqrt(3)/2, 4/5).
//
// That window would also blur every smooth map's directional light by 13%,
// so only the part of each texel's power above
//   kShUnwindowedPowerFraction x 4 pi x median luminance
// goes through it (luminance decides, the texel's colour is kept); the rest
// is projected as it is. Then adding light to a texel changes the irradiance
// anywhere by at least -0.0396 x kShUnwindowedPowerFraction x 4 pi x median
// (the median of the map with the light added: added light can only raise
// it), 1.6e-4 of a uniform map's pi x median: a hot texel can only add light. A uniform map is projected exactly (the window
// leaves band 0 alone).

#include "core/Image.h"
#include "env/SphericalHarmonics.h"

#include <array>

namespace dermis {

inline constexpr std::array<float, 3> kShNonNegativeWindow = {1.0f, 0.8660254f, 0.8f};
inline constexpr double kShUnwindowedPowerFraction = 1.0 / 1024.0;

// The two parts of the projection: `smooth` the power below the cap, as it
// is; `hot` the power above it, windowed. The per-vertex transfer takes only
// the smooth part: its transfer vectors, integrated by rays, are not the
// exact clamped cosine the window's guarantee needs, and a sun's hot part
// times their error darkened a sphere's rim by 85% (docs/environment.md,
// "Hot texels and ringing"); the hot part is lit by its windowed irradiance
// at the normal instead, times the vertex's visible share.
struct SplitSh {
    Sh9 smooth;
    Sh9 hot;
    Sh9 total() const;  // smooth + hot
};
SplitSh projectLatLongSplit(const Image& map);

// The smooth part as a map: each texel's radiance scaled down to the part of
// its power below the cap (the hot share taken out). The visible share's rays
// read it; the hot part is weighed apart (env/ShTransfer.h, shareLightOf).
Image smoothPartOfLatLong(const Image& map);

// projectLatLong with the hot part of each texel windowed, as above: smooth + hot.
Sh9 projectLatLongWithoutRinging(const Image& map);

}  // namespace dermis
