// The profile sampled on a disk in one pass (Christensen & Burley 2015 §5,
// Golubev 2018; passes/SssDiskPass.cpp, shaders/include/DiskSss.glsl).
#include "scene/Scene.h"
#include "scene/SssTechniques.h"

namespace dermis {

SssTechniqueInfo diskTechnique() {
    SssTechniqueInfo info;
    info.technique = SssTechnique::Disk;
    info.settings = {{"disk_samples", "samples", &SssSettings::diskSamples, &SssChoice::diskSamples, diskSamplesRule}};
    info.candidates = sampleCountCandidates(info.technique, &SssChoice::diskSamples, {8, 16, 32, 64});
    return info;
}

}  // namespace dermis
