// Texture uploads (render/GpuScene.h uploadImage, the memory budget of
// docs/testing.md "Memory"): colour as sRGB 8-bit, data as half floats, each
// uploaded in bands of rows; and the LEAN maps, uploaded band by band and
// level by level, hold the same texels as the chain made whole on the CPU.
#include "GlTestEnvironment.h"
#include "TestSupport.h"

#include "core/Image.h"
#include "gl/Gl.h"
#include "lean/LeanBake.h"
#include "render/GpuScene.h"

#include <cmath>
#include <random>

using namespace dermis;

namespace {

class TextureUpload : public test::GlTest {};

Image greyRamp(int width, int height, ColourSpace colourSpace) {
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = colourSpace;
    for (int i = 0; i < width * height; ++i) {
        const float v = static_cast<float>(i % 256) / 255.0f;
        image.texels.emplace_back(v, v, v, 1.0f);
    }
    return image;
}

GLint internalFormat(const gl::Texture& texture) {
    GLint format = 0;
    glGetTextureLevelParameteriv(texture.get(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    return format;
}

}  // namespace

// 300 rows span five upload bands: a band written to the wrong rows would
// put a ramp value where another belongs.
TEST_F(TextureUpload, ColourIsSrgb8AndDataHalfFloatEveryBandInItsRows) {
    EXPECT_EQ(internalFormat(uploadImage(greyRamp(16, 16, ColourSpace::Srgb), "test: ramp")), GL_SRGB8_ALPHA8);
    const Image ramp = greyRamp(3, 300, ColourSpace::Linear);
    const gl::Texture texture = uploadImage(ramp, "test: ramp");
    EXPECT_EQ(internalFormat(texture), GL_RGBA16F);
    std::vector<glm::vec4> back(ramp.texels.size());
    glGetTextureImage(texture.get(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(back.size() * sizeof(glm::vec4)),
                      back.data());
    // Half floats keep 11 significant bits and Mesa rounds toward zero: k / 255
    // within one unit in the last place, 2^-10 relative.
    for (size_t i = 0; i < back.size(); ++i)
        ASSERT_NEAR(back[i].r, ramp.texels[i].r, ramp.texels[i].r * 0x1p-10f) << i;
}

// A material with a normal map: its LEAN textures, read back per level, are
// the CPU chain (bakeLeanMaps) in half precision. 150 rows is three bands of
// kLeanBandRows; 37 columns makes every level's footprint fractional.
TEST_F(TextureUpload, LeanMapsUploadedInBandsEqualTheWholeChain) {
    ASSERT_LT(2 * kLeanBandRows, 150);
    std::mt19937 random(7u);
    std::normal_distribution<float> slope(0.0f, 0.4f);
    Image normals;
    normals.width = 37;
    normals.height = 150;
    for (int i = 0; i < normals.width * normals.height; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(slope(random), slope(random), 1.0f));
        normals.texels.emplace_back(n * 0.5f + 0.5f, 1.0f);
    }
    ModelMaterial material;
    material.normalMap = normals;
    auto gpu = uploadMaterial(material);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto whole = bakeLeanMaps(normals);
    ASSERT_TRUE(whole.ok());
    for (int level = 0; level < whole->levels(); ++level) {
        const Image& expected = whole->lean1[static_cast<size_t>(level)];
        std::vector<glm::vec4> back(expected.texels.size());
        glGetTextureImage(gpu->leanMap1.get(), level, GL_RGBA, GL_FLOAT,
                          static_cast<GLsizei>(back.size() * sizeof(glm::vec4)), back.data());
        // Half floats have 10 mantissa bits; Mesa rounds toward zero, so
        // allow one unit in the last place (a band at the wrong rows is off by
        // whole slopes).
        for (size_t i = 0; i < back.size(); ++i)
            for (int c = 0; c < 4; ++c)
                ASSERT_NEAR(back[i][c], expected.texels[i][c], std::abs(expected.texels[i][c]) * 0x1p-10f + 0x1p-24f)
                    << "level " << level << " texel " << i << " channel " << c;
    }
}
