// `dermis view` as a user (or CI) runs it: under a virtual X display, the
// batch flags render the window with its panels and save a screenshot; bad
// input fails cleanly without needing a display.
#include "TestSupport.h"

#include "core/Image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

std::string defaultScene() { return dermis::test::contentScene("default.json"); }

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream folders(path);
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        std::error_code error;
        if (!folder.empty() && std::filesystem::exists(std::filesystem::path(folder) / program, error)) return true;
    }
    return false;
}

struct RegionStats {
    glm::vec3 mean{0.0f};
    float lumaMin = 1.0f;
    float lumaMax = 0.0f;
};

RegionStats stats(const dermis::Image& image, int x0, int y0, int x1, int y1) {
    RegionStats s;
    double count = 0.0;
    glm::dvec3 sum(0.0);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const glm::vec3 c(image.at(x, y));
            const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
            s.lumaMin = std::min(s.lumaMin, luma);
            s.lumaMax = std::max(s.lumaMax, luma);
            sum += glm::dvec3(c);
            count += 1.0;
        }
    }
    s.mean = glm::vec3(sum / std::max(count, 1.0));
    return s;
}

}  // namespace

// The batch flags render the window, panels included, and save it: the
// screenshot has the window's size, is not uniform, and its panel column
// looks different from the scene beside it.
// ctest: slow window cost=40
TEST(View, BatchScreenshotUnderXvfb) {
    if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt-get install xvfb): dermis view needs a display";
    TempDir dir;
    const std::string png = dir.file("out.png");
    const ProcessResult r = runProcess("xvfb-run -a -s \"-screen 0 1280x800x24\" " + kDermis + " view " + defaultScene() +
                                       " --frames 30 --screenshot " + png + " --size 960x540");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(std::filesystem::exists(png)) << r.err;
    auto image = dermis::loadImage(png, dermis::ColourSpace::Linear);
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, 960);
    ASSERT_EQ(image->height, 540);

    const RegionStats whole = stats(*image, 0, 0, 960, 540);
    EXPECT_GT(whole.lumaMax - whole.lumaMin, 0.3f) << "the screenshot is (nearly) uniform";
    // The settings column is the left 380 pixels; the scene area to its right
    // holds the head, above the profiler docked along the bottom 205 pixels
    // (tools/viewer/ScreenLayout.h: 38% of 540).
    const RegionStats panel = stats(*image, 0, 0, 360, 540);
    const RegionStats scene = stats(*image, 400, 0, 960, 320);
    EXPECT_GT(panel.lumaMax - panel.lumaMin, 0.3f) << "the panel column shows no text or widgets";
    EXPECT_GT(scene.lumaMax, 0.3f) << "the scene area shows no lit head";
    EXPECT_GT(glm::length(panel.mean - scene.mean), 0.05f) << "the panel and scene areas look the same";
}

// A scene with the built-in sky as its environment, panels hidden: where the
// head does not cover the frame the map shows, pale blue sky above the horizon
// and ground below it, not the scene's flat, near-black background colour.
// ctest: slow window
TEST(View, EnvironmentShowsBehindTheHeadUnderXvfb) {
    if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt-get install xvfb): dermis view needs a display";
    TempDir dir;
    const std::string png = dir.file("sky.png");
    const ProcessResult r = runProcess("xvfb-run -a -s \"-screen 0 1280x800x24\" " + kDermis + " view " + defaultScene() +
                                       " --set 'environment={\"source\":\"sky\"}' --no-panels --frames 3 --screenshot " +
                                       png + " --size 640x360");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto image = dermis::loadImage(png, dermis::ColourSpace::Linear);
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, 640);
    ASSERT_EQ(image->height, 360);

    // The head is in the middle; the left edge shows the map: sky at the top, ground at the bottom.
    const RegionStats sky = stats(*image, 0, 0, 120, 60);
    const RegionStats ground = stats(*image, 0, 300, 120, 360);
    EXPECT_GT(sky.lumaMin, 0.3f) << "the top left is not sky (the background colour is near black)";
    EXPECT_GT(sky.mean.b, sky.mean.r) << "the sky is not blue";
    EXPECT_GT(glm::length(sky.mean - ground.mean), 0.1f) << "sky and ground look the same: a flat background";
}

TEST(View, MissingSceneFails) {
    TempDir dir;
    const ProcessResult r = runProcess(kDermis + " view " + dir.file("no-such-scene.json") + " --frames 1 --screenshot " +
                                       dir.file("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no-such-scene.json"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST(View, BadOptionsAreUsageErrors) {
    TempDir dir;
    for (const std::string& options : {std::string("--size 0x0"), std::string("--view sideways"),
                                       std::string("--aov colour"), std::string("--frames -3"),
                                       std::string("--screenshot ") + dir.file("x.bmp"), std::string("--zoom 2")}) {
        const ProcessResult r = runProcess(kDermis + " view " + defaultScene() + " " + options);
        EXPECT_EQ(r.exitCode, 2) << options << "\n" << r.err;
        EXPECT_NE(r.err.find("error: "), std::string::npos) << options << "\n" << r.err;
    }
    // A value the scene refuses, given on the command line, is a usage error (2) for
    // --set-b as for --set.
    const ProcessResult bad = runProcess(kDermis + " view " + defaultScene() + " --set-b sss.taps=4 --frames 1");
    EXPECT_EQ(bad.exitCode, 2) << bad.err;
    EXPECT_NE(bad.err.find("--set-b sss.taps=4"), std::string::npos) << bad.err;
}

TEST(View, HelpListsTheOptions) {
    const ProcessResult r = runProcess(kDermis + " view --help");
    ASSERT_EQ(r.exitCode, 0);
    for (const char* flag : {"--size", "--frames", "--screenshot", "--set", "--set-b", "--view", "--aov", "--quiet"}) {
        EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
    }
    const ProcessResult top = runProcess(kDermis + " --help");
    EXPECT_NE(top.out.find("view"), std::string::npos);
}
