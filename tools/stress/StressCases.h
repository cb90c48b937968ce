#pragma once
// Random scenes and settings for the numerical stress test (docs/stress.md,
// "Cases"): extreme SSS widths and tap counts, both SSS modes and every
// variant, every AOV, frames from 1x1 to 1280x720, near and far planes, a
// camera inside a character, degenerate and zero-area triangles, meshes
// without normals or UVs, zero normals, NaN/Inf texels, light intensities past
// fp16, light sizes, grazing angles, no lights and 64 lights; 1 to 4 frames
// with the camera and a light moving; some scenes go through a JSON file, the
// scene loader and --set overrides; some carry a value the loader must refuse.
// Each case is a pure function of its seed, so a failure is reproduced by its
// seed alone.

#include "core/Result.h"
#include "plan/Aov.h"
#include "scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dermis::stress {

// How a case's scene reaches the renderer.
enum class CasePath {
    Memory,   // the Scene object (still checked by the loader from its JSON text, so it is a legal input)
    Loader,   // written as a JSON file, loaded by the scene loader with `overrides` applied
    Hostile,  // a JSON file (and overrides) holding a value the loader must refuse; never rendered
};

// What the loader's refusal of a hostile case must name.
struct ExpectedRefusal {
    bool throughOverride = false;  // the error names the override (--set ...), not the file
    std::string key;                // e.g. "near_m"
    std::string range;              // text of the allowed range, e.g. ">= 1e-04"
};

struct StressCase {
    uint64_t seed = 0;
    Scene scene;
    int width = 64;
    int height = 36;
    Aov aov = Aov::Final;
    int frames = 1;                // 1-4, every one inspected
    glm::vec3 cameraStepM{0.0f};   // camera and target move by this each frame
    float lightStepDeg = 0.0f;     // the first light turns about +y by this each frame
    CasePath path = CasePath::Memory;
    std::vector<std::string> overrides;  // `--set` texts (Loader and Hostile)
    ExpectedRefusal refusal;             // Hostile only
    std::string description;  // what was extreme about it, for the summary
    // Where its files are (writeStressAssets): one folder per process, so a
    // case's hash leaves it out of the messages it hashes.
    std::string assetDirectory;
};

// Files the cases refer to (glTFs with degenerate triangles, without normals,
// without UVs, with duplicate vertices; textures with NaN/Inf texels),
// written once into `directory`.
Status writeStressAssets(const std::string& directory);

StressCase makeStressCase(uint64_t seed, const std::string& assetDirectory);

// Moves the camera and the first light one step on (frames 1, 2, ...).
void advanceFrame(const StressCase& c, Scene& scene);

}  // namespace dermis::stress
