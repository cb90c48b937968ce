#pragma once
// What `dermis compare` measures: one scene rendered in every SSS mode, the
// texture-space render against the screen-space one on the SSS pixels, each
// against a given reference, and each one's error by cause (CauseMeter).

#include "measure/CauseMeter.h"
#include "measure/MeasuredRender.h"
#include "measure/Session.h"

#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dermis::measure {

struct ModeRenders {
    std::vector<std::pair<std::string, MeasuredRender>> renders;  // kSssModes' order, by name
    std::vector<uint8_t> sssMask;
    const MeasuredRender& of(SssMode mode) const;
};

// Every mode rendered at width x height (`frames` timed each), the SSS mask, and no GL error.
Result<ModeRenders> renderEveryMode(Session& session, const std::string& scenePath, int width, int height, int frames);

// Texture space (test) against screen space (reference), into `metrics`; the
// difference heatmap's top (the 99th percentile, rounded up) is returned, 0
// without SSS pixels. `difference` gets the figures when there are any.
double addModeDifference(const ModeRenders& modes, nlohmann::ordered_json& metrics,
                         std::optional<ImageDifference>* difference);

// Each mode against `reference` (relative RMSE, largest difference, PSNR), printed unless quiet.
nlohmann::ordered_json againstReference(const ModeRenders& modes, const Image& reference);

// Each mode's error by cause and region; the session's mode is restored.
Result<nlohmann::ordered_json> errorsByCause(Session& session, CauseMeter& meter, const ModeRenders& modes, int width,
                                             int height);

}  // namespace dermis::measure
