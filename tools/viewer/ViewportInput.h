#pragma once
// The mouse over the scene area (not over a panel): left drag orbits, right
// drag or shift + left drag pans, the wheel dollies, and in the split view a
// drag that starts on the divider moves it. A drag keeps its meaning until
// its button is released, wherever the cursor goes.

#include "viewer/OrbitCamera.h"
#include "viewer/ViewerState.h"

namespace dermis::viewer {

// In ImGui's units: origin top left.
struct UiRect {
    float x = 0.0f;
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;

    bool contains(float px, float py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

class ViewportInput {
public:
    // Returns true when the camera moved.
    bool update(const UiRect& area, float verticalFovDeg, OrbitCamera& camera, ViewerState& state);

private:
    enum class Drag { None, Orbit, Pan, Divider };
    Drag mDrag = Drag::None;
    int mButton = 0;
    float mLastX = 0.0f;  // the cursor at the previous frame of a drag
    float mLastY = 0.0f;
};

}  // namespace dermis::viewer
