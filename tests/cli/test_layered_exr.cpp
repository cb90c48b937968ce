// `dermis render --aov all --out FILE.exr` (docs/cli.md): every AOV but the
// final image as a layer of one OpenEXR file, named as EXR viewers expect
// (the radiance as the default R, G, B, A; the others NAME.R ...), each layer
// the same floats that a render of that AOV alone writes.
#include "TestSupport.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kRun = " --size 64x36 --frames 1 --quiet";

struct Exr {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;  // interleaved
};

Exr readExr(const std::string& path) {
    Exr exr;
    auto input = OIIO::ImageInput::open(path);
    if (!input) return exr;
    const OIIO::ImageSpec& spec = input->spec();
    exr.width = spec.width;
    exr.height = spec.height;
    exr.channels = spec.channelnames;
    exr.pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
    input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, exr.pixels.data());
    return exr;
}

// The R, G, B, A of `layer` ("" for the default layer) from a layered file.
std::vector<float> layerOf(const Exr& exr, const std::string& layer) {
    std::vector<float> out;
    std::vector<int> index;
    for (const char* c : {"R", "G", "B", "A"}) {
        const std::string name = layer.empty() ? c : layer + "." + c;
        const auto found = std::find(exr.channels.begin(), exr.channels.end(), name);
        if (found == exr.channels.end()) return {};
        index.push_back(int(found - exr.channels.begin()));
    }
    const size_t stride = exr.channels.size();
    for (size_t texel = 0; texel < size_t(exr.width) * exr.height; ++texel)
        for (int c : index) out.push_back(exr.pixels[texel * stride + size_t(c)]);
    return out;
}

}  // namespace

// ctest: cost=22
TEST(LayeredExr, EveryAovIsALayerEqualToItsOwnRender) {
    TempDir dir;
    const std::string scene = dermis::test::contentScene("default.json");
    const ProcessResult all = runProcess(kDermis + " render " + scene + kRun + " --aov all --out " + dir.file("all.exr"));
    ASSERT_EQ(all.exitCode, 0) << all.err;
    const Exr layered = readExr(dir.file("all.exr"));
    ASSERT_EQ(layered.width, 64);
    EXPECT_EQ(layered.channels.size(), 4u * 14u) << "every AOV but final: 14 layers of 4 channels";
    for (const std::string aov : {"radiance", "depth", "diffuse", "normal", "object"}) {
        const std::string alone = dir.file(aov + ".exr");
        const ProcessResult r = runProcess(kDermis + " render " + scene + kRun + " --aov " + aov + " --out " + alone);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::vector<float> expected = layerOf(readExr(alone), "");
        const std::vector<float> layer = layerOf(layered, aov == "radiance" ? "" : aov);
        ASSERT_EQ(layer.size(), expected.size()) << aov << ": missing from the layered file";
        size_t different = 0;
        for (size_t i = 0; i < layer.size(); ++i) different += layer[i] != expected[i];
        EXPECT_EQ(different, 0u) << aov;
    }
    // Only to an .exr, and not with --sequence: usage errors, nothing written.
    for (const std::string bad : {" --aov all --out " + dir.file("x.png"), " --aov all --sequence 0:1:2 --out " + dir.file("x.exr")}) {
        const ProcessResult r = runProcess(kDermis + " render " + scene + " --size 32x18 --quiet" + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
        EXPECT_NE(r.err.find("--aov all"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}
