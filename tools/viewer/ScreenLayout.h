#pragma once
// Where the viewer's windows go: the settings column on the left, the
// profiler docked along the bottom of the rest, the scene above it. Nothing
// floats over the scene, so no panel hides a character; and the camera keeps
// its vertical field of view, so a shorter, wider scene area shows the whole
// of what the full height showed, only smaller (a column on the right would
// have cropped the head's sides instead). A window too small to give the
// scene kMinSceneHeight units under a docked profiler floats the profiler in
// the scene area's top-right corner, as before. No ImGui here (unit-tested).

#include "viewer/ViewportInput.h"

namespace dermis::viewer {

constexpr float kPanelWidth = 380.0f;           // the settings column, in ImGui units
constexpr float kProfilerMargin = 8.0f;         // a floating profiler's distance from the edges
constexpr float kProfilerFloatingWidth = 420.0f;
constexpr float kProfilerMinWidth = 320.0f;
constexpr float kProfilerFloatingHeight = 430.0f;
constexpr float kProfilerDockShare = 0.38f;     // of the display's height
constexpr float kProfilerDockMinHeight = 200.0f;
constexpr float kMinSceneHeight = 240.0f;

struct ScreenLayout {
    UiRect settings;  // zero width when hidden
    UiRect scene;     // where the frame is drawn, at this size
    UiRect profiler;  // zero width when hidden
    bool profilerDocked = false;
};

ScreenLayout layoutScreen(float displayWidth, float displayHeight, bool showPanels, bool showProfiler);

}  // namespace dermis::viewer
