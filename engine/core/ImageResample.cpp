#include "core/ImageResample.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace dermis {

Image makeImage(int width, int height, ColourSpace colourSpace, const glm::vec4& fill) {
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = colourSpace;
    image.texels.assign(static_cast<size_t>(width) * static_cast<size_t>(height), fill);
    return image;
}

Image resampleImage(const Image& image, int width, int height) {
    if (image.empty() || width <= 0 || height <= 0) return Image{};
    Image result = makeImage(width, height, image.colourSpace);
    // The source is wrapped, not copied; glm::vec4 is four tightly packed floats.
    const OIIO::ImageSpec sourceSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf source(sourceSpec, const_cast<glm::vec4*>(image.texels.data()));
    const OIIO::ImageSpec targetSpec(width, height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf target(targetSpec, result.texels.data());
    if (width >= image.width && height >= image.height) {
        OIIO::ImageBufAlgo::resample(target, source, /*interpolate=*/true);
    } else {
        OIIO::ImageBufAlgo::resize(target, source);
    }
    return result;
}

}  // namespace dermis
