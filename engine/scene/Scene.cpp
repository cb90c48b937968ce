#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace dermis {

glm::mat4 Transform::worldFromObject(float metresPerUnit) const {
    const glm::mat4 identity(1.0f);
    const glm::mat4 t = glm::translate(identity, translationM);
    const glm::mat4 rx = glm::rotate(identity, glm::radians(rotationDeg.x), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::mat4 ry = glm::rotate(identity, glm::radians(rotationDeg.y), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 rz = glm::rotate(identity, glm::radians(rotationDeg.z), glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::mat4 s = glm::scale(identity, glm::vec3(scale * metresPerUnit));
    return t * rz * ry * rx * s;
}

}  // namespace dermis
