// `dermis reference` as a user runs it: a small run writes a linear EXR of the
// diffuse AOV; bad input gives one error line, a non-zero exit and no file.
#include "TestSupport.h"

#include "core/Image.h"

#include <gtest/gtest.h>

#include <filesystem>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

std::string furnaceScene() { return dermis::test::contentScene("furnace.json"); }

size_t errorLines(const std::string& err) {
    size_t count = 0;
    for (size_t at = err.find("error: "); at != std::string::npos; at = err.find("error: ", at + 1)) ++count;
    return count;
}

}  // namespace

TEST(ReferenceCli, WritesTheDiffuseAovOfTheFurnace) {
    TempDir dir;
    const ProcessResult r = runProcess(kDermis + " reference " + furnaceScene() + " --size 8x6 --density 2 --threads 2 --out " +
                                       dir.file("ref.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto image = dermis::loadImage(dir.file("ref.exr"), dermis::ColourSpace::Linear);
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, 8);
    ASSERT_EQ(image->height, 6);
    // The furnace plane fills the view: albedo (0.8, 0.6, 0.5) under unit light, less the
    // specular's share on the way out (rho_s 0.18).
    for (const glm::vec4& texel : image->texels) {
        EXPECT_EQ(texel.a, 1.0f);
        EXPECT_NEAR(texel.r, 0.8f * 0.97f, 0.01f);
        EXPECT_NEAR(texel.b, 0.5f * 0.97f, 0.01f);
    }
}

TEST(ReferenceCli, BadInputFailsCleanly) {
    TempDir dir;
    const std::string out = dir.file("ref.exr");
    struct Case {
        std::string arguments;
        int exitCode;
        std::string mention;
    };
    const Case cases[] = {
        {furnaceScene() + " --out " + out + " --density 0", 2, "--density"},
        {furnaceScene() + " --out " + out + " --aov specular", 2, "--aov"},
        {furnaceScene() + " --out " + out + " --spp 2", 2, "--spp"},  // not a perfect square
        {furnaceScene() + " --out " + dir.file("ref.png"), 2, ".exr"},
        {furnaceScene() + " --out " + out + " --set sss.mix=7", 2, "mix"},  // a refused --set is a usage error
        {dir.file("missing.json") + " --out " + out, 1, "missing.json"},
        // A file where the folder should be: found before the reference is computed.
        {furnaceScene() + " --out " + dir.file("a-file/ref.exr"), 1, dir.file("a-file") + ": cannot create the directory: a file of that name is in the way"},
    };
    dermis::test::writeTextFile(dir.file("a-file"), "not a folder");
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " reference " + c.arguments);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.arguments << "\n" << r.err;
        EXPECT_EQ(errorLines(r.err), 1u) << c.arguments << "\n" << r.err;
        EXPECT_NE(r.err.find(c.mention), std::string::npos) << c.arguments << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
        EXPECT_FALSE(std::filesystem::exists(dir.file("ref.png")));
    }
}

