// Files written by a real encoder: `gltfpack` (Debian's, meshoptimizer 0.18)
// turns the project's test content into quantized (KHR_mesh_quantization with
// KHR_texture_transform) and meshopt-compressed (EXT_meshopt_compression, -c
// and -cc) files at test time, and each renders as the source file does. The
// skinned, morphing cylinder is rendered bent at 1 s, so joints, weights and
// the morph target are all decoded; the multi-material strip checks the
// materials and vertex colours. `draco_transcoder` (Debian's draco 1.5.5,
// KHR_draco_mesh_compression) refuses morph targets, so it gets the cylinder
// without its morph target. Each test skips with a message when its encoder
// is missing.
#include "TestContent.h"
#include "TestSupport.h"

#include "core/Image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

bool have(const std::string& tool) { return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0; }

// Mean absolute difference over RGB, in 1/255 steps of the 8-bit images.
double meanDifference255(const dermis::Image& a, const dermis::Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) sum += std::abs(double(a.texels[i][c]) - double(b.texels[i][c]));
    return 255.0 * sum / (3.0 * double(a.texels.size()));
}

size_t litTexels(const dermis::Image& image) {
    size_t count = 0;
    for (const glm::vec4& t : image.texels)
        if (t.r + t.g + t.b > 0.3f) ++count;
    return count;
}

