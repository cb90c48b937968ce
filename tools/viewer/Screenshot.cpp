#include "viewer/Screenshot.h"

#include "gl/Gl.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace dermis::viewer {

Image readBackBuffer(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = ColourSpace::Srgb;
    const size_t rowBytes = static_cast<size_t>(width) * 4;
    std::vector<uint8_t> bottomFirst(rowBytes * static_cast<size_t>(height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomFirst.data());
    image.texels.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) {
        const uint8_t* row = bottomFirst.data() + static_cast<size_t>(height - 1 - y) * rowBytes;
        for (int x = 0; x < width; ++x) {
            const uint8_t* texel = row + static_cast<size_t>(x) * 4;
            // The window has no alpha worth keeping: the PNG is opaque.
            image.at(x, y) = glm::vec4(texel[0] / 255.0f, texel[1] / 255.0f, texel[2] / 255.0f, 1.0f);
        }
    }
    return image;
}

Status saveScreenshot(const std::string& path, int width, int height) {
    if (std::filesystem::path(path).extension() != ".png") {
        return makeError(path, "a screenshot is an 8-bit window capture: the file must end in .png");
    }
    if (width <= 0 || height <= 0) return makeError(path, "the window has no pixels to capture");
    return saveImage(path, readBackBuffer(width, height));
}

}  // namespace dermis::viewer
