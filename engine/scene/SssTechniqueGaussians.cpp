// d'Eon & Luebke 2007's sum of Gaussians, one separable blur pair each
// (passes/SssPasses.cpp, shaders/include/SssBlur.glsl).
#include "scene/Scene.h"
#include "scene/SssTechniques.h"

namespace dermis {

SssTechniqueInfo gaussiansTechnique() {
    SssTechniqueInfo info;
    info.technique = SssTechnique::Gaussians;
    info.settings = {{"taps", "taps", &SssSettings::taps, &SssChoice::taps, blurTapsRule},
                     {"gaussians", "gaussians", &SssSettings::gaussians, &SssChoice::gaussians, profileGaussiansRule}};
    for (int gaussians = 2; gaussians <= 6; ++gaussians) {
        for (int taps : {5, 9, 17}) {
            SssChoice choice;
            choice.technique = info.technique;
            choice.gaussians = gaussians;
            choice.taps = taps;
            info.candidates.push_back(choice);
        }
    }
    return info;
}

}  // namespace dermis