class CompressedGltf : public ::testing::Test {
protected:
    void SetUp() override {
        if (!have("gltfpack")) GTEST_SKIP() << "gltfpack is not installed (Debian package gltfpack; tools/setup.sh installs it)";
        ASSERT_TRUE(dermis::test::writeBendingCylinder(mDir.file("cylinder.gltf")));
        ASSERT_TRUE(dermis::test::writeMultiMaterialStrip(mDir.file("strip.gltf"), nullptr));
    }
    // Renders `gltf` in the scene at 1 s (the cylinder bent, its morph target at full weight).
    dermis::Image render(const std::string& gltf, const std::string& name) {
        const bool cylinder = gltf.rfind("cylinder", 0) == 0;
        const std::string camera = cylinder ? R"({"position_m": [0.0, 0.11, 0.42], "target_m": [0.03, 0.11, 0.0]})"
                                            : R"({"position_m": [0.0, 0.07, 0.04], "target_m": [0.0, 0.0, 0.002]})";
        std::ofstream(mDir.file(name + ".json"))
            << R"({"camera": )" << camera << R"(, "lights": [{"type": "directional", "direction": [0.3, -1, -0.4]}],
  "characters": [{"name": "c", "mesh": {"gltf": ")" << gltf << R"("}, "metres_per_unit": 1)"
            << (cylinder ? R"(, "animation": {"clip": "bend"})" : "") << "}]}";
        const ProcessResult r = runProcess(kDermis + " render " + mDir.file(name + ".json") +
                                           " --size 160x90 --time 1 --out " + mDir.file(name + ".png"));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        auto image = dermis::loadImage(mDir.file(name + ".png"), dermis::ColourSpace::Srgb);
        EXPECT_TRUE(image.ok());
        return image.ok() ? *image : dermis::Image{};
    }
    TempDir mDir;
};

TEST_F(CompressedGltf, GltfpackOutputRendersAsItsSource) {
    struct Variant {
        const char* options;
        const char* suffix;
    };
    // Quantized positions, normals and UVs: measured 0.035/255 (cylinder) and 0.062/255
    // (strip) for every variant. The bound, 0.25/255 (the goals allow 1/255), catches a
    // wrong decode: without meshoptimizer's octahedral filter on -cc normals the two read
    // 1.11 and 0.48.
    const Variant variants[] = {{"", "q.glb"}, {"-c", "c.glb"}, {"-cc", "cc.glb"}, {"-c", "c.gltf"}};
    for (const char* source : {"cylinder", "strip"}) {
        const dermis::Image original = render(std::string(source) + ".gltf", std::string(source) + "_source");
        ASSERT_GT(litTexels(original), 300u) << source;
        for (const Variant& variant : variants) {
            const std::string packed = std::string(source) + "_" + variant.suffix;
            const ProcessResult pack = runProcess("gltfpack -i " + mDir.file(std::string(source) + ".gltf") + " -o " +
                                                  mDir.file(packed) + " " + variant.options);
            ASSERT_EQ(pack.exitCode, 0) << pack.err;
            const dermis::Image image = render(packed, packed);
            ASSERT_EQ(image.texels.size(), original.texels.size()) << packed;
            const double difference = meanDifference255(image, original);
            std::printf("%s: mean difference %.3f / 255 from %s.gltf\n", packed.c_str(), difference, source);
            EXPECT_LT(difference, 0.25) << packed;
        }
    }
}

// gltfpack -cf writes the uncompressed data to a fallback buffer file for
// loaders without EXT_meshopt_compression; Dermis decodes and never reads it, so
// the file may be left out (it was refused: "buffer 1 ... not found").
TEST_F(CompressedGltf, AMeshoptFallbackFileIsNotNeeded) {
    ASSERT_EQ(runProcess("gltfpack -i " + mDir.file("cylinder.gltf") + " -o " + mDir.file("cylinder_cf.glb") + " -cf").exitCode, 0);
    ASSERT_TRUE(std::filesystem::exists(mDir.file("cylinder_cf.fallback.bin")));
    const dermis::Image with = render("cylinder_cf.glb", "with_fallback");
    std::filesystem::remove(mDir.file("cylinder_cf.fallback.bin"));
    const dermis::Image without = render("cylinder_cf.glb", "without_fallback");
    ASSERT_GT(litTexels(with), 300u);
    ASSERT_EQ(without.texels.size(), with.texels.size());
    EXPECT_EQ(meanDifference255(without, with), 0.0);
}

TEST_F(CompressedGltf, CorruptMeshoptDataIsRefusedNamingTheView) {
    ASSERT_EQ(runProcess("gltfpack -i " + mDir.file("cylinder.gltf") + " -o " + mDir.file("c.gltf") + " -c").exitCode, 0);
    // Overwrite the start of the compressed buffer (c.bin, the same size): the first view's
    // data no longer starts with the codec's header byte, and meshoptimizer refuses it.
    {
        std::ifstream in(mDir.file("c.bin"), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), {});
        ASSERT_GT(bytes.size(), 16u);
        bytes.replace(0, 16, 16, '\xff');
        std::ofstream(mDir.file("c.bin"), std::ios::binary | std::ios::trunc) << bytes;
    }
    std::ofstream(mDir.file("c.json")) << R"({"characters": [{"name": "c", "mesh": {"gltf": "c.gltf"}}]})";
    const ProcessResult r = runProcess(kDermis + " render " + mDir.file("c.json") + " --size 32x18 --out " + mDir.file("c.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_FALSE(std::filesystem::exists(mDir.file("c.png")));
    EXPECT_NE(r.err.find("c.gltf"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bufferView 0: EXT_meshopt_compression data does not decode"), std::string::npos) << r.err;
}

TEST_F(CompressedGltf, DracoTranscoderOutputRendersAsItsSource) {
    if (!have("draco_transcoder")) GTEST_SKIP() << "draco_transcoder is not installed (Debian package draco)";
    // The cylinder without its morph target (and the clip's weight channel), which Draco
    // cannot hold; joints and weights stay, so the bent pose checks the skin attributes.
    nlohmann::json document;
    std::ifstream(mDir.file("cylinder.gltf")) >> document;
    for (auto& mesh : document["meshes"]) {
        mesh.erase("weights");
        for (auto& primitive : mesh["primitives"]) primitive.erase("targets");
    }
    for (auto& animation : document["animations"]) {
        nlohmann::json kept = nlohmann::json::array();
        for (auto& channel : animation["channels"])
            if (channel["target"]["path"] != "weights") kept.push_back(channel);
        animation["channels"] = kept;
    }
    std::ofstream(mDir.file("cylinder_rigid.gltf")) << document.dump();
    const dermis::Image original = render("cylinder_rigid.gltf", "cylinder_rigid");
    ASSERT_GT(litTexels(original), 300u);
    for (const char* packed : {"cylinder_draco.glb", "cylinder_draco.gltf"}) {
        const ProcessResult pack =
            runProcess("draco_transcoder -i " + mDir.file("cylinder_rigid.gltf") + " -o " + mDir.file(packed));
        ASSERT_EQ(pack.exitCode, 0) << pack.err << pack.out;
        const dermis::Image image = render(packed, packed);
        ASSERT_EQ(image.texels.size(), original.texels.size()) << packed;
        // draco_transcoder's default quantization: measured 0.027/255; the bound is the gltfpack
        // test's. Reading each point's value without Draco's point-to-value map gives 12.3.
        const double difference = meanDifference255(image, original);
        std::printf("%s: mean difference %.3f / 255 from cylinder_rigid.gltf\n", packed, difference);
        EXPECT_LT(difference, 0.25) << packed;
    }
}

}  // namespace
