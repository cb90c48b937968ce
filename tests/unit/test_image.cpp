#include "core/Image.h"

#include "FuzzSupport.h"

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>

using namespace dermis;
namespace fs = std::filesystem;

namespace {

class ImageTest : public ::testing::Test {
public:
    std::string path(const std::string& name) const { return (mDir / name).string(); }

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

void writeBytes(const std::string& path, const std::vector<char>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Noise in every channel, so that the encoded data does not compress away and
// a mutation anywhere lands in real pixel data.
Image makeNoise(int width, int height, uint32_t seed) {
    Image image;
    image.width = width;
    image.height = height;
    std::mt19937 random(seed);
    for (int i = 0; i < width * height; ++i) {
        glm::vec4 texel;
        for (int c = 0; c < 4; ++c) texel[c] = static_cast<float>(random() & 0xffu) / 255.0f;
        image.texels.push_back(texel);
    }
    return image;
}

uint32_t readBigEndian(const std::vector<char>& bytes, size_t at) {
    uint32_t value = 0;
    for (size_t i = 0; i < 4; ++i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

void writeBigEndian(std::vector<char>& bytes, size_t at, uint32_t value) {
    for (size_t i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>(value >> (24 - 8 * i));
}

uint32_t crc32(const char* data, size_t size) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= static_cast<unsigned char>(data[i]);
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// Recomputes every chunk's CRC, so that libpng looks past the checksums and
// parses what a mutation did to the chunk itself. Stops at a chunk whose
// length runs past the end.
void repairPngCrcs(std::vector<char>& png) {
    constexpr size_t kSignatureBytes = 8;
    for (size_t at = kSignatureBytes; at + 12 <= png.size();) {
        const size_t length = readBigEndian(png, at);
        if (length > png.size() - at - 12) return;
        writeBigEndian(png, at + 8 + length, crc32(png.data() + at + 4, length + 4));
        at += 12 + length;
    }
}

// Where an EXR header's box2i attribute `name` keeps its xMax (yMax follows).
size_t exrBoxMaxOffset(const std::vector<char>& exr, const std::string& name) {
    const std::string key = name + std::string("\0box2i\0", 7);
    const auto found = std::search(exr.begin(), exr.end(), key.begin(), key.end());
    if (found == exr.end()) return 0;
    return static_cast<size_t>(found - exr.begin()) + key.size() + 4 + 8;  // size, then xMin and yMin
}

void writeLittleEndian(std::vector<char>& bytes, size_t at, uint32_t value) {
    for (size_t i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>(value >> (8 * i));
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

// The memory budget (core/Image.h kMaxImageTexels): one texel over it is
// refused from the header alone, with a line naming the file and the budget.
TEST_F(ImageTest, ImageAboveTheTexelBudgetIsRefusedByName) {
    const int width = kMaxImageDimension;
    const int height = static_cast<int>(kMaxImageTexels / static_cast<size_t>(width)) + 1;
    std::vector<uint8_t> grey(static_cast<size_t>(width) * static_cast<size_t>(height), 90);
    writeRaw<uint8_t>(path("big.png"), width, height, 1, OIIO::TypeDesc::UINT8, grey);
    Result<Image> loaded = loadImage(path("big.png"), ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    const std::string line = loaded.error().message();
    EXPECT_NE(line.find("big.png"), std::string::npos) << line;
    EXPECT_NE(line.find("budget of " + std::to_string(kMaxImageTexels)), std::string::npos) << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
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

// Each outcome of a broken file: an image, or an error that names the file
// (and, for memory, the name given) on one line.
void expectWellFormedOutcome(const Result<Image>& loaded, const std::string& name) {
    if (loaded) {
        EXPECT_GT(loaded->width, 0);
        EXPECT_EQ(loaded->texels.size(), static_cast<size_t>(loaded->width) * static_cast<size_t>(loaded->height));
        return;
    }
    EXPECT_NE(loaded.error().message().find(name), std::string::npos) << loaded.error().message();
    EXPECT_EQ(loaded.error().message().find('\n'), std::string::npos) << loaded.error().message();
}

TEST_F(ImageTest, PngAndExrTruncatedAtManyOffsetsAreErrors) {
    for (const char* extension : {".png", ".exr"}) {
        SCOPED_TRACE(extension);
        ASSERT_TRUE(saveImage(path(std::string("whole") + extension), makeNoise(32, 32, 7)));
        const std::vector<char> whole = readBytes(path(std::string("whole") + extension));
        size_t accepted = 0;
        for (const size_t length : fuzz::truncationLengths(whole.size(), 64, 48)) {
            SCOPED_TRACE("first " + std::to_string(length) + " bytes");
            const std::string file = path("cut" + std::to_string(length) + extension);
            writeBytes(file, fuzz::truncated(whole, length));
            const Result<Image> fromFile = loadImage(file, ColourSpace::Linear);
            expectWellFormedOutcome(fromFile, file);
            const std::string name = "cut" + std::to_string(length) + extension;
            expectWellFormedOutcome(loadImageFromMemory(whole.data(), length, name, ColourSpace::Linear), name);
            // A PNG may lose its 12-byte IEND chunk and still hold every pixel.
            if (length + 12 < whole.size()) accepted += fromFile ? 1 : 0;
        }
        EXPECT_EQ(accepted, 0u);
    }
}

TEST_F(ImageTest, HeaderClaimingHugeSizeIsRefusedBeforeAllocating) {
    ASSERT_TRUE(saveImage(path("small.png"), makeNoise(4, 4, 1)));
    std::vector<char> png = readBytes(path("small.png"));
    ASSERT_EQ(std::string(png.data() + 12, 4), "IHDR");
    writeBigEndian(png, 16, 100000);
    writeBigEndian(png, 20, 100000);
    repairPngCrcs(png);
    writeBytes(path("huge.png"), png);
    Result<Image> loaded = loadImage(path("huge.png"), ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().what.find("100000x100000"), std::string::npos) << loaded.error().message();
    EXPECT_EQ(loaded.error().where, path("huge.png"));
    loaded = loadImageFromMemory(png.data(), png.size(), "embedded huge", ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().what.find("100000x100000"), std::string::npos) << loaded.error().message();

    writeBigEndian(png, 16, 0x7fffffffu);  // beyond libpng's own limits
    repairPngCrcs(png);
    writeBytes(path("huger.png"), png);
    expectWellFormedOutcome(loadImage(path("huger.png"), ColourSpace::Linear), path("huger.png"));
    EXPECT_FALSE(loadImage(path("huger.png"), ColourSpace::Linear));

    ASSERT_TRUE(saveImage(path("small.exr"), makeNoise(4, 4, 1)));
    std::vector<char> exr = readBytes(path("small.exr"));
    for (const char* box : {"dataWindow", "displayWindow"}) {
        const size_t at = exrBoxMaxOffset(exr, box);
        ASSERT_NE(at, 0u) << box;
        writeLittleEndian(exr, at, 99999);
        writeLittleEndian(exr, at + 4, 99999);
    }
    writeBytes(path("huge.exr"), exr);
    // OpenEXR itself refuses this one (its line offset table runs past the
    // end of the file) before the size check is reached.
    loaded = loadImage(path("huge.exr"), ColourSpace::Linear);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().where, path("huge.exr"));
}

// 300 seeded mutants of a small noise image saved as `extension`, each read
// from disk and every fourth also from memory (the path of glTF-embedded
// images). PNG mutants at odd indices have their chunk CRCs repaired, so that
// libpng parses the damage instead of stopping at the checksum.
void expectMutantsWellFormed(ImageTest& test, const std::string& extension, uint32_t seed) {
    constexpr int kMutants = 300;
    const bool png = extension == ".png";
    ASSERT_TRUE(saveImage(test.path("valid" + extension), makeNoise(16, 16, 3)));
    const std::vector<char> valid = readBytes(test.path("valid" + extension));
    fuzz::Mutator mutator(seed);
    size_t accepted = 0;
    for (int mutant = 0; mutant < kMutants; ++mutant) {
        SCOPED_TRACE("mutant " + std::to_string(mutant));
        std::vector<char> bytes = mutator.mutate(valid);
        if (png && mutant % 2 == 1) repairPngCrcs(bytes);
        const std::string name = "mutant" + std::to_string(mutant) + extension;
        writeBytes(test.path(name), bytes);
        const Result<Image> fromFile = loadImage(test.path(name), ColourSpace::Srgb);
        expectWellFormedOutcome(fromFile, test.path(name));
        if (mutant % 4 == 0)
            expectWellFormedOutcome(loadImageFromMemory(bytes.data(), bytes.size(), name, ColourSpace::Srgb), name);
        accepted += fromFile ? 1 : 0;
    }
    // Mutations inside pixel data often still decode: both outcomes are exercised.
    EXPECT_GT(accepted, 0u);
    EXPECT_LT(accepted, size_t(kMutants));
}

TEST_F(ImageTest, RandomMutationsOfPngNeverCrash) { expectMutantsWellFormed(*this, ".png", 1009u); }

TEST_F(ImageTest, RandomMutationsOfExrNeverCrash) { expectMutantsWellFormed(*this, ".exr", 2003u); }
