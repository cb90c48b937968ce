#include "render/SssVariant.h"

namespace dermis {

bool sssUsesLean(const SssSettings& settings) { return settings.variant != "c"; }

std::string sssBlurEdges(const SssSettings& settings) {
    if (settings.blur != "variant") return settings.blur;
    return settings.variant == "lbb" ? "bilateral" : "control";
}

float sssMomentWeight(const glm::vec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0f; }

}  // namespace dermis
