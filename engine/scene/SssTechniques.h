#pragma once
// The registry of screen-space SSS techniques (docs/screen-space.md,
// "Techniques"): one descriptor per technique, defined in the technique's own
// file (scene/SssTechnique<Name>.cpp) and listed once in SssTechniques.cpp.
// Everything that handles "every technique" loops over sssTechniques(): the
// scene's settings and the quality table's choices (the sample counts), the
// tuner's and the benchmarks' candidates, the sweep's labels. The GL half is
// passes/SssTechniquePasses.cpp (one line per technique that adds passes).
// A technique that scatters in the lighting pass instead (SssLightingScatter)
// hands the pass its GLSL and its per-slot table here, and the lighting pass's
// generic hook (render/LightingScatter.h) does the rest.
//
// Adding a technique: its enum value and name (scene/SceneEnums.h), its
// descriptor file here, its passes or lighting hook and shaders, one line in
// each registry it joins; a new sample count also needs its member in SssChoice
// and SssSettings.

#include "scene/IntegerRule.h"
#include "scene/SssChoice.h"

#include <glm/vec4.hpp>

#include <initializer_list>
#include <vector>

namespace dermis {

struct SssSettings;
struct DiffusionProfile;

// What a technique that scatters in the lighting pass gives it (render/LightingScatter.h).
struct SssLightingScatter {
    // In shaders/include/: defines, for a LightingScatterSurface s (include/LightingScatter.glsl),
    //   vec3 <prefix>Falloff(s, float nDotL): the light's diffuse share per channel;
    //   bool <prefix>ShadowShows(s, float viewDepthM): whether <prefix>Shadow is worth its cost;
    //   vec4 <prefix>Shadow(s, sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, float nDotL):
    //        rgb the diffuse visibility, alpha the light's own (the specular's).
    const char* glslFile = nullptr;
    const char* glslPrefix = nullptr;
    // The per-slot table the GLSL reads (lightingTableV), RGBA texels, row by row.
    int tableColumns = 0;
    int tableRows = 0;
    std::vector<glm::vec4> (*makeTable)(const DiffusionProfile& profile, float widthScale) = nullptr;
    // The slot's ProfileParams.lightingParameter (s.parameter in the GLSL).
    float (*slotParameter)(const DiffusionProfile& profile, float widthScale) = nullptr;
};

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
    // Set when it scatters in the lighting pass (from a table), not by
    // filtering the irradiance: the SSS chain passes its slots' irradiance
    // through unchanged.
    SssLightingScatter lighting;
    bool scattersInLighting() const { return lighting.glslFile != nullptr; }
};

// `technique` with each of `counts` in `member`, the rest at the defaults.
std::vector<SssChoice> sampleCountCandidates(SssTechnique technique, int SssChoice::*member, std::initializer_list<int> counts);

// Every technique, in kSssTechniques' order.
const std::vector<SssTechniqueInfo>& sssTechniques();
const SssTechniqueInfo& sssTechniqueInfo(SssTechnique technique);

}  // namespace dermis
