// `dermis render --time` and `--sequence` on the animated test cylinder
// (tests/support/TestContent.h): a sequence writes one numbered image per
// time with a progress line each, the times differ, and bad values are
// refused with one line and exit status 2 before anything is written.
#include "TestContent.h"
#include "TestSupport.h"

#include "core/Image.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

std::string writeCylinderScene(const TempDir& dir) {
    EXPECT_TRUE(dermis::test::writeBendingCylinder(dir.file("cylinder.gltf")));
    std::ofstream(dir.file("cylinder.json")) << R"({
  "camera": {"position_m": [0.0, 0.11, 0.42], "target_m": [0.03, 0.11, 0.0]},
  "lights": [{"type": "directional", "direction": [0.85, -0.35, -0.4]}],
  "characters": [{"name": "cylinder", "mesh": {"gltf": "cylinder.gltf"}, "animation": {"clip": "bend"}}]
})";
    return dir.file("cylinder.json");
}

size_t differingTexels(const dermis::Image& a, const dermis::Image& b) {
    size_t count = 0;
    for (size_t i = 0; i < a.texels.size() && i < b.texels.size(); ++i)
        if (glm::any(glm::greaterThan(glm::abs(a.texels[i] - b.texels[i]), glm::vec4(1.0f / 255.0f)))) ++count;
    return count;
}

TEST(AnimationCli, SequenceWritesOneNumberedImagePerTimeWithProgress) {
    TempDir dir;
    const std::string scene = writeCylinderScene(dir);
    const ProcessResult r =
        runProcess(kDermis + " render " + scene + " --size 96x72 --sequence 0:1:2 --out " + dir.file("bend.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // 0, 0.5 and 1 s: three frames, numbered from 0.
    for (const char* name : {"bend_0000.png", "bend_0001.png", "bend_0002.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir.file(name))) << name;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("bend_0003.png")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("bend.png")));
    EXPECT_NE(r.err.find("frame 3/3 at 1 s: " + dir.file("bend_0002.png")), std::string::npos) << r.err;
    // The pose changes the image: at 1 s the tip is bent by 90 degrees.
    auto first = dermis::loadImage(dir.file("bend_0000.png"), dermis::ColourSpace::Srgb);
    auto last = dermis::loadImage(dir.file("bend_0002.png"), dermis::ColourSpace::Srgb);
    ASSERT_TRUE(first.ok() && last.ok());
    EXPECT_GT(differingTexels(*first, *last), 200u);

    // --time gives the same frame as the sequence's frame at that time.
    const ProcessResult single =
        runProcess(kDermis + " render " + scene + " --size 96x72 --frames 1 --time 1 --out " + dir.file("one.png"));
    ASSERT_EQ(single.exitCode, 0) << single.err;
    auto one = dermis::loadImage(dir.file("one.png"), dermis::ColourSpace::Srgb);
    ASSERT_TRUE(one.ok());
    EXPECT_EQ(differingTexels(*one, *last), 0u);
}

TEST(AnimationCli, BadTimesAreRefusedBeforeAnythingIsWritten) {
    TempDir dir;
    const std::string scene = writeCylinderScene(dir);
    struct Case {
        std::string arguments;
        std::string message;
    };
    const Case cases[] = {
        {"--time nan", "--time: expected a number in [-1e+06, 1e+06], got 'nan'"},
        {"--time 2e6", "--time: expected a number in"},
        {"--sequence 1:0:10", "--sequence: END 0 is before START"},
        {"--sequence 0:1", "--sequence: expected START:END:FPS"},
        {"--sequence 0:1:0", "--sequence FPS: expected a number in (0, 10000]"},
        {"--sequence 0:1000:1000", "--sequence: gives 1000001 frames; at most 100000"},
        {"--sequence 0:1:10 --time 1", "--sequence: renders each time once"},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " render " + scene + " " + c.arguments + " --out " + dir.file("x.png"));
        EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.err;
        EXPECT_NE(r.err.find("error: " + c.message), std::string::npos) << c.arguments << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
        EXPECT_FALSE(std::filesystem::exists(dir.file("x_0000.png")));
    }
}

}  // namespace
