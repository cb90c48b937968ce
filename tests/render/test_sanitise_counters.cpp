// The sanitise counters and the planted NaN (gl/SanitiseCounters.h,
// shaders/include/Sanitise.glsl; docs/stress.md, "Counting and reading every
// target"): a NaN planted in any pass of the default frame, in either SSS
// mode, is found and attributed to that pass; a clean frame reports none.
#include "RenderFixture.h"

#include "gl/NonFiniteCounter.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace dermis;

namespace {

// Small frames: every pass still covers pixels of the head (its SSS included).
constexpr int kWidth = 64;
constexpr int kHeight = 36;
// A glCopyImageSubData of the irradiance (passes/TextureSpacePasses.cpp): it
// runs no shader, so there is nothing to plant into.
constexpr const char* kCopyPass = "ts init";

class SanitiseCountersTest : public test::RenderFixture {
protected:
    struct Frame {
        std::vector<std::string> passes;
        std::vector<gl::PassSanitised> sanitised;
        std::string faultyPass;
        bool planted = false;
    };

    // One frame with counting on, the read-back of every target, and a NaN
    // planted in `plantPass` (empty: none).
    Frame countedFrame(const std::string& plantPass) {
        gl::SanitiseCounters& counters = mRenderer->sanitiseCounters();
        gl::NonFiniteCounter targets;
        counters.reset();
        counters.setCounting(true);
        counters.setPlantPass(plantPass);
        mRenderer->setPassInspector(targets.inspector());
        render(Aov::Final, kWidth, kHeight);
        mRenderer->setPassInspector(nullptr);
        counters.setCounting(false);
        counters.setPlantPass("");
        Frame frame;
        frame.passes = mRenderer->framePasses();
        frame.sanitised = counters.passes();
        frame.faultyPass = gl::firstFaultyPass(frame.passes, frame.sanitised, targets);
        frame.planted = counters.planted();
        return frame;
    }

    // Plants a NaN in every pass of the mode's frame in turn.
    void plantInEveryPass(const std::string& mode) {
        load("default.json", {"mode=" + mode});
        const Frame clean = countedFrame("");
        ASSERT_GT(clean.passes.size(), 8u);
        EXPECT_EQ(clean.faultyPass, "") << "the default frame makes no NaN or Inf";
        for (const std::string& pass : clean.passes) {
            if (pass == kCopyPass) continue;
            // The planted pass and every pass after it may see the NaN (it
            // flows downstream: lighting reads the G-buffer's NaN albedo, for
            // one), but no pass before it can, because they ran before the
            // flag was set. So the first faulty pass must be exactly the
            // planted one: a NaN attributed to a later pass, or missed, fails.
            // A shadow pass runs only while its map is not cached, and a map
            // planted with NaN stays cached: a fresh renderer before and after.
            const bool shadow = pass.rfind("shadow:", 0) == 0;
            if (shadow) load("default.json", {"mode=" + mode});
            const Frame planted = countedFrame(pass);
            if (shadow) load("default.json", {"mode=" + mode});
            EXPECT_TRUE(planted.planted) << pass;
            EXPECT_EQ(planted.faultyPass, pass) << "planted in '" << pass << "' (mode " << mode << ")";
        }
        std::printf("mode %s: planted a NaN in each of %zu passes:", mode.c_str(), clean.passes.size());
        for (const std::string& pass : clean.passes) std::printf(" [%s]", pass.c_str());
        std::printf("\n");
    }
};

TEST_F(SanitiseCountersTest, PlantedNanIsFoundInEveryScreenSpacePass) { plantInEveryPass("ss"); }

TEST_F(SanitiseCountersTest, PlantedNanIsFoundInEveryTextureSpacePass) { plantInEveryPass("ts"); }

TEST_F(SanitiseCountersTest, TonemapCountsOneNanPerPixel) {
    load("default.json");
    const Frame frame = countedFrame("tonemap");
    // The tonemap is a full-screen pass that sanitises its input once per
    // pixel, and debugPlant replaces one component (x) of it: exactly one
    // NaN per pixel, counted by sanitizeColour's atomicAdd. One more or one
    // less than width x height means a lost or doubled count.
    const auto it = std::find_if(frame.sanitised.begin(), frame.sanitised.end(),
                                 [](const gl::PassSanitised& p) { return p.pass == "tonemap"; });
    ASSERT_NE(it, frame.sanitised.end());
    EXPECT_EQ(it->counts.nan, uint64_t(kWidth) * kHeight);
    EXPECT_EQ(it->counts.inf, 0u);
    EXPECT_EQ(frame.faultyPass, "tonemap");
}

TEST_F(SanitiseCountersTest, LightPastFp16IsClampedAndCountedNotFailed) {
    // The largest legal light (colour x intensity up to 1e20, core/Limits.h):
    // lighting's irradiance is far above 65504 on every lit pixel, so the
    // sanitisers must clamp (overflow > 0), and nothing in the frame may be
    // NaN or Inf (1e20 x a Beckmann peak below 3e11 stays finite in float32,
    // whose maximum is 3.4e38).
    ASSERT_NO_FATAL_FAILURE(load("default.json", {"lights.0.intensity=1e20"}));
    const Frame frame = countedFrame("");
    const auto it = std::find_if(frame.sanitised.begin(), frame.sanitised.end(),
                                 [](const gl::PassSanitised& p) { return p.pass == "lighting"; });
    ASSERT_NE(it, frame.sanitised.end());
    EXPECT_GT(it->counts.overflow, 0u);
    EXPECT_EQ(frame.faultyPass, "");
    for (const gl::PassSanitised& p : frame.sanitised) {
        std::printf("%-16s nan %llu inf %llu overflow %llu negative %llu\n", p.pass.c_str(),
                    static_cast<unsigned long long>(p.counts.nan), static_cast<unsigned long long>(p.counts.inf),
                    static_cast<unsigned long long>(p.counts.overflow),
                    static_cast<unsigned long long>(p.counts.negative));
    }
}

TEST_F(SanitiseCountersTest, UnknownPlantPassPlantsNothing) {
    load("default.json");
    const Frame frame = countedFrame("no such pass");
    EXPECT_FALSE(frame.planted);
    EXPECT_EQ(frame.faultyPass, "");
}

}  // namespace
