// `dermis bake-lean` and `dermis render --variant` as a user runs them.
#include "TestSupport.h"

#include "core/Image.h"
#include "lean/LeanBake.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

std::string defaultScene() { return dermis::test::contentScene("default.json"); }

std::string writeNormalMap(const TempDir& dir) {
    dermis::Image image;
    image.width = 24;
    image.height = 10;
    for (int i = 0; i < image.width * image.height; ++i) {
        const float tilt = (i % 3) * 0.2f;
        image.texels.push_back(glm::vec4(glm::normalize(glm::vec3(tilt, -tilt, 1.0f)) * 0.5f + 0.5f, 1.0f));
    }
    EXPECT_TRUE(dermis::saveImage(dir.file("normals.png"), image).ok());
    return dir.file("normals.png");
}

std::set<std::string> executedPasses(const std::string& timingsFile) {
    const auto timings = nlohmann::json::parse(dermis::test::readTextFile(timingsFile));
    std::set<std::string> names;
    for (const auto& pass : timings["passes"]) {
        if (pass["executed"].get<bool>()) names.insert(pass["name"].get<std::string>());
    }
    return names;
}

}  // namespace

TEST(LeanCli, BakeWritesBothMapsWithTheirMipChains) {
    TempDir dir;
    const std::string input = writeNormalMap(dir);
    const ProcessResult r =
        runProcess(kDermis + " bake-lean " + input + " --out " + dir.file("out/n") + " --roughness 0.2 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* suffix : {"_lean1.exr", "_lean2.exr"}) {
        auto levels = dermis::loadMipChain(dir.file(std::string("out/n") + suffix));
        ASSERT_TRUE(levels.ok()) << levels.error().message();
        EXPECT_EQ(levels->size(), 5u);  // 24x10, 12x5, 6x2, 3x1, 1x1
        EXPECT_EQ(levels->back().width, 1);
    }
    auto lean2 = dermis::loadMipChain(dir.file("out/n_lean2.exr"));
    ASSERT_TRUE(lean2.ok());
    EXPECT_NEAR((*lean2)[0].texels[0].y, 0.5f * 0.2f * 0.2f, 1e-6);
}

TEST(LeanCli, BakeRefusesBadInputWithOneLine) {
    TempDir dir;
    const std::string input = writeNormalMap(dir);
    const ProcessResult noOut = runProcess(kDermis + " bake-lean " + input);
    EXPECT_EQ(noOut.exitCode, 2);
    EXPECT_NE(noOut.err.find("--out PREFIX is required"), std::string::npos) << noOut.err;
    const ProcessResult badRoughness = runProcess(kDermis + " bake-lean " + input + " --out " + dir.file("x") +
                                                  " --roughness 1.5");
    EXPECT_EQ(badRoughness.exitCode, 2);
    EXPECT_NE(badRoughness.err.find("--roughness 1.5"), std::string::npos) << badRoughness.err;
    const ProcessResult missing = runProcess(kDermis + " bake-lean " + dir.file("none.png") + " --out " + dir.file("x"));
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("none.png"), std::string::npos) << missing.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x_lean1.exr")));
    const ProcessResult help = runProcess(kDermis + " bake-lean --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("PREFIX_lean1.exr"), std::string::npos);
}

// The variants are one graph: the final frame runs the same passes in c and
// lbb (lbb's G-buffer, blurs and composite carry the moments, c's do not);
// the specular AOV of lbb adds the LEAN specular pass.
// ctest: cost=55
TEST(LeanCli, VariantsAreOneGraphWithDifferentTargets) {
    TempDir dir;
    auto passesOf = [&](const char* variant, const char* aov) {
        const std::string timings = dir.file(std::string(variant) + aov + ".json");
        const ProcessResult r = runProcess(kDermis + " render " + defaultScene() + " --size 96x54 --frames 1 --variant " +
                                           variant + " --aov " + aov + " --out " + dir.file("x.exr") + " --timings " +
                                           timings + " --quiet");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0 ? executedPasses(timings) : std::set<std::string>{};
    };
    const std::set<std::string> control = passesOf("c", "final");
    EXPECT_FALSE(control.empty());
    EXPECT_EQ(passesOf("lbb", "final"), control);
    EXPECT_EQ(passesOf("c", "specular").count("lean specular"), 0u);
    EXPECT_EQ(passesOf("lbb", "specular").count("lean specular"), 1u);
    const ProcessResult bad = runProcess(kDermis + " render " + defaultScene() + " --variant lean --out " + dir.file("y.png"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("expected c, lcb or lbb"), std::string::npos) << bad.err;
}
