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
    info.candidates = sampleCountCandidates(info.technique, &SssChoice::separableSamples, {7, 11, 17, 25});
    return info;
}

}  // namespace dermis
