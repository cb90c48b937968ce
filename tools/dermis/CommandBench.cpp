// dermis bench: run time against error. Sweeps the quality knobs of both SSS
// modes, times each configuration and measures its error against the CPU
// reference.
#include "Args.h"
#include "ReferenceOptions.h"
#include "measure/CauseMeter.h"
#include "Commands.h"
#include "measure/MeasuredRender.h"
#include "Python.h"
#include "measure/Session.h"

#include "bench/BenchReport.h"
#include "bench/SweepPlan.h"
#include "bench/SweepSpec.h"
#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/ImageResample.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/TextFile.h"
#include "scene/SceneEnums.h"
#include "scene/SceneLoader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <unistd.h>

namespace dermis::cli {

using namespace measure;
namespace {

using bench::BenchRow;

// The reference takes ambient occlusion as 1 (reference/ReferenceRenderer.h),
// so every configuration is rendered without SSAO: like is compared with like.
// Light through thin parts is in the reference (the profile over 3-D distance),
// so transmittance and the translucent shadow map stay as the scene sets them.
const std::vector<std::string> kReferenceDefinition = {"ssao.enabled=false"};
constexpr int kFirstWarmUpFrames = 3;
constexpr double kErrorLimit = 0.02;  // "the cheapest setting within 2% relative RMSE"

const char* const kHelp =
    "usage: dermis bench SCENE --out DIR [options]\n"
    "\n"
    "Run time against error. Renders SCENE in many quality configurations of both SSS\n"
    "modes; for each, takes the median GPU ms per frame over N frames and the relative\n"
    "RMSE of the diffuse AOV over SSS pixels, split by cause:\n"
    "  total       against the full CPU reference (dermis reference)\n"
    "  irradiance  SSS off in both the render and the reference: the lighting's own error\n"
    "  scatter     against the matched-irradiance reference (the render with SSS off plus\n"
    "              the exact scattering of the engine's own irradiance): the SSS\n"
    "              technique's own error; 0 when the scene has SSS off, and for a\n"
    "              configuration that turns it off, what leaving SSS out costs\n"
    "and by region: REGIONS.\n"
    "Every configuration is rendered with SSAO off, because the reference takes AO as 1.\n"
    "Writes into DIR:\n"
    "  reference.exr, reference_sss_off.exr, thickness.exr, scatter_change_H.exr\n"
    "                  the CPU images (each with a .json note of what it was computed\n"
    "                  from; a later run into DIR reuses those that still match)\n"
    "  results.csv     one row per configuration: mode, SSS technique (screen space), swept\n"
    "                  values, whether it is the shipped default and on its Pareto fronts\n"
    "                  (total, scatter; one per technique in screen space, one for texture space),\n"
    "                  frame and SSS GPU ms, total relative RMSE, largest difference,\n"
    "                  PSNR, the relative RMSE of every cause and region, its --set overrides\n"
    "  passes.csv      the median GPU ms of every pass of every configuration\n"
    "  summary.json    per mode: the default's error by cause and region, the most\n"
    "                  accurate configuration, the cheapest within 2% total relative RMSE\n"
    "                  and within 2% of the most accurate one, the cheapest within 1%\n"
    "                  scatter error; the machine and the sweep\n"
    "  pareto.png      total and scatter relative RMSE against frame GPU ms, both modes,\n"
    "                  fronts marked\n"
    "  regions.png     the defaults' relative RMSE by cause and region\n"
    "  errors.md       the same as a Markdown table\n"
    "  passes.png      stacked per-pass GPU ms of the fronts' and the default configurations\n"
    "  ERROR_IMAGES\n"
    "                  where each mode's default configuration differs from the reference:\n"
    "                  max over RGB of |mode - reference| on SSS pixels, false colour, scale bar\n"
    "\n"
    "options:\n"
    "  --out DIR          output directory (created if missing); required\n"
    "  --sweep SPEC       what to vary, ';'-separated axes MODE_PREFIXKEY=V1,V2,...; KEY is a\n"
    "                     settings path as --set takes it, several joined by '+', or `scale`\n"
    "                     (render at scale x the size, resample the result back). Default:\n"
    "                     DEFAULT_SWEEP\n"
    "                     The shipped default settings of each swept mode are always measured.\n"
    "  --size WxH         the compared frame size (default 640x360)\n"
    "  --frames N         timed frames per configuration, after one warm-up (default 5)\n"
    "  --reference FILE   an existing full reference .exr of this scene at --size (skips computing it)\n"
    "REFERENCE_OPTIONS"
    "  --set PATH=VALUE   override a scene value for every configuration; repeatable\n"
    "  --backend NAME     egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --no-plots         write the CSV and JSON files only (no Python needed; no PNGs, no errors.md)\n"
    "  --quiet            no progress\n"
    "  --help             this text\n"
    "\n"
    "The plots are drawn by tools/plot_bench.py with matplotlib (Debian: python3-matplotlib).\n"
    "Exit status: 0 on success, 1 when the scene, a configuration, the reference, a write or\n"
    "the plotting fails, 2 for bad command-line usage. Every configuration is checked before\n"
    "anything is rendered.\n";

// Draws the plots of `texts` (the CSV and JSON files, by name) in a hidden
// directory inside outDir, and stages each plot as outDir's file.
Status stagePlots(const std::filesystem::path& outDir, const std::vector<std::pair<std::string, std::string>>& texts,
                  OutputFiles& outputs) {
    namespace fs = std::filesystem;
    const fs::path drawing = outDir / (".plots.dermis-" + std::to_string(::getpid()));
    struct RemoveAfter {
        fs::path dir;
        ~RemoveAfter() {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    } removeAfter{drawing};
    for (const auto& [name, text] : texts)
        if (Status written = writeTextFileAtomically((drawing / name).string(), text); !written.ok()) return written;
    const std::string script = std::string(DERMIS_TOOLS_DIR) + "/plot_bench.py";
    const std::string command = pythonInterpreter() + " '" + script + "' '" + drawing.string() + "'";
    if (std::system(command.c_str()) != 0) {
        return makeError(script, "plotting failed (it needs python3 with matplotlib: apt-get install python3-matplotlib); "
                                 "nothing was written, --no-plots skips the plots");
    }
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(drawing, error)) {
        if (entry.path().extension() != ".png") continue;
        const std::string target = (outDir / entry.path().filename()).string();
        if (Status staged = outputs.stageFile(target, entry.path()); !staged.ok()) return staged;
    }
    if (error) return makeError(drawing.string(), "could not list the plots: " + error.message());
    return success();
}

double sssGpuMs(const std::vector<PassSummary>& passes) {
    double total = 0.0;
    for (const PassSummary& pass : passes) total += bench::isSssPass(pass.name) ? pass.gpuMs : 0.0;
    return total;
}

}  // namespace

int runBench(const std::vector<std::string>& rawArgs) {
    std::set<std::string> valued = {"out", "sweep", "size", "frames", "reference", "set", "backend"};
    valued.insert(kReferenceOptionNames.begin(), kReferenceOptionNames.end());
    auto args = parseArgs(rawArgs, valued, {"no-plots", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::string errorImages;
        for (const EnumEntry<SssMode>& mode : kSssModes) {
            errorImages += (errorImages.empty() ? "error_" : ", error_") + std::string(mode.name) + ".png";
        }
        std::string help = kHelp;
        for (const auto& [word, text] : {std::pair<std::string, std::string>{"DEFAULT_SWEEP", bench::kDefaultSweepSpec},
                                         {"MODE_PREFIX", bench::modePrefixSyntax()},
                                         {"ERROR_IMAGES", errorImages},
                                         {"REGIONS", bench::kErrorRegions.list(", ")},
                                         {"REFERENCE_OPTIONS", referenceOptionsHelp()}}) {
            help.replace(help.find(word), word.size(), text);
        }
        std::fputs(help.c_str(), stdout);
        return 0;
    }
    if (args->positional.size() != 1) return usageError(makeError("bench", "expected exactly one SCENE file"));
    if (!args->has("out")) return usageError(makeError("bench", "--out DIR is required"));
    log::setQuiet(args->flags.count("quiet") > 0);
    const std::string scenePath = args->positional[0];
    const std::filesystem::path outDir = args->get("out", "");
    auto size = parseSize(args->get("size", "640x360"), kMaxFrameDimension);
    if (!size.ok()) return usageError(size.error());
    auto frames = parsePositiveInt("--frames", args->get("frames", "5"));
    if (!frames.ok()) return usageError(frames.error());
    auto backend = parseBackend(args->get("backend", "auto"));
    if (!backend.ok()) return usageError(backend.error());
    auto parsedReference = referenceSettingsFromArgs(*args);
    if (!parsedReference.ok()) return usageError(parsedReference.error());
    ReferenceSettings referenceSettings = *parsedReference;
    auto axes = bench::parseSweepSpec(args->get("sweep", bench::kDefaultSweepSpec));
    if (!axes.ok()) return usageError(axes.error());
    auto sweep = bench::expandSweep(*axes);
    if (!sweep.ok()) return usageError(sweep.error());
    const int width = size->first;
    const int height = size->second;

    std::vector<std::string> base = kReferenceDefinition;
    for (const std::string& change : args->all("set")) base.push_back(change);
    auto planned = bench::planConfigs(scenePath, base, *sweep);
    if (!planned.ok()) return failure(planned.error());

    OutputFiles outputs;  // every file of the command, or none (docs/cli.md, "Outputs")
    if (Status prepared = outputs.prepareDirectory(outDir.string()); !prepared.ok()) return failure(prepared.error());
    auto file = [&](const std::string& name) { return (outDir / name).string(); };

    std::optional<Image> givenReference;
    if (args->has("reference")) {
        auto loaded = loadReferenceImage(args->get("reference", ""), width, height);
        if (!loaded.ok()) return failure(loaded.error());
        givenReference = std::move(*loaded);
    }
    auto session = Session::open(scenePath, base, *backend, false);
    if (!session.ok()) return failure(session.error());
    referenceSettings.width = width;
    referenceSettings.height = height;
    ReferenceImages references(outDir, referenceSettings);
    auto meter = CauseMeter::create(*session, references, std::move(givenReference));
    if (!meter.ok()) return failure(meter.error());
    const Image& reference = meter->fullReference();
    const std::vector<uint8_t> mask = meter->sssMask();

    log::info("bench: " + std::to_string(planned->size()) + " configurations of " + scenePath + " at " +
              std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(*frames) + " frames each");
    std::vector<BenchRow> rows;
    for (size_t i = 0; i < planned->size(); ++i) {
        const bench::PlannedConfig& config = (*planned)[i];
        session->scene->settings = config.scene.settings;
        session->scene->environment = config.scene.environment;  // its quality keys may be swept (SweepSpec.cpp)
        const int w = std::max(1, static_cast<int>(std::lround(width * config.sweep.scale)));
        const int h = std::max(1, static_cast<int>(std::lround(height * config.sweep.scale)));
        // The first configuration also warms up the process (first use of every
        // program, the shadow maps' cache).
        auto measured = measureRender(*session, scenePath, w, h, *frames, i == 0 ? kFirstWarmUpFrames : 1);
        if (!measured.ok()) return failure(measured.error());
        const Image diffuse = (w == width && h == height) ? measured->diffuse : resampleImage(measured->diffuse, width, height);
        auto error = compareImages(reference, diffuse, mask);
        if (!error.ok()) return failure(error.error());
        auto errors = meter->measure(*session, diffuse, w, h);
        if (!errors.ok()) return failure(errors.error());

        if (config.isDefault) {
            const std::string heatmap = file("error_" + config.sweep.mode + ".png");
            const double scaleMax = roundUpToNiceNumber(differencePercentile(reference, diffuse, mask, 0.99));
            if (Status saved = outputs.stageImage(heatmap, differenceHeatmap(reference, diffuse, mask, scaleMax));
                !saved.ok())
                return failure(saved.error());
        }

        BenchRow row;
        row.id = static_cast<int>(i);
        row.mode = config.sweep.mode;
        if (config.scene.settings.mode == SssMode::ScreenSpace) {
            row.technique = std::string(kSssTechniques.name(config.scene.settings.sss.technique));
        }
        row.label = config.sweep.label.empty() ? "default" : config.sweep.label;
        row.isDefault = config.isDefault;
        row.width = w;
        row.height = h;
        row.frames = *frames;
        for (const PassSummary& pass : measured->timings.summary()) {
            if (pass.executed) row.passes.push_back(pass);
        }
        row.frameGpuMs = measured->timings.frameGpuMs();
        row.sssGpuMs = sssGpuMs(row.passes);
        row.wallMs = measured->wallMsPerFrame;
        row.relativeRmse = error->relativeRmse;
        row.maxAbsDifference = error->maxAbsDifference;
        row.psnrDb = error->psnrDb;
        row.errors = *errors;
        row.overrides = config.sweep.overrides;
        rows.push_back(std::move(row));
        if (!log::quiet()) {
            std::printf("[%zu/%zu] %s %-40s %8.1f ms  relative RMSE: total %6.2f%%, irradiance %6.2f%%, scatter %6.2f%%\n",
                        i + 1, planned->size(), rows.back().mode.c_str(), rows.back().label.c_str(),
                        rows.back().frameGpuMs, 100.0 * rows.back().relativeRmse,
                        100.0 * rows.back().errors.relativeRmse(bench::ErrorCause::Irradiance),
                        100.0 * rows.back().errors.relativeRmse(bench::ErrorCause::Scatter));
            std::fflush(stdout);
        }
    }
    bench::markParetoFronts(rows);

    nlohmann::ordered_json summary;
    summary["scene"] = scenePath;
    summary["width"] = width;
    summary["height"] = height;
    summary["frames"] = *frames;
    summary["renderer"] = session->context->renderer();
    summary["sweep"] = args->get("sweep", bench::kDefaultSweepSpec);
    summary["every_configuration"] = base;
    summary["reference"] = args->has("reference") ? args->get("reference", "") : file("reference.exr");
    summary["reference_spp"] = referenceSettings.samplesPerPixel;
    summary["irradiance_size_texels"] = referenceSettings.irradianceSizeTexels;
    summary["sss_pixels"] = std::count(mask.begin(), mask.end(), uint8_t{1});
    summary["uncovered_pixels"] = meter->uncoveredPixels();
    for (const EnumEntry<bench::ErrorRegion>& region : bench::kErrorRegions) {
        const std::vector<uint8_t> inRegion = bench::regionMask(meter->regions(), region.value);
        summary["region_pixels"][std::string(region.name)] = std::count(inRegion.begin(), inRegion.end(), uint8_t{1});
    }
    summary["scatter_error_limit"] = bench::kScatterErrorLimit;  // the goal line of the plots
    summary["modes"] = bench::benchSummary(rows, kErrorLimit);
    const std::vector<std::pair<std::string, std::string>> texts = {{"results.csv", bench::resultsCsv(rows)},
                                                                     {"passes.csv", bench::passesCsv(rows)},
                                                                     {"summary.json", summary.dump(2) + "\n"}};
    for (const auto& [name, text] : texts)
        if (Status written = outputs.stageText(file(name), text); !written.ok()) return failure(written.error());
    if (!args->flags.count("no-plots")) {
        if (Status plotted = stagePlots(outDir, texts, outputs); !plotted.ok()) return failure(plotted.error());
    }
    if (Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    for (const auto& [mode, entry] : summary["modes"].items()) {
        if (log::quiet() || entry["default"].is_null()) continue;
        std::printf("%s default: %.1f ms, relative RMSE %.2f%% (scatter %.2f%%)\n", mode.c_str(),
                    entry["default"]["frame_gpu_ms"].get<double>(), 100.0 * entry["default"]["relative_rmse"].get<double>(),
                    entry["default"]["scatter_relative_rmse"].is_null()
                        ? NAN : 100.0 * entry["default"]["scatter_relative_rmse"].get<double>());
    }
    log::info("wrote " + outDir.string());
    return 0;
}

}  // namespace dermis::cli
