#include "measure/ModeComparison.h"

#include "bench/BenchReport.h"
#include "core/Log.h"
#include "frame/Renderer.h"

#include <cmath>
#include <cstdio>

namespace dermis::measure {

const MeasuredRender& ModeRenders::of(SssMode mode) const {
    for (const auto& [name, measured] : renders) {
        if (name == kSssModes.name(mode)) return measured;
    }
    return renders.front().second;
}

Result<ModeRenders> renderEveryMode(Session& session, const std::string& scenePath, int width, int height, int frames) {
    ModeRenders modes;
    for (const EnumEntry<SssMode>& mode : kSssModes) {
        session.scene->settings.mode = mode.value;
        log::info("rendering " + scenePath + " in mode " + std::string(mode.name));
        auto measured = measureRender(session, scenePath, width, height, frames, /*warmUpFrames=*/0);
        if (!measured.ok()) return measured.error();
        modes.renders.emplace_back(std::string(mode.name), std::move(*measured));
    }
    auto mask = sssMask(*session.renderer, width, height);
    if (!mask.ok()) return mask.error();
    modes.sssMask = std::move(*mask);
    if (const Status gl = session.checkGlErrors(); !gl.ok()) return gl.error();
    return modes;
}

double addModeDifference(const ModeRenders& modes, nlohmann::ordered_json& metrics,
                         std::optional<ImageDifference>* difference) {
    const Image& ss = modes.of(SssMode::ScreenSpace).diffuse;
    const Image& ts = modes.of(SssMode::TextureSpace).diffuse;
    auto compared = compareImages(ss, ts, modes.sssMask);
    if (!compared.ok()) {
        metrics["sss_pixels"] = 0;
        log::warn("no SSS pixel on screen: the metrics are empty");
        return 0.0;
    }
    *difference = *compared;
    metrics.update(differenceJson(*compared));
    // The heatmap's scale tops out at the 99th percentile, so that a few
    // outliers do not leave the rest black; larger differences saturate.
    const double p99 = differencePercentile(ss, ts, modes.sssMask, 0.99);
    metrics["difference_p99"] = std::isfinite(p99) ? nlohmann::ordered_json(p99) : nlohmann::ordered_json();
    const double scaleMax = roundUpToNiceNumber(p99);
    metrics["heatmap_scale_max"] = scaleMax;
    return scaleMax;
}

nlohmann::ordered_json againstReference(const ModeRenders& modes, const Image& reference) {
    nlohmann::ordered_json against;
    for (const auto& [mode, measured] : modes.renders) {
        auto error = compareImages(reference, measured.diffuse, modes.sssMask);
        against[mode] = error.ok() ? differenceJson(*error) : nlohmann::ordered_json();
        if (error.ok() && !log::quiet()) {
            std::printf("%s against the reference: relative RMSE %.4f, max difference %.4g, PSNR %.1f dB\n", mode.c_str(),
                        error->relativeRmse, error->maxAbsDifference, error->psnrDb);
        }
    }
    return against;
}

Result<nlohmann::ordered_json> errorsByCause(Session& session, CauseMeter& meter, const ModeRenders& modes, int width,
                                             int height) {
    nlohmann::ordered_json out;
    const SssMode shippedMode = session.scene->settings.mode;
    for (const auto& [mode, measured] : modes.renders) {
        session.scene->settings.mode = *kSssModes.parse(mode);
        auto errors = meter.measure(session, measured.diffuse, width, height);
        if (!errors.ok()) {
            session.scene->settings.mode = shippedMode;
            return errors.error();
        }
        out[mode] = bench::causeErrorsJson(*errors);
        if (!log::quiet()) {
            std::printf("%s relative RMSE: total %.2f%%, irradiance %.2f%%, scatter %.2f%%\n", mode.c_str(),
                        100.0 * errors->relativeRmse(bench::ErrorCause::Total),
                        100.0 * errors->relativeRmse(bench::ErrorCause::Irradiance),
                        100.0 * errors->relativeRmse(bench::ErrorCause::Scatter));
        }
    }
    session.scene->settings.mode = shippedMode;
    return out;
}

}  // namespace dermis::measure
