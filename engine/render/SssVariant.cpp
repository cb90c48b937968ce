#include "render/SssVariant.h"

namespace dermis {

bool frameUsesLean(const RenderSettings& settings) { return settings.mode == "ss" && settings.sss.variant != "c"; }

std::string sssBlurEdges(const SssSettings& settings) {
    if (settings.blur != "variant") return settings.blur;
    return settings.variant == "lbb" ? "bilateral" : "control";
}

float sssMomentWeight(const glm::vec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0f; }

}  // namespace dermis
