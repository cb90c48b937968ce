#pragma once
// Runs the wrong-image detectors (stress/Invariants.h) on a stress case: the
// one place that renders the AOVs they read, at the case's size, and applies
// a planted violation (kPlants) to what the checks receive.

#include "core/Result.h"
#include "frame/Renderer.h"
#include "scene/Scene.h"
#include "stress/Invariants.h"
#include "stress/StressCases.h"

#include <cstdint>
#include <memory>

namespace dermis::stress {

// Side of the texture-space irradiance captured for the energy bound in ts mode.
constexpr int kEnergyCaptureTexels = 512;

// Invariants 1-3 on `scene` as `renderer` (made from it; any pass inspector is
// removed) renders it at width x height.
Result<InvariantReport> checkFrameInvariants(Renderer& renderer, const Scene& scene, int width, int height,
                                             Plant plant = Plant::None);

// Invariant 4 on the smooth-lighting family: a skin sphere, one distant
// unshadowed directional light and ambient, no SSAO or transmittance, drawn
// from `seed`, rendered in both modes at kSsTsFrame x kSsTsFrame. A GL
// context must be current. *relative gets the measured difference. The
// renderers use `programs` when given (compiled in that context) and compile
// their own otherwise.
constexpr int kSsTsFrame = 64;
Result<InvariantTally> checkScreenVsTextureCase(uint64_t seed, Plant plant = Plant::None, float* relative = nullptr,
                                                std::shared_ptr<Programs> programs = nullptr);
Scene makeSmoothLightingScene(uint64_t seed, SssMode mode);

// Adds light to `scene` in one of four ways chosen by `seed`: every light
// (and the environment) twice as bright, one light eight times as bright
// (past fp16 for the brightest cases), one more light from the camera, or
// more ambient. Returns what it did, for a violation's detail.
std::string addLight(Scene& scene, uint64_t seed);

// Invariant 5 on `scene` as `renderer` (made from it) renders it: its
// radiance before and after addLight(scene, seed), at width x height. The
// scene is restored before returning.
Result<InvariantTally> checkMoreLight(Renderer& renderer, Scene& scene, uint64_t seed, int width, int height,
                                      Plant plant = Plant::None);

// What `dermis stress` runs per case: invariants 1-3 and 5 on `scene` (the
// case's scene as loaded and moved to its last frame, which `renderer`
// renders), and every kSsTsEvery-th seed invariant 4 on the smooth-lighting
// case of that seed.
constexpr uint64_t kSsTsEvery = 10;
Result<InvariantReport> checkCaseInvariants(Renderer& renderer, Scene& scene, const StressCase& c, Plant plant,
                                            std::shared_ptr<Programs> programs = nullptr);

}  // namespace dermis::stress
