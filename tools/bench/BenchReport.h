#pragma once
// What `dermis bench` writes: results.csv (one row per configuration),
// passes.csv (per-pass GPU ms of each), summary.json (the shipped defaults'
// error and the cheapest configurations under error limits), and the plots,
// which tools/plot_bench.py draws from those files.

#include "bench/ErrorCauses.h"
#include "core/Result.h"
#include "render/FrameTimings.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis::bench {

struct BenchRow {
    int id = 0;
    std::string mode;   // a name from kSssModes
    std::string technique;  // a name from kSssTechniques; screen space only, "" in texture space
    std::string label;  // the swept values, "default" for the shipped settings
    bool isDefault = false;
    bool onParetoFront = false;         // within its front group (paretoGroup), on total error
    bool onScatterParetoFront = false;  // within its front group, on scatter error
    int width = 0;
    int height = 0;
    int frames = 0;
    double frameGpuMs = 0.0;  // median over the frames of the sum over passes
    double sssGpuMs = 0.0;    // the mode's own passes (sss ..., transmittance, ts ...), medians summed
    double wallMs = 0.0;      // per frame
    double relativeRmse = 0.0;  // total error over every SSS pixel (errors holds it too)
    double maxAbsDifference = 0.0;
    double psnrDb = 0.0;
    CauseErrors errors;         // relative RMSE by cause and region
    std::vector<std::string> overrides;  // the --set strings of the configuration
    std::vector<PassSummary> passes;     // executed passes
};

// True for the passes that a mode adds for subsurface scattering: every pass
// but those each frame has whatever its technique (shadows, G-buffer, SSAO,
// lighting, composite, tone mapping, the AOV and the LEAN specular).
bool isSssPass(const std::string& passName);

// The rows one Pareto front compares: "ss gaussians", "ss separable",
// "ss disk" (one front per screen-space technique) and "ts".
std::string paretoGroup(const BenchRow& row);

// Marks each row's onParetoFront and onScatterParetoFront (frame GPU ms
// against the total and the scatter relative RMSE, per paretoGroup).
void markParetoFronts(std::vector<BenchRow>& rows);

// The accuracy goal on the technique's own error: 1% relative RMSE.
constexpr double kScatterErrorLimit = 0.01;

// {cause: {region: {relative_rmse, max_abs_difference, pixels} or null}}.
nlohmann::ordered_json causeErrorsJson(const CauseErrors& errors);

std::string resultsCsv(const std::vector<BenchRow>& rows);
std::string passesCsv(const std::vector<BenchRow>& rows);

// Per mode: the default row (with its error by cause and region), the most
// accurate one, and the cheapest whose relative RMSE is at most `errorLimit`
// (absolute, against the reference) and at most the most accurate one's +
// `errorLimit` (null where none is); the same on scatter error.
nlohmann::ordered_json benchSummary(const std::vector<BenchRow>& rows, double errorLimit);

}  // namespace dermis::bench
