#include "core/Image.h"

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

using namespace dermis;
namespace fs = std::filesystem;

namespace {

class ImageTest : public ::testing::Test {
protected:
    void SetUp() override {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::temp_directory_path() /
               ("dermis_image_" + std::to_string(::getpid()) + "_" + std::string(info->name()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(mDir, ignored);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    size_t fileCount() const { return static_cast<size_t>(std::distance(fs::directory_iterator(mDir), {})); }

    fs::path mDir;
};

Image makeGradient(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.texels.emplace_back(static_cast<float>(x) / static_cast<float>(width - 1),
                                      static_cast<float>(y) / static_cast<float>(height - 1),
                                      static_cast<float>((x * 7 + y * 13) % 17) / 16.0f,
                                      0.25f + 0.5f * static_cast<float>(x % 2));
    return image;
}

// Writes raw channels with OpenImageIO directly, bypassing saveImage.
template <class T>
void writeRaw(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
              const std::vector<T>& data) {
    auto output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output);
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // write the values as given
    ASSERT_TRUE(output->open(path, spec)) << output->geterror();
    ASSERT_TRUE(output->write_image(type, data.data())) << output->geterror();
    ASSERT_TRUE(output->close());
}

std::vector<char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_F(ImageTest, PngRoundTripWithinOneLevel) {
    Image image = makeGradient(9, 6);
    image.texels[0] = glm::vec4(-1.0f, 2.0f, 0.5f, 1.0f);  // clamped on save
    ASSERT_TRUE(saveImage(path("a.png"), image));
    int sanitised = -1;
    Result<Image> loaded = loadImage(path("a.png"), ColourSpace::Srgb, &sanitised);
    ASSERT_TRUE(loaded) << loaded.error().message();
    EXPECT_EQ(loaded->width, 9);
    EXPECT_EQ(loaded->height, 6);
    EXPECT_EQ(loaded->colourSpace, ColourSpace::Srgb);
    EXPECT_EQ(sanitised, 0);
    image.texels[0] = glm::vec4(0.0f, 1.0f, 0.5f, 1.0f);
    for (size_t i = 0; i < image.texels.size(); ++i)
        for (int c = 0; c < 4; ++c)
            // Alpha below 1 must not premultiply colour on either side.
            EXPECT_NEAR(loaded->texels[i][c], image.texels[i][c], 1.0f / 255.0f) << "texel " << i << " channel " << c;
    EXPECT_EQ(fileCount(), 1u);  // no temporary left beside it
}

TEST_F(ImageTest, ExrRoundTripIsExact) {
    Image image = makeGradient(5, 4);
    image.texels[3] = glm::vec4(-2.5f, 1234.5f, 1e-7f, 3.0f);
    ASSERT_TRUE(saveImage(path("a.exr"), image));
    Result<Image> loaded = loadImage(path("a.exr"), ColourSpace::Linear);
    ASSERT_TRUE(loaded) << loaded.error().message();
    ASSERT_EQ(loaded->texels.size(), image.texels.size());
    for (size_t i = 0; i < image.texels.size(); ++i) EXPECT_EQ(loaded->texels[i], image.texels[i]) << "texel " << i;
}

TEST_F(ImageTest, RowZeroIsTheTopRow) {
    Image image = makeGradient(3, 3);
    ASSERT_TRUE(saveImage(path("rows.exr"), image));
    auto input = OIIO::ImageInput::open(path("rows.exr"));
    ASSERT_TRUE(input);
    std::vector<float> firstRow(3 * 4);
    ASSERT_TRUE(input->read_scanline(0, 0, OIIO::TypeFloat, firstRow.data()));
    EXPECT_EQ(firstRow[4 + 0], image.at(1, 0).x);
    EXPECT_EQ(firstRow[4 + 2], image.at(1, 0).z);
}

TEST_F(ImageTest, GreyPngExpandsToRgba) {
    writeRaw<uint8_t>(path("grey.png"), 2, 1, 1, OIIO::TypeDesc::UINT8, {0, 255});
    Result<Image> grey = loadImage(path("grey.png"), ColourSpace::Linear);
    ASSERT_TRUE(grey) << grey.error().message();
    EXPECT_EQ(grey->texels[0], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(grey->texels[1], glm::vec4(1.0f, 1.0f, 1.0f, 1.0f));

    writeRaw<uint8_t>(path("greyalpha.png"), 1, 1, 2, OIIO::TypeDesc::UINT8, {51, 102});
    Result<Image> greyAlpha = loadImage(path("greyalpha.png"), ColourSpace::Linear);
    ASSERT_TRUE(greyAlpha) << greyAlpha.error().message();
    EXPECT_NEAR(greyAlpha->texels[0].x, 0.2f, 1e-6f);
    EXPECT_NEAR(greyAlpha->texels[0].z, 0.2f, 1e-6f);
    EXPECT_NEAR(greyAlpha->texels[0].w, 0.4f, 1e-6f);

    writeRaw<uint8_t>(path("rgb.png"), 1, 1, 3, OIIO::TypeDesc::UINT8, {255, 0, 51});
    Result<Image> rgb = loadImage(path("rgb.png"), ColourSpace::Linear);
    ASSERT_TRUE(rgb) << rgb.error().message();
    EXPECT_NEAR(rgb->texels[0].z, 0.2f, 1e-6f);
    EXPECT_EQ(rgb->texels[0].w, 1.0f);
}

TEST_F(ImageTest, SixteenBitPngIsScaledToUnitRange) {
    writeRaw<uint16_t>(path("deep.png"), 3, 1, 1, OIIO::TypeDesc::UINT16, {0, 32768, 65535});
    Result<Image> loaded = loadImage(path("deep.png"), ColourSpace::Linear);
    ASSERT_TRUE(loaded) << loaded.error().message();
    EXPECT_EQ(loaded->texels[0].x, 0.0f);
    EXPECT_NEAR(loaded->texels[1].x, 32768.0f / 65535.0f, 1e-6f);
    EXPECT_EQ(loaded->texels[2].x, 1.0f);
}

TEST_F(ImageTest, TruncatedPngIsAnErrorNamingThePath) {
    Image image = makeGradient(64, 64);
    uint32_t state = 12345u;
    for (glm::vec4& texel : image.texels) {  // noise, so the data does not compress away
        state = state * 1664525u + 1013904223u;
        texel.z = static_cast<float>(state >> 24) / 255.0f;
    }
    ASSERT_TRUE(saveImage(path("whole.png"), image));
    std::vector<char> bytes = readBytes(path("whole.png"));
    ASSERT_GT(bytes.size(), 1000u);
    {
        std::ofstream out(path("cut.png"), std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    }
    Result<Image> loaded = loadImage(path("cut.png"), ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().message().find(path("cut.png")), std::string::npos) << loaded.error().message();
    EXPECT_EQ(loaded.error().message().find('\n'), std::string::npos) << loaded.error().message();
    EXPECT_EQ(fileCount(), 2u);
}

TEST_F(ImageTest, GarbageAndMissingFilesAreErrors) {
    { std::ofstream(path("junk.png")) << "this is not a png"; }
    Result<Image> junk = loadImage(path("junk.png"), ColourSpace::Linear);
    ASSERT_FALSE(junk);
    EXPECT_NE(junk.error().message().find("junk.png"), std::string::npos);

    Result<Image> missing = loadImage(path("nope.png"), ColourSpace::Linear);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().where, path("nope.png"));

    EXPECT_FALSE(loadImage(mDir.string(), ColourSpace::Linear));  // a directory
}

TEST_F(ImageTest, OversizedImageIsRefused) {
    std::vector<uint8_t> row(static_cast<size_t>(kMaxImageDimension) + 1, 128);
    writeRaw<uint8_t>(path("wide.png"), kMaxImageDimension + 1, 1, 1, OIIO::TypeDesc::UINT8, row);
    Result<Image> loaded = loadImage(path("wide.png"), ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().what.find("16385"), std::string::npos) << loaded.error().message();
}

TEST_F(ImageTest, UnsupportedExtensionWritesNothing) {
    Image image = makeGradient(2, 2);
    Status saved = saveImage(path("a.tga"), image);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().where, path("a.tga"));
    EXPECT_FALSE(saveImage(path("noextension"), image));
    EXPECT_EQ(fileCount(), 0u);
}

TEST_F(ImageTest, FailedSaveLeavesNoPartialFile) {
    fs::create_directories(path("occupied.png"));  // a directory where the file should go
    Status saved = saveImage(path("occupied.png"), makeGradient(4, 4));
    ASSERT_FALSE(saved);
    EXPECT_NE(saved.error().message().find("occupied.png"), std::string::npos);
    EXPECT_EQ(fileCount(), 1u);  // only the directory; the temporary was removed

    Image broken = makeGradient(4, 4);
    broken.texels.pop_back();
    EXPECT_FALSE(saveImage(path("broken.exr"), broken));
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(ImageTest, SaveCreatesMissingDirectories) {
    std::string nested = path("one/two/out.exr");
    ASSERT_TRUE(saveImage(nested, makeGradient(2, 2)));
    EXPECT_TRUE(fs::is_regular_file(nested));
}

TEST_F(ImageTest, NonFiniteExrTexelsAreSanitisedAndCounted) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> data = {0.5f, nan, 0.25f, 1.0f,   // texel 0: one NaN
                               inf,  -inf, nan, nan,     // texel 1: all non-finite
                               0.1f, 0.2f, 0.3f, 0.4f};  // texel 2: clean
    writeRaw<float>(path("nan.exr"), 3, 1, 4, OIIO::TypeDesc::FLOAT, data);
    int sanitised = -1;
    Result<Image> loaded = loadImage(path("nan.exr"), ColourSpace::Linear, &sanitised);
    ASSERT_TRUE(loaded) << loaded.error().message();
    EXPECT_EQ(sanitised, 2);
    EXPECT_EQ(loaded->texels[0], glm::vec4(0.5f, 0.0f, 0.25f, 1.0f));
    EXPECT_EQ(loaded->texels[1], glm::vec4(0.0f));
    EXPECT_EQ(loaded->texels[2], glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
}

TEST_F(ImageTest, DecodesFromMemory) {
    Image image = makeGradient(4, 3);
    ASSERT_TRUE(saveImage(path("m.png"), image));
    std::vector<char> bytes = readBytes(path("m.png"));
    Result<Image> loaded = loadImageFromMemory(bytes.data(), bytes.size(), "embedded", ColourSpace::Srgb);
    ASSERT_TRUE(loaded) << loaded.error().message();
    ASSERT_EQ(loaded->texels.size(), image.texels.size());
    for (size_t i = 0; i < image.texels.size(); ++i)
        EXPECT_NEAR(loaded->texels[i].y, image.texels[i].y, 1.0f / 255.0f);

    Result<Image> cut = loadImageFromMemory(bytes.data(), bytes.size() / 2, "image 3", ColourSpace::Srgb);
    ASSERT_FALSE(cut);
    EXPECT_EQ(cut.error().where, "image 3");
    const char junk[] = "definitely not an image";
    EXPECT_FALSE(loadImageFromMemory(junk, sizeof junk, "junk", ColourSpace::Srgb));
    EXPECT_FALSE(loadImageFromMemory(nullptr, 0, "empty", ColourSpace::Srgb));
}
