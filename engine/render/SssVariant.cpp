#include "render/SssVariant.h"

namespace dermis {

bool frameUsesLean(const RenderSettings& settings) { return settings.mode == SssMode::ScreenSpace && settings.sss.variant != SssVariant::C; }

SssBlur sssBlurEdges(const SssSettings& settings) {
    if (settings.blur != SssBlur::Variant) return settings.blur;
    return settings.variant == SssVariant::Lbb ? SssBlur::Bilateral : SssBlur::Control;
}

float sssMomentWeight(const glm::vec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0f; }

}  // namespace dermis
