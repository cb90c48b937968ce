// dermis compare: one frame of a scene in screen-space and in texture-space
// mode, the images, a difference heatmap and the metrics.
#include "Args.h"
#include "ReferenceOptions.h"
#include "measure/CauseMeter.h"
#include "Commands.h"
#include "measure/MeasuredRender.h"
#include "measure/Session.h"

#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "bench/BenchReport.h"
#include "core/TextFile.h"
#include "frame/Renderer.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis compare SCENE --out DIR [options]\n"
    "\n"
    "Renders one frame of SCENE in screen-space (mode ss) and in texture-space (mode ts)\n"
    "subsurface scattering, everything else the same, and writes into DIR:\n"
    "  ss.exr, ts.exr    the diffuse AOV, linear float: the scattered light leaving the\n"
    "                    skin (after albedo and energy conservation, before the specular\n"
    "                    and tone mapping), which is what the two modes compute differently\n"
    "  ss.png, ts.png    the final tone-mapped images\n"
    "  difference.png    max over RGB of |ss - ts| of the diffuse AOV on SSS pixels, in\n"
    "                    false colour with a scale bar up to the 99th percentile rounded\n"
    "                    up (larger differences saturate; other pixels dark grey)\n"
    "  metrics.json      over SSS pixels (characters with a diffusion profile): relative\n"
    "                    RMSE, RMSE, largest difference and PSNR of ts against ss; and each\n"
    "                    mode's per-pass timings (as `dermis render --timings` writes them)\n"
    "                    and, with --reference, each mode's error against the reference;\n"
    "                    with --errors, each mode's error by cause and region\n"
    "\n"
    "options:\n"
    "  --out DIR           output directory (created if missing); required\n"
    "  --size WxH          frame size in pixels (default 640x360)\n"
    "  --frames N          frames per mode; timings are medians over them (default 5)\n"
    "  --reference FILE    a CPU reference of the diffuse AOV at the same size (dermis\n"
    "                      reference SCENE --size WxH --out FILE); metrics.json then holds\n"
    "                      each mode's relative RMSE, largest difference and PSNR against it\n"
    "                      over SSS pixels. The reference takes ambient occlusion as 1:\n"
    "                      add --set ssao.enabled=false to compare like with like\n"
    "  --errors            each mode's error split by cause (total against the full CPU\n"
    "                      reference, irradiance with SSS off on both sides, scatter against\n"
    "                      the matched-irradiance reference) and by region, as `dermis bench`\n"
    "                      reports it (docs/bench.md); computes the CPU references into DIR\n"
    "                      (reused by a later run when they still match) and sets\n"
    "                      ssao.enabled=false, as the reference takes AO as 1; with\n"
    "                      --reference, that file is the full reference\n"
    "REFERENCE_OPTIONS"
    "  --set PATH=VALUE    override a scene value, checked like the file; repeatable\n"
    "  --backend NAME      egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --gl-debug          GL debug context; driver errors fail the run\n"
    "  --quiet             no progress messages\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene, the GL context or a write fails,\n"
    "2 for bad command-line usage.\n";

Result<MeasuredRender> renderMode(Session& session, const std::string& scenePath, SssMode mode, int width,
                                  int height, int frames) {
    session.scene->settings.mode = mode;
    log::info("rendering " + scenePath + " in mode " + std::string(kSssModes.name(mode)));
    return measureRender(session, scenePath, width, height, frames, /*warmUpFrames=*/0);
}


}  // namespace

