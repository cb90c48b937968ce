#include "core/ImageResample.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace dermis {

Image resampleImage(const Image& image, int width, int height) {
    Image result;
    if (image.empty() || width <= 0 || height <= 0) return result;
    result.width = width;
    result.height = height;
    result.colourSpace = image.colourSpace;
    result.texels.assign(static_cast<size_t>(width) * static_cast<size_t>(height), glm::vec4(0.0f));
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
