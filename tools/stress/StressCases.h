#pragma once
// Random scenes and settings for the numerical stress test (docs/stress.md): extreme SSS widths and tap counts, near and far
// planes, a camera inside a character, degenerate and zero-area triangles,
// zero normals, NaN/Inf texels, light intensities past fp16, grazing angles,
// no lights and 64 lights. Each case is a pure function of its seed, so a
// failure is reproduced by its seed alone.

#include "core/Result.h"
#include "render/Aov.h"
#include "scene/Scene.h"

#include <cstdint>
#include <string>

namespace dermis::stress {

struct StressCase {
    uint64_t seed = 0;
    Scene scene;
    int width = 64;
    int height = 36;
    Aov aov = Aov::Final;
    std::string description;  // what was extreme about it, for the summary
};

// Files the cases refer to (a degenerate glTF, textures with NaN/Inf texels),
// written once into `directory`.
Status writeStressAssets(const std::string& directory);

StressCase makeStressCase(uint64_t seed, const std::string& assetDirectory);

}  // namespace dermis::stress
