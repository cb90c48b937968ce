#pragma once
// The viewer's camera: the eye circles a target point at some distance, with
// yaw about the scene camera's up vector and a pitch kept short of the poles
// (so the view never flips). Mouse movements in pixels drive it; the result is
// written into a scene Camera, whose lens (field of view, near, far) it keeps.

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace dermis::viewer {

class OrbitCamera {
public:
    explicit OrbitCamera(const Camera& camera);

    // Dragging right turns the scene to the right, dragging down tilts its top towards the viewer.
    void orbit(float dxPx, float dyPx);
    // Moves the target in the view plane so that the point under the cursor follows it.
    void pan(float dxPx, float dyPx, float viewportHeightPx, float verticalFovDeg);
    // Positive steps (wheel forward) move towards the target.
    void dolly(float steps);

    void applyTo(Camera& camera) const;  // eye, target and up
    glm::vec3 eye() const;
    glm::vec3 target() const { return mTarget; }
    float distance() const { return mDistance; }

private:
    glm::vec3 mTarget{0.0f};
    glm::vec3 mUp{0.0f, 1.0f, 0.0f};
    glm::vec3 mAxisX{0.0f, 0.0f, 1.0f};  // with mAxisZ, an orthonormal basis of the plane normal to mUp
    glm::vec3 mAxisZ{-1.0f, 0.0f, 0.0f};
    float mDistance = 1.0f;
    float mYaw = 0.0f;
    float mPitch = 0.0f;
    float mMinDistance = 0.01f;
    float mMaxDistance = 100.0f;
};

}  // namespace dermis::viewer
