#pragma once
// What `dermis bench` measures: each planned configuration of a sweep timed
// and scored against the references by cause and region, the Pareto fronts
// marked, and the run's summary (bench/BenchReport.h writes the files).

#include "measure/CauseMeter.h"
#include "measure/Session.h"

#include "bench/BenchReport.h"
#include "bench/SweepPlan.h"
#include "core/Image.h"
#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis::measure {

struct BenchSweepSettings {
    std::string scenePath;
    int width = 0;  // the compared size; a configuration's `scale` renders at a multiple
    int height = 0;
    int frames = 5;  // timed, after one warm-up (the first configuration warms up longer)
    bool printRows = true;
    // The ids of the rows: firstId, firstId + idStep, ... (a shard's configurations in the job's plan).
    int firstId = 0;
    int idStep = 1;
};

struct BenchSweepResult {
    std::vector<bench::BenchRow> rows;  // in the plan's order, fronts marked
    // Per swept mode's default configuration: "error_MODE.png" and its heatmap
    // (max over RGB of |render - reference| on SSS pixels, false colour).
    std::vector<std::pair<std::string, Image>> errorImages;
};

// Renders and scores every configuration in turn on the session (whose scene
// settings it leaves at the last configuration's).
Result<BenchSweepResult> measureBenchSweep(Session& session, CauseMeter& meter,
                                           const std::vector<bench::PlannedConfig>& planned,
                                           const BenchSweepSettings& settings);

// The fraction of relative RMSE within which "the cheapest good enough" configuration must lie.
constexpr double kBenchErrorLimit = 0.02;

// summary.json: the run's settings, the SSS pixels and regions, and per mode
// the default, the most accurate and the cheapest good-enough configurations.
nlohmann::ordered_json benchSummaryJson(const BenchSweepSettings& settings, const BenchSweepResult& result,
                                        const CauseMeter& meter, const Session& session);

}  // namespace dermis::measure
