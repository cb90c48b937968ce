#include "viewer/ViewportInput.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace dermis::viewer {
namespace {
constexpr float kDividerGrabWidth = 6.0f;
}

bool ViewportInput::update(const UiRect& area, float verticalFovDeg, OrbitCamera& camera, ViewerState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 mouse = io.MousePos;
    const float dividerX = area.x + state.dividerFraction * area.width;
    const bool overScene = !io.WantCaptureMouse && area.contains(mouse.x, mouse.y);
    const bool overDivider = overScene && state.mode == ViewMode::Split && std::abs(mouse.x - dividerX) <= kDividerGrabWidth;

    if (mDrag == Drag::None && overScene) {
        if (io.MouseClicked[0]) {
            mButton = 0;
            mDrag = overDivider ? Drag::Divider : io.KeyShift ? Drag::Pan : Drag::Orbit;
        } else if (io.MouseClicked[1] || io.MouseClicked[2]) {
            mButton = io.MouseClicked[1] ? 1 : 2;
            mDrag = Drag::Pan;
        }
        // Deltas count from where the button went down: at a few frames per
        // second, ImGui's MouseDelta of the click frame also holds the move
        // that brought the cursor there.
        mLastX = mouse.x;
        mLastY = mouse.y;
    }
    if (overDivider || mDrag == Drag::Divider) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);

    bool moved = false;
    if (mDrag != Drag::None && !io.MouseDown[mButton]) mDrag = Drag::None;
    if (!ImGui::IsMousePosValid(&mouse)) return false;  // the cursor left the window: no position this frame
    const ImVec2 delta(mouse.x - mLastX, mouse.y - mLastY);
    mLastX = mouse.x;
    mLastY = mouse.y;
    const bool hasDelta = delta.x != 0.0f || delta.y != 0.0f;
    if (hasDelta) {
        switch (mDrag) {
            case Drag::Orbit:
                camera.orbit(delta.x, delta.y);
                moved = true;
                break;
            case Drag::Pan:
                camera.pan(delta.x, delta.y, area.height, verticalFovDeg);
                moved = true;
                break;
            case Drag::Divider:
                if (area.width > 0.0f) state.dividerFraction = std::clamp((mouse.x - area.x) / area.width, 0.0f, 1.0f);
                break;
            case Drag::None: break;
        }
    }
    if (overScene && io.MouseWheel != 0.0f) {
        camera.dolly(io.MouseWheel);
        moved = true;
    }
    return moved;
}

}  // namespace dermis::viewer
