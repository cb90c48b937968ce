#include "viewer/ScreenLayout.h"

#include <algorithm>

namespace dermis::viewer {

ScreenLayout layoutScreen(float displayWidth, float displayHeight, bool showPanels, bool showProfiler) {
    ScreenLayout layout;
    const float left = showPanels ? std::min(kPanelWidth, displayWidth) : 0.0f;
    layout.settings = {0.0f, 0.0f, left, showPanels ? displayHeight : 0.0f};
    layout.scene = {left, 0.0f, std::max(displayWidth - left, 0.0f), displayHeight};
    if (!showPanels || !showProfiler) return layout;

    const float dockHeight = std::max(kProfilerDockMinHeight, kProfilerDockShare * displayHeight);
    if (displayHeight - dockHeight >= kMinSceneHeight) {
        layout.profilerDocked = true;
        layout.scene.height = displayHeight - dockHeight;
        layout.profiler = {left, layout.scene.height, layout.scene.width, dockHeight};
        return layout;
    }
    // At most half the scene area's width, so that the scene stays in view in a small window.
    const float width = std::clamp(layout.scene.width * 0.5f, kProfilerMinWidth, kProfilerFloatingWidth);
    const float height = std::min(kProfilerFloatingHeight, displayHeight * 0.6f);
    layout.profiler = {displayWidth - kProfilerMargin - width, kProfilerMargin, width, height};
    return layout;
}

}  // namespace dermis::viewer
