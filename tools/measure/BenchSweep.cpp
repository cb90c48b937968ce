#include "measure/BenchSweep.h"

#include "measure/MeasuredRender.h"

#include "core/ImageMetrics.h"
#include "core/ImageResample.h"
#include "core/Log.h"
#include "scene/SceneEnums.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dermis::measure {
namespace {

constexpr int kFirstWarmUpFrames = 3;

double sssGpuMs(const std::vector<PassSummary>& passes) {
    double total = 0.0;
    for (const PassSummary& pass : passes) total += bench::isSssPass(pass.name) ? pass.gpuMs : 0.0;
    return total;
}

bench::BenchRow rowOf(size_t id, const bench::PlannedConfig& config, const MeasuredRender& measured, int width,
                      int height, int frames) {
    bench::BenchRow row;
    row.id = static_cast<int>(id);
    row.mode = config.sweep.mode;
    if (config.scene.settings.mode == SssMode::ScreenSpace) {
        row.technique = std::string(kSssTechniques.name(config.scene.settings.sss.technique));
    }
    row.label = config.sweep.label.empty() ? "default" : config.sweep.label;
    row.isDefault = config.isDefault;
    row.width = width;
    row.height = height;
    row.frames = frames;
    for (const PassSummary& pass : measured.timings.summary()) {
        if (pass.executed) row.passes.push_back(pass);
    }
    row.frameGpuMs = measured.timings.frameGpuMs();
    row.sssGpuMs = sssGpuMs(row.passes);
    row.wallMs = measured.wallMsPerFrame;
    row.overrides = config.sweep.overrides;
    return row;
}

void printRow(const bench::BenchRow& row, size_t index, size_t count) {
    std::printf("[%zu/%zu] %s %-40s %8.1f ms  relative RMSE: total %6.2f%%, irradiance %6.2f%%, scatter %6.2f%%\n",
                index + 1, count, row.mode.c_str(), row.label.c_str(), row.frameGpuMs, 100.0 * row.relativeRmse,
                100.0 * row.errors.relativeRmse(bench::ErrorCause::Irradiance),
                100.0 * row.errors.relativeRmse(bench::ErrorCause::Scatter));
    std::fflush(stdout);
}

}  // namespace

Result<BenchSweepResult> measureBenchSweep(Session& session, CauseMeter& meter,
                                           const std::vector<bench::PlannedConfig>& planned,
                                           const BenchSweepSettings& settings) {
    const Image& reference = meter.fullReference();
    const std::vector<uint8_t> mask = meter.sssMask();
    BenchSweepResult result;
    for (size_t i = 0; i < planned.size(); ++i) {
        const bench::PlannedConfig& config = planned[i];
        session.scene->settings = config.scene.settings;
        session.scene->environment = config.scene.environment;  // its quality keys may be swept (SweepSpec.cpp)
        const int w = std::max(1, static_cast<int>(std::lround(settings.width * config.sweep.scale)));
        const int h = std::max(1, static_cast<int>(std::lround(settings.height * config.sweep.scale)));
        // The first configuration also warms up the process (first use of every
        // program, the shadow maps' cache).
        auto measured = measureRender(session, settings.scenePath, w, h, settings.frames, i == 0 ? kFirstWarmUpFrames : 1);
        if (!measured.ok()) return measured.error();
        const Image diffuse = (w == settings.width && h == settings.height)
                                  ? measured->diffuse
                                  : resampleImage(measured->diffuse, settings.width, settings.height);
        auto error = compareImages(reference, diffuse, mask);
        if (!error.ok()) return error.error();
        auto errors = meter.measure(session, diffuse, w, h);
        if (!errors.ok()) return errors.error();
        if (config.isDefault) {
            const double scaleMax = roundUpToNiceNumber(differencePercentile(reference, diffuse, mask, 0.99));
            result.errorImages.emplace_back("error_" + config.sweep.mode + ".png",
                                            differenceHeatmap(reference, diffuse, mask, scaleMax));
        }
        bench::BenchRow row = rowOf(size_t(settings.firstId) + i * size_t(settings.idStep), config, *measured, w, h, settings.frames);
        row.relativeRmse = error->relativeRmse;
        row.maxAbsDifference = error->maxAbsDifference;
        row.psnrDb = error->psnrDb;
        row.errors = *errors;
        if (settings.printRows && !log::quiet()) printRow(row, i, planned.size());
        result.rows.push_back(std::move(row));
    }
    bench::markParetoFronts(result.rows);
    return result;
}

nlohmann::ordered_json benchSummaryJson(const BenchSweepSettings& settings, const BenchSweepResult& result,
                                        const CauseMeter& meter, const Session& session) {
    nlohmann::ordered_json summary;
    summary["scene"] = settings.scenePath;
    summary["width"] = settings.width;
    summary["height"] = settings.height;
    summary["frames"] = settings.frames;
    summary["renderer"] = session.context->renderer();
    const std::vector<uint8_t> mask = meter.sssMask();
    summary["sss_pixels"] = std::count(mask.begin(), mask.end(), uint8_t{1});
    summary["uncovered_pixels"] = meter.uncoveredPixels();
    for (const EnumEntry<bench::ErrorRegion>& region : bench::kErrorRegions) {
        const std::vector<uint8_t> inRegion = bench::regionMask(meter.regions(), region.value);
        summary["region_pixels"][std::string(region.name)] = std::count(inRegion.begin(), inRegion.end(), uint8_t{1});
    }
    summary["scatter_error_limit"] = bench::kScatterErrorLimit;  // the goal line of the plots
    summary["modes"] = bench::benchSummary(result.rows, kBenchErrorLimit);
    return summary;
}

}  // namespace dermis::measure
