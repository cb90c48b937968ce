// Jimenez et al. 2015's Separable SSS: one pre-integrated separable pair
// (passes/SssSeparablePasses.cpp, shaders/include/SeparableSss.glsl).
#include "scene/Scene.h"
#include "scene/SssTechniques.h"

namespace dermis {

SssTechniqueInfo separableTechnique() {
    SssTechniqueInfo info;
    info.technique = SssTechnique::Separable;
    info.settings = {{"separable_samples", "samples", &SssSettings::separableSamples, &SssChoice::separableSamples,
                      separableSamplesRule}};
    for (int samples : {7, 11, 17, 25}) {
        SssChoice choice;
        choice.technique = info.technique;
        choice.separableSamples = samples;
        info.candidates.push_back(choice);
    }
    return info;
}

}  // namespace dermis
