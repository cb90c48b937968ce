#pragma once
// The error of a render split by cause and by image region (`dermis bench`,
// `dermis compare --errors`; docs/bench.md). No GL.
//
// Causes, each a relative RMSE of the diffuse AOV over SSS pixels:
//   total       the render against the full CPU reference (exact lighting,
//               exact scattering);
//   irradiance  the render with SSS off against the reference with SSS off:
//               what the lighting (shadow maps, filtering, precision) gets
//               wrong before any scattering;
//   scatter     the render against the matched-irradiance reference: the
//               render with SSS off plus the exact scattering change of the
//               engine's own irradiance (reference/ReferenceRenderer.h,
//               renderScatterChange), so only the SSS technique's own error
//               is left. With SSS off it is exactly 0.
// Regions partition the SSS pixels (ErrorRegion); every pixel is in one.

#include "core/EnumTable.h"
#include "core/Image.h"
#include "core/ImageMetrics.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace dermis::bench {

enum class ErrorCause { Total, Irradiance, Scatter };
inline constexpr EnumTable<ErrorCause, 3> kErrorCauses{
    "error cause",
    {{{ErrorCause::Total, "total", "against the full CPU reference"},
      {ErrorCause::Irradiance, "irradiance", "SSS off in both the render and the reference"},
      {ErrorCause::Scatter, "scatter", "against the matched-irradiance reference (the technique's own error)"}}}};

// Thickness is the distance through the part along the inward normal at the
// pixel's surface point (reference/ReferenceRenderer.h, renderThicknessMm).
// The bins follow the skin profile: its widest Gaussian has a standard
// deviation of 2.7 mm, so light crosses a part thinner than about 3 of them
// (8 mm), and under 4 mm (the ear's rim, the nostril wings) it dominates.
constexpr float kThinUnderMm = 4.0f;
constexpr float kThickFromMm = 8.0f;
// Pixels this close (in pixels, any direction) to another surface or the
// background: where the pixel footprint straddles an edge and the
// screen-space blur's neighbourhood is cut.
constexpr int kSilhouetteBandPx = 2;

enum class ErrorRegion { All, Silhouette, ThinUnder4Mm, Thin4To8Mm, Rest };
inline constexpr EnumTable<ErrorRegion, 5> kErrorRegions{
    "error region",
    {{{ErrorRegion::All, "all", "every SSS pixel"},
      {ErrorRegion::Silhouette, "silhouette", "within 2 px of another surface or the background"},
      {ErrorRegion::ThinUnder4Mm, "thin_under_4mm", "thinner than 4 mm through the part, off the silhouette"},
      {ErrorRegion::Thin4To8Mm, "thin_4_to_8mm", "4 to 8 mm through the part, off the silhouette"},
      {ErrorRegion::Rest, "rest", "every other SSS pixel"}}}};
constexpr uint8_t kNoRegion = 0xff;

// Per pixel: the region (an ErrorRegion other than All) of each SSS pixel,
// kNoRegion elsewhere. objectIds: 0 for the background, else the character
// index + 1; isSss[id]: whether that id has a diffusion profile (isSss[0] is
// false). thicknessMm: the reference's thickness image (r, mm; non-finite or
// huge where the ray leaves the part), the same size.
std::vector<uint8_t> classifyRegions(int width, int height, const std::vector<int>& objectIds,
                                     const std::vector<bool>& isSss, const Image& thicknessMm);

// Takes out of `regions` every pixel that a reference (alpha = its coverage)
// does not cover fully, and returns how many it took: a reference pixel that
// is partly background averages the background's 0 in, which the engine's
// point-sampled pixel never does.
size_t dropUncovered(std::vector<uint8_t>& regions, const std::vector<const Image*>& references);

// The mask (1 = compared) of one region; All selects every classified pixel.
std::vector<uint8_t> regionMask(const std::vector<uint8_t>& regions, ErrorRegion region);

// One figure per cause and region; nullopt where a region has no pixel or
// the cause was not measured.
struct CauseErrors {
    std::array<std::array<std::optional<ImageDifference>, kErrorRegions.size()>, kErrorCauses.size()> table;

    const std::optional<ImageDifference>& at(ErrorCause cause, ErrorRegion region) const {
        return table[size_t(cause)][size_t(region)];
    }
    // relative RMSE, NaN when not measured.
    double relativeRmse(ErrorCause cause, ErrorRegion region = ErrorRegion::All) const;
};

// Fills one cause's row: `test` against `reference` over each region.
void measureCause(CauseErrors& errors, ErrorCause cause, const Image& reference, const Image& test,
                  const std::vector<uint8_t>& regions);

// reference + change, texel by texel (RGB; alpha from `reference`): the
// matched-irradiance reference from a render with SSS off and the exact
// scattering change.
Image addImages(const Image& reference, const Image& change);

}  // namespace dermis::bench
