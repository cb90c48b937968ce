#include "reference/TextureSampling.h"

#include <cmath>

namespace dermis::reference {

float srgbToLinear(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

Image decodeToLinear(const Image& image) {
    if (image.colourSpace == ColourSpace::Linear) return image;
    Image linear = image;
    linear.colourSpace = ColourSpace::Linear;
    for (glm::vec4& texel : linear.texels) {
        for (int c = 0; c < 3; ++c) texel[c] = srgbToLinear(texel[c]);
    }
    return linear;
}

}  // namespace dermis::reference
