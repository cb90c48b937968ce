#pragma once
// Values the scene loader must refuse (core/Limits.h), for the stress test's
// hostile cases: each is either written into the scene file or given as a
// `--set` override, and the refusal must name the file (or the override), the
// key and the allowed range.

#include "scene/Scene.h"

#include <string>
#include <vector>

namespace dermis::stress {

struct HostileValue {
    std::string name;   // for the case's description
    std::string key;    // the key the error must name
    std::string range;  // text the error must give for the allowed range
    // The spoiled value written into the scene (file route); null when the
    // value cannot be written as JSON (1e999).
    void (*spoil)(Scene& scene);
    // The same value as a --set override (override route); null when the
    // scene may lack what the override names (a light).
    std::string (*override)(const Scene& scene);
};

const std::vector<HostileValue>& hostileValues();

}  // namespace dermis::stress
