#include "plan/SssVariant.h"

namespace dermis {

bool frameUsesLean(const RenderSettings& settings) { return settings.mode == SssMode::ScreenSpace && settings.sss.variant != SssVariant::C; }

SssBlur sssBlurEdges(const SssSettings& settings) {
    if (settings.blur != SssBlur::Variant) return settings.blur;
    return settings.variant == SssVariant::Lbb ? SssBlur::Bilateral : SssBlur::Control;
}

float sssMomentWeight(const glm::vec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0f; }

SssMomentCut sssMomentCut(const std::vector<SssGaussianStep>& steps, float maxWidthMm) {
    SssMomentCut cut;
    if (steps.empty()) return cut;
    // Skipped steps are the leading, narrow ones (folded into sss init's
    // identity weight); the first that runs reads the irradiance, and its
    // step variance is the Gaussian's whole variance.
    bool found = false;
    float varianceMm2 = 0.0f;
    for (size_t i = 0; i < steps.size(); ++i) {
        if (steps[i].skipped) continue;
        varianceMm2 = (found ? varianceMm2 : 0.0f) + steps[i].stepVarianceMm2;
        if (found && maxWidthMm > 0.0f && varianceMm2 > maxWidthMm * maxWidthMm) break;
        cut.lastStep = i;
        found = true;
    }
    if (!found) cut.lastStep = steps.size() - 1;  // nothing runs: keep the chain packed throughout
    for (size_t i = cut.lastStep; i < steps.size(); ++i) {
        if (!steps[i].skipped) cut.weight += sssMomentWeight(steps[i].weight);
    }
    return cut;
}

}  // namespace dermis
