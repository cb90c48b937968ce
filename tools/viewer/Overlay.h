#pragma once
// What the viewer draws over the scene area (behind the panels): the A/B
// labels and the divider, the difference view's colour scale, the latest
// render error, and for a few seconds the latest message (saved, refused ...).

#include "viewer/SceneJson.h"
#include "viewer/ViewerState.h"
#include "viewer/ViewportInput.h"

#include <vector>

namespace dermis::viewer {

void drawOverlay(const UiRect& area, const ViewerState& state, const std::vector<SceneDifference>& differences);

}  // namespace dermis::viewer
