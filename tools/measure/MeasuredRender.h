#pragma once
// Rendering one frame of a session's scene the way `compare` and `bench`
// measure it: N timed frames (medians), the final image, the linear diffuse
// AOV, and which pixels belong to characters with a diffusion profile.

#include "measure/Session.h"

#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/Result.h"
#include "render/FrameTimings.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dermis::measure {

struct MeasuredRender {
    Image finalImage;      // tone-mapped, after the timed frames
    Image diffuse;         // the diffuse AOV (linear), one more frame
    FrameTimings timings;  // the timed frames only
    std::string timingsJson;
    double wallMsPerFrame = 0.0;  // of the timed frames
};

// `warmUpFrames` are rendered and not timed (shader variants, cached shadow
// maps, texture pools settle); then `frames` timed ones.
Result<MeasuredRender> measureRender(Session& session, const std::string& scenePath, int width, int height,
                                     int frames, int warmUpFrames);

// Per pixel: 0 for the background, else the character index + 1 (the object AOV).
Result<std::vector<int>> objectIds(Session& session, int width, int height);

// The SSS mask, the one definition every measurement uses (bench, compare,
// tune, the error causes, the benchmarks): one byte per pixel, 1 where the
// surface seen scatters (the scatter AOV > 0: a material with a profile, and
// its scatter map not 0 there). Renders one frame of that AOV.
Result<std::vector<uint8_t>> sssMask(Renderer& renderer, int width, int height);

// A linear float image of exactly width x height (the CPU reference) of
// `scene`, or an error naming the file and what is wrong: the size, an 8-bit
// (encoded, not linear) file, or a reference recorded as made from another
// scene (reference/ReferenceDefinition.h; a file without the record, made
// elsewhere, is taken as it is).
Result<Image> loadReferenceImage(const std::string& path, int width, int height, const Scene& scene);

// relative_rmse, rmse, max_abs_difference, psnr_db, peak, sss_pixels; JSON
// has no infinity, so a non-finite figure is written as null.
nlohmann::ordered_json differenceJson(const ImageDifference& difference);

}  // namespace dermis::measure
