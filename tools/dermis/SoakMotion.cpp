#include "SoakMotion.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace dermis::cli {
namespace {

float turn(int frame, int periodFrames) {
    return glm::two_pi<float>() * static_cast<float>(frame % periodFrames) / static_cast<float>(periodFrames);
}

}  // namespace

void applySoakMotion(const Scene& base, int frame, int periodFrames, Scene& scene) {
    const glm::vec3 axis(0.0f, 1.0f, 0.0f);
    const glm::vec3 centreM = base.camera.targetM;
    const float angle = turn(frame, periodFrames);
    scene.camera.positionM = centreM + glm::rotate(base.camera.positionM - centreM, angle, axis);
    if (base.lights.empty()) return;
    const Light& light = base.lights.front();
    scene.lights.front().positionM = centreM + glm::rotate(light.positionM - centreM, -angle, axis);
    scene.lights.front().direction = glm::rotate(light.direction, -angle, axis);
}

bool soakCopyPresent(int frame, int periodFrames) { return frame % periodFrames >= periodFrames / 2; }

Character soakCopy(const Character& original, float offsetM) {
    Character copy = original;
    copy.name = original.name + " copy";
    copy.transform.translationM.x += offsetM;
    return copy;
}

}  // namespace dermis::cli
