// Headless renders of the procedural default scene through the whole graph.
#include "RenderFixture.h"
#include "TestSupport.h"

#include "gl/ShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

using namespace dermis;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 90;

class HeadlessRender : public test::RenderFixture {
protected:
    Image render(Aov aov, int frames = 1) { return RenderFixture::render(aov, kWidth, kHeight, frames); }
};

struct Stats {
    double mean = 0.0;
    double variance = 0.0;
    size_t nonFinite = 0;
};

Stats channelStats(const Image& image) {
    Stats s;
    double sum = 0.0;
    double sumSquares = 0.0;
    size_t n = 0;
    for (const glm::vec4& t : image.texels) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(t[c])) {
                ++s.nonFinite;
                continue;
            }
            sum += t[c];
            sumSquares += double(t[c]) * t[c];
            ++n;
        }
    }
    if (n > 0) {
        s.mean = sum / double(n);
        s.variance = sumSquares / double(n) - s.mean * s.mean;
    }
    return s;
}


}  // namespace

TEST_F(HeadlessRender, FinalImageIsFiniteNotUniformAndShowsTheLitHead) {
    load("default.json");
    const Image image = render(Aov::Final);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    const Stats stats = channelStats(image);
    EXPECT_EQ(stats.nonFinite, 0u);
    EXPECT_GT(stats.variance, 1e-3) << "the image is (nearly) uniform";
    // The centre of the frame is the head: brighter than the dark background.
    const glm::vec4 centre = image.at(kWidth / 2, kHeight / 2);
    const glm::vec4 corner = image.at(2, 2);
    EXPECT_GT(centre.r + centre.g + centre.b, corner.r + corner.g + corner.b + 0.3f);
}

TEST_F(HeadlessRender, LinearAovsAreFinite) {
    load("default.json");
    for (Aov aov : {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Diffuse, Aov::Specular, Aov::Irradiance}) {
        const Image image = render(aov);
        const Stats stats = channelStats(image);
        EXPECT_EQ(stats.nonFinite, 0u) << kAovs.name(aov);
        EXPECT_GT(stats.variance, 0.0) << kAovs.name(aov) << " is uniform";
    }
}

TEST_F(HeadlessRender, NormalAovIsUnitLengthOnTheHead) {
    load("default.json");
    const Image image = render(Aov::Normal);
    size_t covered = 0;
    for (const glm::vec4& t : image.texels) {
        if (t.a < 0.5f) continue;  // background
        ++covered;
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 2e-3f);
    }
    EXPECT_GT(covered, size_t(kWidth * kHeight / 10));
}

TEST_F(HeadlessRender, AlbedoAovCullsLightingAndShadows) {
    load("default.json");
    render(Aov::Albedo);
    const PassSummary* lighting = pass("lighting");
    ASSERT_NE(lighting, nullptr);
    EXPECT_FALSE(lighting->executed);
    EXPECT_EQ(lighting->culledBecause, "nothing reads its output");
    for (const PassSummary& s : mSummary) {
        if (s.name.rfind("shadow", 0) == 0) EXPECT_FALSE(s.executed) << s.name;
    }
    const PassSummary* gbuffer = pass("gbuffer");
    ASSERT_NE(gbuffer, nullptr);
    EXPECT_TRUE(gbuffer->executed);
}

TEST_F(HeadlessRender, CachedShadowMapsRenderOnceAndGiveTheSameImage) {
    load("default.json");
    const Image first = render(Aov::Final, 1);
    const Image third = render(Aov::Final, 2);
    pass("gbuffer");  // refreshes mSummary
    for (const PassSummary& s : mSummary) {
        if (s.name.rfind("shadow", 0) == 0) {
            EXPECT_EQ(s.executedFrames, 1u) << s.name;
            EXPECT_EQ(s.frames, 3u) << s.name;
        }
    }
    ASSERT_EQ(first.texels.size(), third.texels.size());
    EXPECT_EQ(std::memcmp(first.texels.data(), third.texels.data(), first.texels.size() * sizeof(glm::vec4)), 0);
}

TEST_F(HeadlessRender, TimedPassesHaveFiniteNonNegativeTimes) {
    load("default.json");
    render(Aov::Final, 3);
    pass("gbuffer");
    ASSERT_FALSE(mSummary.empty());
    for (const PassSummary& s : mSummary) {
        EXPECT_TRUE(std::isfinite(s.gpuMs) && s.gpuMs >= 0.0) << s.name;
        EXPECT_TRUE(std::isfinite(s.cpuMs) && s.cpuMs >= 0.0) << s.name;
        if (s.executed) EXPECT_GT(s.samples, 0u) << s.name;
    }
}

TEST_F(HeadlessRender, ShaderReloadKeepsThePreviousProgramsOnACompileError) {
    // The viewer's hot reload (Renderer::reloadShaders) on a copy of shaders/.
    test::TempDir dir;
    const std::filesystem::path shaders = dir.file("shaders");
    std::filesystem::copy(gl::shaderDirectory(), shaders, std::filesystem::copy_options::recursive);
    const test::ScopedEnvironmentVariable override("DERMIS_SHADER_DIR", shaders.c_str());
    load("default.json");
    const Image before = render(Aov::Albedo);

    const std::filesystem::path aov = shaders / "aov.frag";
    const std::string good = test::readTextFile(aov.string());
    test::writeTextFile(aov.string(), good + "\nthis is not GLSL\n");
    const Status failed = mRenderer->reloadShaders();
    // The driver may report the failed compile through the debug output; it is
    // the failure this test asks for, not an error of the renderer.
    mErrorsBefore = gl::debugErrorCount();
    ASSERT_FALSE(failed.ok());
    EXPECT_NE(failed.error().message().find("aov.frag"), std::string::npos) << failed.error().message();
    const Image kept = render(Aov::Albedo);
    ASSERT_EQ(kept.texels.size(), before.texels.size());
    EXPECT_TRUE(std::equal(kept.texels.begin(), kept.texels.end(), before.texels.begin())) << "the old programs render";

    test::writeTextFile(aov.string(), good);
    const Status fixed = mRenderer->reloadShaders();
    EXPECT_TRUE(fixed.ok()) << fixed.error().message();
}