int runCompare(const std::vector<std::string>& rawArgs) {
    std::set<std::string> valued = {"out", "size", "frames", "set", "backend", "reference"};
    valued.insert(kReferenceOptionNames.begin(), kReferenceOptionNames.end());
    auto args = parseArgs(rawArgs, valued, {"errors", "gl-debug", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::string help = kHelp;
        const std::string word = "REFERENCE_OPTIONS";
        help.replace(help.find(word), word.size(), referenceOptionsHelp());
        std::fputs(help.c_str(), stdout);
        return 0;
    }
    if (args->positional.size() != 1) return usageError(makeError("compare", "expected exactly one SCENE file"));
    if (!args->has("out")) return usageError(makeError("compare", "--out DIR is required"));
    log::setQuiet(args->flags.count("quiet") > 0);
    const std::string scenePath = args->positional[0];
    const std::filesystem::path outDir = args->get("out", "");
    auto size = parseSize(args->get("size", "640x360"), kMaxFrameDimension);
    if (!size.ok()) return usageError(size.error());
    auto frames = parsePositiveInt("--frames", args->get("frames", "5"));
    if (!frames.ok()) return usageError(frames.error());
    auto backend = parseBackend(args->get("backend", "auto"));
    if (!backend.ok()) return usageError(backend.error());

    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (ec || !std::filesystem::is_directory(outDir)) return failure(makeError(outDir.string(), "cannot create the directory"));

    std::optional<Image> reference;
    if (args->has("reference")) {
        auto loaded = loadReferenceImage(args->get("reference", ""), size->first, size->second);
        if (!loaded.ok()) return failure(loaded.error());
        reference = std::move(*loaded);
    }

    const bool byCause = args->flags.count("errors") > 0;
    auto referenceSettings = referenceSettingsFromArgs(*args);
    if (!referenceSettings.ok()) return usageError(referenceSettings.error());
    std::vector<std::string> overrides = args->all("set");
    if (byCause) overrides.insert(overrides.begin(), "ssao.enabled=false");
    auto session = Session::open(scenePath, overrides, *backend, args->flags.count("gl-debug") > 0);
    if (!session.ok()) return failure(session.error());
    const int width = size->first;
    const int height = size->second;

    // Every mode is rendered; the difference is texture space (test) against screen space (reference).
    std::vector<std::pair<std::string, MeasuredRender>> renders;
    for (const EnumEntry<SssMode>& mode : kSssModes) {
        auto measured = renderMode(*session, scenePath, mode.value, width, height, *frames);
        if (!measured.ok()) return failure(measured.error());
        renders.emplace_back(std::string(mode.name), std::move(*measured));
    }
    auto rendered = [&renders](SssMode mode) -> const MeasuredRender* {
        for (const auto& [name, measured] : renders) {
            if (name == kSssModes.name(mode)) return &measured;
        }
        return &renders.front().second;
    };
    const MeasuredRender* ss = rendered(SssMode::ScreenSpace);
    const MeasuredRender* ts = rendered(SssMode::TextureSpace);
    auto mask = sssMask(*session->renderer, width, height);
    if (!mask.ok()) return failure(mask.error());
    if (const Status gl = session->checkGlErrors(); !gl.ok()) return failure(gl.error());

    auto file = [&](const std::string& name) { return (outDir / name).string(); };
    OutputFiles outputs;  // every file of the command, or none (docs/cli.md, "Outputs")
    for (const char* extension : {".exr", ".png"}) {
        for (const auto& [mode, measured] : renders) {
            const Image& image = std::string(extension) == ".exr" ? measured.diffuse : measured.finalImage;
            if (const Status saved = outputs.stageImage(file(mode + extension), image); !saved.ok())
                return failure(saved.error());
        }
    }

    nlohmann::ordered_json metrics;
    metrics["scene"] = scenePath;
    metrics["width"] = width;
    metrics["height"] = height;
    metrics["frames"] = *frames;
    metrics["compared"] = "diffuse AOV (linear), texture space (test) against screen space (reference), SSS pixels";
    auto difference = compareImages(ss->diffuse, ts->diffuse, *mask);
    double scaleMax = 0.0;
    if (difference.ok()) {
        metrics.update(differenceJson(*difference));
        // The heatmap's scale tops out at the 99th percentile, so that a few
        // outliers do not leave the rest black; larger differences saturate.
        const double p99 = differencePercentile(ss->diffuse, ts->diffuse, *mask, 0.99);
        metrics["difference_p99"] = std::isfinite(p99) ? nlohmann::ordered_json(p99) : nlohmann::ordered_json();
        scaleMax = roundUpToNiceNumber(p99);
        metrics["heatmap_scale_max"] = scaleMax;
    } else {
        metrics["sss_pixels"] = 0;
        log::warn("no SSS pixel on screen: the metrics are empty");
    }
    if (reference) {
        nlohmann::ordered_json against;
        against["file"] = args->get("reference", "");
        for (const auto& [mode, measured] : renders) {
            auto error = compareImages(*reference, measured.diffuse, *mask);
            against[mode] = error.ok() ? differenceJson(*error) : nlohmann::ordered_json();
            if (error.ok() && !log::quiet()) {
                std::printf("%s against the reference: relative RMSE %.4f, max difference %.4g, PSNR %.1f dB\n", mode.c_str(),
                            error->relativeRmse, error->maxAbsDifference, error->psnrDb);
            }
        }
        metrics["against_reference"] = against;
    }
    if (byCause) {
        referenceSettings->width = width;
        referenceSettings->height = height;
        ReferenceImages references(outDir, *referenceSettings);
        auto meter = CauseMeter::create(*session, references, reference);
        if (!meter.ok()) return failure(meter.error());
        metrics["uncovered_pixels"] = meter->uncoveredPixels();
        const SssMode shippedMode = session->scene->settings.mode;
        for (const auto& [mode, measured] : renders) {
            session->scene->settings.mode = *kSssModes.parse(mode);
            auto errors = meter->measure(*session, measured.diffuse, width, height);
            if (!errors.ok()) return failure(errors.error());
            metrics["errors"][mode] = bench::causeErrorsJson(*errors);
            if (!log::quiet()) {
                std::printf("%s relative RMSE: total %.2f%%, irradiance %.2f%%, scatter %.2f%%\n", mode.c_str(),
                            100.0 * errors->relativeRmse(bench::ErrorCause::Total),
                            100.0 * errors->relativeRmse(bench::ErrorCause::Irradiance),
                            100.0 * errors->relativeRmse(bench::ErrorCause::Scatter));
            }
        }
        session->scene->settings.mode = shippedMode;
    }
    for (const auto& [mode, measured] : renders) metrics["timings"][mode] = nlohmann::json::parse(measured.timingsJson);

    if (const Status saved =
            outputs.stageImage(file("difference.png"), differenceHeatmap(ss->diffuse, ts->diffuse, *mask, scaleMax));
        !saved.ok()) {
        return failure(saved.error());
    }
    if (const Status written = outputs.stageText(file("metrics.json"), metrics.dump(2) + "\n"); !written.ok())
        return failure(written.error());
    if (const Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    if (!log::quiet() && difference.ok()) {
        std::printf("%zu SSS pixels: relative RMSE %.4f, max difference %.4g, PSNR %.1f dB\n", difference->pixels,
                    difference->relativeRmse, difference->maxAbsDifference, difference->psnrDb);
    }
    log::info("wrote " + outDir.string());
    return 0;
}

}  // namespace dermis::cli
