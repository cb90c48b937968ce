#include "plan/BackFaceCulling.h"

namespace dermis {

bool mayCullBackFaces(bool closedOutward, const CharacterPlacement& placement, const ViewParams& view) {
    if (!closedOutward || placement.animated) return false;
    if (glm::determinant(glm::mat3(placement.worldFromObject)) <= 0.0f) return false;
    const Bounds& b = placement.worldBounds;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 world((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                              (corner & 4) ? b.max.z : b.min.z);
        const float viewZ = (view.viewFromWorld * glm::vec4(world, 1.0f)).z;
        if (!(viewZ < -view.nearM)) return false;  // also false for NaN
    }
    return true;
}

}  // namespace dermis
