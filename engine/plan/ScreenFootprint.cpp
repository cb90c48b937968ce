#include "plan/ScreenFootprint.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

// Clip planes in the order screenFootprint counts them: -x, +x, -y, +y, -z (near), +z (far).
constexpr const char* kOutsidePlane[6] = {"left of the view",  "right of the view",          "below the view",
                                          "above the view",    "behind the camera or nearer than the near plane", "beyond the far plane"};
// The order a reason is looked for in: behind the camera first, since a box
// there can be outside a side plane too.
constexpr int kReasonOrder[6] = {4, 5, 0, 1, 2, 3};

}  // namespace

ScreenFootprint screenFootprint(const Bounds& bounds, const ViewParams& view) {
    ScreenFootprint out;
    const glm::mat4 clipFromWorld = view.clipFromView * view.viewFromWorld;
    int outside[6] = {0, 0, 0, 0, 0, 0};
    bool behindNear = false;
    float nearest = INFINITY;
    glm::vec2 ndcMin(INFINITY);
    glm::vec2 ndcMax(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec4 clip = clipFromWorld * glm::vec4(p, 1.0f);
        for (int axis = 0; axis < 3; ++axis) {
            if (clip[axis] < -clip.w) ++outside[2 * axis];
            if (clip[axis] > clip.w) ++outside[2 * axis + 1];
        }
        const float viewDepthM = -(view.viewFromWorld * glm::vec4(p, 1.0f)).z;
        nearest = std::min(nearest, viewDepthM);
        if (clip.w <= view.nearM * 0.5f) {
            behindNear = true;
        } else {
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            ndcMin = glm::min(ndcMin, ndc);
            ndcMax = glm::max(ndcMax, ndc);
        }
    }
    for (int plane : kReasonOrder) {
        if (outside[plane] == 8) {
            out.outside = kOutsidePlane[plane];
            return out;
        }
    }
    out.visible = true;
    out.nearestViewDepthM = std::max(nearest, view.nearM);
    if (behindNear) {
        out.scissor = glm::ivec4(0, 0, view.widthPx, view.heightPx);
        out.unclippedPixels = INFINITY;
        return out;
    }
    const glm::vec2 extentPx = (ndcMax - ndcMin) * 0.5f * glm::vec2(float(view.widthPx), float(view.heightPx));
    out.unclippedPixels = extentPx.x * extentPx.y;
    ndcMin = glm::clamp(ndcMin, glm::vec2(-1.0f), glm::vec2(1.0f));
    ndcMax = glm::clamp(ndcMax, glm::vec2(-1.0f), glm::vec2(1.0f));
    const int x0 = static_cast<int>(std::floor((ndcMin.x * 0.5f + 0.5f) * float(view.widthPx)));
    const int y0 = static_cast<int>(std::floor((ndcMin.y * 0.5f + 0.5f) * float(view.heightPx)));
    const int x1 = static_cast<int>(std::ceil((ndcMax.x * 0.5f + 0.5f) * float(view.widthPx)));
    const int y1 = static_cast<int>(std::ceil((ndcMax.y * 0.5f + 0.5f) * float(view.heightPx)));
    out.scissor = glm::ivec4(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
    return out;
}

ViewParams makeViewParams(const Camera& camera, int widthPx, int heightPx) {
    ViewParams view;
    view.viewFromWorld = glm::lookAt(camera.positionM, camera.targetM, camera.up);
    view.clipFromView = glm::perspective(glm::radians(camera.verticalFovDeg), float(widthPx) / float(heightPx),
                                         camera.nearM, camera.farM);
    view.nearM = camera.nearM;
    view.widthPx = widthPx;
    view.heightPx = heightPx;
    return view;
}

}  // namespace dermis
