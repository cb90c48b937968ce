// Hostile input gets one clear line (docs/cli.md, "Errors"): the cap of a
// count, why a file cannot be opened, a path with a newline still one line,
// an empty .glb, a normal map with a NaN texel.
#include "TestSupport.h"

#include "core/ImageResample.h"

#include <gtest/gtest.h>

#include <filesystem>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;
namespace fs = std::filesystem;

namespace {

const std::string kDermis = DERMIS_BINARY;

void expectOneError(const ProcessResult& r, const std::string& fragment) {
    EXPECT_NE(r.exitCode, 0);
    const std::vector<std::string> lines = dermis::test::errorLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_NE(lines[0].find(fragment), std::string::npos) << lines[0];
}

}  // namespace

TEST(HostileMessages, CountsAboveTheCapSayTheCap) {
    const std::string scene = dermis::test::contentScene("default.json");
    expectOneError(runProcess(kDermis + " render " + scene + " --frames 100000000"),
                   "--frames: at most 1000000, got '100000000'");
    expectOneError(runProcess(kDermis + " render " + scene + " --frames 99999999999999999999999"), "--frames: at most 1000000");
    expectOneError(runProcess(kDermis + " render " + scene + " --frames -3"), "--frames: expected a positive integer");
}

TEST(HostileMessages, FilesThatCannotBeOpenedSayWhy) {
    TempDir dir;
    fs::create_symlink(dir.file("loop2.json"), dir.file("loop1.json"));
    fs::create_symlink(dir.file("loop1.json"), dir.file("loop2.json"));
    expectOneError(runProcess(kDermis + " render " + dir.file("loop1.json")), "Too many levels of symbolic links");
    // A path with a newline stays one line, the newline written as \n.
    expectOneError(runProcess(kDermis + " render '" + dir.file("a") + "\nb.json'"), "a\\nb.json: cannot open scene file");
    dermis::test::writeTextFile(dir.file("empty.glb"), "");
    dermis::test::writeTextFile(dir.file("scene.json"), R"({"characters": [{"name": "a", "mesh": {"gltf": "empty.glb"}}]})");
    expectOneError(runProcess(kDermis + " render " + dir.file("scene.json") + " --size 32x18 --out " + dir.file("x.png")),
                   "empty.glb: the file is empty (0 bytes)");
}

TEST(HostileMessages, ANormalMapWithANanIsRefused) {
    TempDir dir;
    dermis::Image map = dermis::makeImage(8, 8, dermis::ColourSpace::Linear, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
    map.at(3, 4).x = std::nanf("");
    ASSERT_TRUE(dermis::saveImage(dir.file("normal.exr"), map));
    const ProcessResult r = runProcess(kDermis + " bake-lean " + dir.file("normal.exr") + " --out " + dir.file("baked"));
    expectOneError(r, "normal.exr: 1 texels are not finite");
    EXPECT_FALSE(fs::exists(dir.file("baked_lean1.exr")));
}
