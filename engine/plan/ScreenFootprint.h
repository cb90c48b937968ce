#pragma once
// Where a world-space box lands on screen: whether it may cover a pixel, its
// nearest view depth and a pixel rectangle around it. Conservative: the box is
// culled only when all eight corners are outside one frustum plane, and a box
// reaching behind the camera covers the whole frame. Shared by the
// screen-space (SssPlan) and texture-space (TsPlan) planners.

#include "plan/SssPlan.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace dermis {

struct ScreenFootprint {
    bool visible = false;
    // When not visible: which side of the view all eight corners are on.
    const char* outside = "";
    float nearestViewDepthM = 0.0f;  // clamped to the near plane
    glm::ivec4 scissor{0};           // x, y, width, height in pixels (GL convention: y up)
    // The area of the box's projected rectangle before clipping to the
    // frame, pixels: what the whole character would cover (infinite when the
    // box reaches behind the camera).
    float unclippedPixels = 0.0f;
};

ScreenFootprint screenFootprint(const Bounds& bounds, const ViewParams& view);

// The view Renderer::planFrame sets up for a camera and frame size.
ViewParams makeViewParams(const Camera& camera, int widthPx, int heightPx);

}  // namespace dermis
