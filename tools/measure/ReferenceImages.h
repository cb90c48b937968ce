#pragma once
// The CPU images that `dermis bench` and `dermis compare --errors` measure a
// render against (bench/ErrorCauses.h), computed once and kept in the output
// directory beside a note of what they were computed from, so that a second
// run into the same directory reuses them when nothing they depend on changed:
//   reference.exr            the full CPU reference (exact lighting and scattering)
//   reference_sss_off.exr    the same with SSS off (lighting only)
//   thickness.exr            mm through the part under each pixel (r)
//   scatter_change_H.exr     the exact scattering change of the engine's own
//                            irradiance, one per lighting setup (H: a hash of it)
// Each FILE.exr has FILE.json holding its identity: the scene as loaded (with
// every override) and the reference's settings.

#include "measure/Session.h"

#include "core/Image.h"
#include "core/Result.h"
#include "reference/ReferenceRenderer.h"
#include "scene/Scene.h"

#include <filesystem>
#include <map>
#include <string>

namespace dermis::measure {

struct ReferenceSettings {
    int width = 0;
    int height = 0;
    float density = 8.0f;            // quadrature samples per s^2 (dermis reference --density)
    // One sample at the pixel centre, where the engine rasterises and shades: a
    // box-filtered pixel (more samples) also measures the engine's aliasing,
    // which is not what the causes are about (docs/bench.md, "Sampling").
    int samplesPerPixel = 1;
    int irradianceSizeTexels = 4096;  // the engine's UV irradiance for the matched reference
    // Sub-samples per pixel of the matched reference's scattering change, a
    // square: box-filtered over the pixel, as the engine's render it is added
    // to filters the normal map over the pixel (docs/bench.md, "Sampling").
    int changeSamplesPerPixel = 4;
    // The full and SSS-off references are progressive (ReferenceRenderer::renderDiffuseProgressive).
    reference::ProgressiveSettings progressive;
};

class ReferenceImages {
public:
    ReferenceImages(std::filesystem::path directory, ReferenceSettings settings);

    // The full reference of `scene` (lights, scattering, thickness as the scene sets them).
    Result<Image> full(const Scene& scene);
    Result<Image> sssOff(const Scene& scene);
    Result<Image> thicknessMm(const Scene& scene);
    // The exact scattering change of the engine's irradiance for the session's
    // current scene with SSS on or off as `scatters` says (a GL context must be
    // current): computed once per lighting setup, the real-time SSS knobs
    // (technique, taps, SSS on or off in the configuration) do not change it.
    Result<Image> scatterChange(Session& session, bool scatters);

    const ReferenceSettings& settings() const { return mSettings; }

private:
    template <class Compute>
    Result<Image> cached(const std::string& name, const std::string& identity, Compute&& compute);

    std::filesystem::path mDirectory;
    ReferenceSettings mSettings;
    std::map<std::string, Image> mMemory;  // identity -> image, this run's
};

// One line: the stages' wall seconds, the samples computed and reused, the passes.
std::string referenceStagesSummary(const reference::ReferenceStats& stats);

// The scene with the settings that only the real-time techniques read (mode,
// taps, Gaussians used, blur edges, transmittance, texture-space sizes) set to
// their defaults: two scenes that differ only there light the skin the same.
Scene lightingOnly(const Scene& scene);

}  // namespace dermis::measure
