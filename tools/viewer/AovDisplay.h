#pragma once
// Which AOVs there are (read from plan/Aov.h, so a new one shows up in the
// selector by itself) and how each is mapped to the screen by default.

#include "plan/Aov.h"
#include "viewer/SplitView.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis::viewer {

struct AovChoice {
    Aov aov;
    std::string name;
};

const std::vector<AovChoice>& aovChoices();

struct AovMapping {
    DisplayTransform transform = DisplayTransform::AsStored;
    glm::vec2 range{0.0f, 1.0f};
    const char* unit = "";  // of the range, for the panel
};

// A range that shows the AOV well: normals from [-1, 1], view depth around
// the camera's distance to its target, thickness in mm, the stretch map in mm
// per UV unit, colours from [0, 1].
AovMapping defaultAovMapping(Aov aov, float cameraDistanceM);

}  // namespace dermis::viewer
