#pragma once
// The configurations `dermis bench` renders: the sweep (SweepSpec.h) loaded
// as scenes, made canonical and without duplicates.

#include "bench/SweepSpec.h"
#include "core/Result.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace dermis::bench {

struct PlannedConfig {
    SweepConfig sweep;
    Scene scene;  // the scene file with `base`, --set and the configuration applied
    bool isDefault = false;
};

// Loads every configuration (so a bad value fails before hours of work), adds
// each swept mode's shipped defaults and drops configurations that are the
// same. Each is first made canonical: the SSS settings its technique does not
// read are reset to the defaults (SssChoice::canonical), so sweeping
// sss.technique x every technique's sample count measures each render once.
// `base` are --set strings applied to every configuration before its own.
Result<std::vector<PlannedConfig>> planConfigs(const std::string& scenePath, const std::vector<std::string>& base,
                                               const std::vector<SweepConfig>& sweep);

}  // namespace dermis::bench
