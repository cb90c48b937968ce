#pragma once
// Resampling an image to another size with OpenImageIO: bilinear
// interpolation when enlarging (ImageBufAlgo::resample), a filtered average
// when shrinking (ImageBufAlgo::resize, its default lanczos3).
// `dermis bench` uses it to compare a frame rendered at a lower resolution
// with a full-size reference.

#include "core/Image.h"

namespace dermis {

// A width x height image of `colourSpace` with every texel `fill`: the blank
// target of a resampling.
Image makeImage(int width, int height, ColourSpace colourSpace, const glm::vec4& fill = glm::vec4(0.0f));

// The same colour space; alpha is resampled like the colour. An empty image
// for an empty input or a non-positive size.
Image resampleImage(const Image& image, int width, int height);

}  // namespace dermis
