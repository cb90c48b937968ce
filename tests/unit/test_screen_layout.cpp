// The viewer's layout (tools/viewer/ScreenLayout.h): no panel lies over the
// scene area, so none hides a character; the settings column, the scene and
// a docked profiler tile the window.
#include "viewer/ScreenLayout.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace dermis::viewer;

namespace {

float overlap(const UiRect& a, const UiRect& b) {
    const float w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
    const float h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
    return std::max(w, 0.0f) * std::max(h, 0.0f);
}

float area(const UiRect& r) { return r.width * r.height; }

}  // namespace

TEST(ScreenLayout, AtTheDefaultSizeTheProfilerIsDockedBelowTheSceneAndCoversNoneOfIt) {
    const ScreenLayout layout = layoutScreen(1280.0f, 800.0f, true, true);  // dermis view's default --size
    ASSERT_TRUE(layout.profilerDocked);
    EXPECT_EQ(overlap(layout.profiler, layout.scene), 0.0f);
    EXPECT_EQ(overlap(layout.settings, layout.scene), 0.0f);
    EXPECT_EQ(overlap(layout.settings, layout.profiler), 0.0f);
    EXPECT_FLOAT_EQ(area(layout.settings) + area(layout.scene) + area(layout.profiler), 1280.0f * 800.0f);
    // The scene keeps the full width right of the settings, so with a fixed
    // vertical field of view nothing that the full height showed is cropped.
    EXPECT_FLOAT_EQ(layout.scene.x, kPanelWidth);
    EXPECT_FLOAT_EQ(layout.scene.width, 1280.0f - kPanelWidth);
    EXPECT_GE(layout.scene.height, kMinSceneHeight);
    EXPECT_FLOAT_EQ(layout.profiler.y, layout.scene.y + layout.scene.height);
}

TEST(ScreenLayout, WithoutPanelsOrProfilerTheSceneTakesWhatTheyLeave) {
    const ScreenLayout bare = layoutScreen(1280.0f, 800.0f, false, true);
    EXPECT_FLOAT_EQ(area(bare.scene), 1280.0f * 800.0f);
    EXPECT_EQ(area(bare.profiler), 0.0f);
    const ScreenLayout noProfiler = layoutScreen(1280.0f, 800.0f, true, false);
    EXPECT_FLOAT_EQ(noProfiler.scene.height, 800.0f);
    EXPECT_FALSE(noProfiler.profilerDocked);
}

TEST(ScreenLayout, AWindowTooShortForADockFloatsTheProfilerInTheTopRightCorner) {
    const ScreenLayout layout = layoutScreen(900.0f, 400.0f, true, true);
    EXPECT_FALSE(layout.profilerDocked);
    EXPECT_FLOAT_EQ(layout.scene.height, 400.0f);
    EXPECT_FLOAT_EQ(layout.profiler.x + layout.profiler.width, 900.0f - kProfilerMargin);
    EXPECT_FLOAT_EQ(layout.profiler.y, kProfilerMargin);
    EXPECT_LE(layout.profiler.width, std::max(layout.scene.width * 0.5f, kProfilerMinWidth));
}
