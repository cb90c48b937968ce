#pragma once
// One screen-space SSS choice: the technique and the sample counts it reads
// (scene/SssTechniques.h lists which), for one stencil slot
// (plan/SssPlan.h): the scene's settings.sss, or a quality table's row.

#include "scene/SceneEnums.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dermis {

struct SssSettings;

// The screen-space technique and its sample counts for one stencil slot
// (plan/SssPlan.h): the scene's settings.sss, or a quality table's choice.
struct SssChoice {
    SssTechnique technique = SssTechnique::Gaussians;
    int taps = 9;               // gaussians: taps per direction
    int gaussians = 6;          // gaussians: at most this many of the profile's
    int separableSamples = 17;  // separable: samples per direction
    int diskSamples = 40;       // disk: samples per pixel
    static SssChoice fromSettings(const SssSettings& settings);
    // The reference of every loss: technique gaussians, every Gaussian, the most taps.
    static SssChoice finest();
    // The same render with the settings its technique does not read reset to
    // the defaults (SssSettings{}), so equal renders compare equal.
    SssChoice canonical() const;
    void applyTo(SssSettings& settings) const;
    bool operator==(const SssChoice& other) const;
    bool operator!=(const SssChoice& other) const { return !(*this == other); }
};

// {"technique": ..., "taps": ..., "gaussians": ..., "separable_samples": ..., "disk_samples": ...}
nlohmann::ordered_json sssChoiceJson(const SssChoice& choice);
// "gaussians taps=9 gaussians=4", "separable samples=17", "disk samples=32"
std::string describeSssChoice(const SssChoice& choice);

}  // namespace dermis
