#pragma once
// Comparing two renders of the same frame (screen space against texture
// space, a render against a CPU reference): error figures over a mask of
// pixels, and a false-colour difference image with a scale bar. No GL.

#include "core/Image.h"
#include "core/Result.h"

#include <cstdint>
#include <vector>

namespace dermis {

struct ImageDifference {
    size_t pixels = 0;              // pixels compared (those in the mask)
    double rmse = 0.0;              // root mean square of the RGB channel differences
    double relativeRmse = 0.0;      // rmse / root mean square of the reference's RGB channels
    double maxAbsDifference = 0.0;  // the largest |reference - test| of any RGB channel
    double peak = 0.0;              // the largest reference RGB channel value
    double psnrDb = 0.0;            // 10 log10(peak^2 / mse), at most kMaxPsnrDb (identical images)
};

constexpr double kMaxPsnrDb = 200.0;

// mask: one byte per pixel, non-zero = compared; empty = every pixel. Errors
// for images of different sizes, a mask of another size, or an empty
// selection. Non-finite texels count as a difference of +infinity (so
// maxAbsDifference and rmse are +inf and psnrDb 0).
Result<ImageDifference> compareImages(const Image& reference, const Image& test, const std::vector<uint8_t>& mask = {});

// The mask of the pixels an object AOV (character index + 1, 0 for the
// background; read rounded) gives to `id`, for compareImages.
std::vector<uint8_t> objectMask(const Image& objectAov, long id);

// The per-pixel difference max_c |reference_c - test_c| in false colour
// (black-blue-purple-orange-yellow), pixels outside the mask in dark grey, and
// a scale bar with labels on the right (0 at the bottom, scaleMax at the top).
// scaleMax <= 0 picks a round number at or above the largest difference.
// The result is display-ready (ColourSpace::Srgb, values in [0,1]) for a PNG.
Image differenceHeatmap(const Image& reference, const Image& test, const std::vector<uint8_t>& mask,
                        double scaleMax = 0.0);

// The given fraction (0..1) of the per-pixel differences max_c |reference_c -
// test_c| over the mask lies at or below the returned value (non-finite
// differences count as the largest). 0 when the inputs do not match.
double differencePercentile(const Image& reference, const Image& test, const std::vector<uint8_t>& mask,
                            double fraction);

// The smallest 1, 2 or 5 x 10^k at or above x (x > 0); 1 for x <= 0.
double roundUpToNiceNumber(double x);

}  // namespace dermis
