#pragma once
// The registry of screen-space SSS techniques (docs/screen-space.md,
// "Techniques"): one descriptor per technique, defined in the technique's own
// file (scene/SssTechnique<Name>.cpp) and listed once in SssTechniques.cpp.
// Everything that handles "every technique" loops over sssTechniques(): the
// scene's settings and the quality table's choices (the sample counts), the
// tuner's and the benchmarks' candidates, the sweep's labels. The GL half is
// passes/SssTechniquePasses.cpp (one line per technique: its passes).
//
// Adding a technique: its enum value and name (scene/SceneEnums.h), its
// descriptor file here, its passes and shaders, one line in each registry;
// a new sample count also needs its member in SssChoice and SssSettings.

#include "scene/IntegerRule.h"
#include "scene/SssChoice.h"

#include <initializer_list>
#include <vector>

namespace dermis {

struct SssSettings;

// One integer setting a technique reads.
struct SssSampleSetting {
    const char* key;    // in settings.sss and in a quality table's choice: "taps"
    const char* label;  // in describeSssChoice: "taps", "samples"
    int SssSettings::*setting;
    int SssChoice::*choice;
    const IntegerRule& (*rule)();
};

struct SssTechniqueInfo {
    SssTechnique technique = SssTechnique::Gaussians;
    std::vector<SssSampleSetting> settings;  // the sample counts it reads
    // The choices `dermis tune` measures and the technique benchmarks time,
    // cheapest first (canonical: only its own settings differ from the defaults).
    std::vector<SssChoice> candidates;
    // It scatters in the lighting pass (from a table), not by filtering the
    // irradiance: the SSS chain passes its slots' irradiance through unchanged.
    bool scattersInLighting = false;
};

// `technique` with each of `counts` in `member`, the rest at the defaults.
std::vector<SssChoice> sampleCountCandidates(SssTechnique technique, int SssChoice::*member, std::initializer_list<int> counts);

// Every technique, in kSssTechniques' order.
const std::vector<SssTechniqueInfo>& sssTechniques();
const SssTechniqueInfo& sssTechniqueInfo(SssTechnique technique);

}  // namespace dermis