// compare --reference takes only a reference of the scene it renders: one of
// another scene, of other settings the reference reads, or an 8-bit image gives
// one error naming the file and what differs, where metrics of a meaningless
// comparison used to be written with exit 0. What the reference leaves out
// (SSAO here) may differ.
TEST(ReferenceCli, CompareRefusesAReferenceOfAnotherScene) {
    TempDir dir;
    const std::string furnace = furnaceScene();
    const std::string slab = dermis::test::contentScene("slab.json");
    ASSERT_EQ(runProcess(kDermis + " reference " + furnace + " --size 8x6 --density 2 --spp 1 --quiet --out " +
                         dir.file("ref.exr")).exitCode, 0);
    ASSERT_EQ(runProcess(kDermis + " render " + furnace + " --size 8x6 --frames 1 --quiet --out " + dir.file("frame.png")).exitCode, 0);
    const std::string compare = " --size 8x6 --frames 1 --quiet --reference ";

    const ProcessResult same = runProcess(kDermis + " compare " + furnace + compare + dir.file("ref.exr") +
                                          " --set ssao.enabled=false --out " + dir.file("same"));
    EXPECT_EQ(same.exitCode, 0) << same.err;

    const ProcessResult other = runProcess(kDermis + " compare " + slab + compare + dir.file("ref.exr") + " --out " + dir.file("other"));
    EXPECT_EQ(other.exitCode, 1) << other.err;
    EXPECT_NE(other.err.find(dir.file("ref.exr") + ": a reference of another scene: it differs from " + slab + " in its camera"),
              std::string::npos)
        << other.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("other"))) << "the folder it made for its outputs stays";
    EXPECT_TRUE(std::filesystem::exists(dir.file("same") + "/metrics.json"));

    const ProcessResult mix = runProcess(kDermis + " compare " + furnace + compare + dir.file("ref.exr") +
                                         " --set sss.mix=0.3 --out " + dir.file("mix"));
    EXPECT_EQ(mix.exitCode, 1) << mix.err;
    EXPECT_NE(mix.err.find("in its settings"), std::string::npos) << mix.err;

    const ProcessResult png = runProcess(kDermis + " compare " + furnace + compare + dir.file("frame.png") + " --out " + dir.file("png"));
    EXPECT_EQ(png.exitCode, 1) << png.err;
    EXPECT_NE(png.err.find("must be a linear float image"), std::string::npos) << png.err;
    for (const ProcessResult* r : {&other, &mix, &png}) EXPECT_EQ(errorLines(r->err), 1u) << r->err;
    EXPECT_EQ(same.err.find("samples per pixel"), std::string::npos) << same.err;

    // Two references used with a warning on stderr: an EXR without the record
    // (the engine's own frame here), taken as it is; an antialiased one
    // (--spp 4), where the engine shades pixel centres.
    ASSERT_EQ(runProcess(kDermis + " render " + furnace + " --size 8x6 --frames 1 --quiet --aov diffuse --out " +
                         dir.file("frame.exr")).exitCode, 0);
    ASSERT_EQ(runProcess(kDermis + " reference " + furnace + " --size 8x6 --density 2 --spp 4 --quiet --out " +
                         dir.file("ref4.exr")).exitCode, 0);
    const std::pair<std::string, std::string> warned[] = {
        {"frame.exr", ": no record of what it is a reference of"},
        {"ref4.exr", ": the reference averages 4 samples per pixel (--spp 4)"}};
    for (const auto& [file, warning] : warned) {
        const ProcessResult r = runProcess(kDermis + " compare " + furnace + compare + dir.file(file) +
                                           " --set ssao.enabled=false --out " + dir.file(file + ".compared"));
        EXPECT_EQ(r.exitCode, 0) << file << ": " << r.err;
        EXPECT_NE(r.err.find(dir.file(file) + warning), std::string::npos) << r.err;
    }
    EXPECT_EQ(same.err.find("no record"), std::string::npos) << same.err;
}

// How the engine approximates an environment (occlusion, diffuse, specular, SH bands, the
// extracted light) is its own, as SSAO is: a reference serves every choice of them. The map,
// its intensity and rotation are the scene's.
TEST(ReferenceCli, TheEnginesEnvironmentChoicesMayDifferFromTheReferences) {
    TempDir dir;
    const std::string furnace = furnaceScene();
    const std::string sky = " --set 'environment={\"source\":\"sky\",\"intensity\":0.5}'";
    ASSERT_EQ(runProcess(kDermis + " reference " + furnace + " --size 8x6 --density 2 --spp 1 --quiet --out " +
                         dir.file("ref.exr") + sky).exitCode, 0);
    const std::string compare = kDermis + " compare " + furnace + " --size 8x6 --frames 1 --quiet --reference " +
                                dir.file("ref.exr") + " --set ssao.enabled=false";
    const ProcessResult engine = runProcess(compare + " --out " + dir.file("engine") +
                                            " --set 'environment={\"source\":\"sky\",\"intensity\":0.5,\"occlusion\":\"none\","
                                            "\"diffuse\":\"sh\",\"sh_bands\":2,\"extract_light\":\"off\"}'");
    EXPECT_EQ(engine.exitCode, 0) << engine.err;
    const ProcessResult brighter = runProcess(compare + " --out " + dir.file("brighter") +
                                              " --set 'environment={\"source\":\"sky\",\"intensity\":0.6}'");
    EXPECT_EQ(brighter.exitCode, 1) << brighter.err;
    EXPECT_NE(brighter.err.find("in its environment"), std::string::npos) << brighter.err;
}
