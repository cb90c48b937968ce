// dermis compare: one frame of a scene in screen-space and in texture-space
// mode, the images, a difference heatmap and the metrics.
#include "Args.h"
#include "Commands.h"
#include "ReferenceOptions.h"

#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "measure/CauseMeter.h"
#include "measure/MeasuredRender.h"
#include "measure/ModeComparison.h"
#include "measure/Session.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
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
    "                      reference SCENE --size WxH --spp 1 --out FILE; one with more\n"
    "                      samples per pixel is antialiased, which the engine is not, and\n"
    "                      gets a warning); metrics.json then holds\n"
    "                      each mode's relative RMSE, largest difference and PSNR against it\n"
    "                      over SSS pixels. The reference takes ambient occlusion as 1:\n"
    "                      add --set ssao.enabled=false to compare like with like. A\n"
    "                      reference whose header records another scene (camera, lights,\n"
    "                      characters, profiles, environment, or the settings it reads) or\n"
    "                      an 8-bit image is refused\n"
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
    "  --quiet             no progress messages (warnings stay)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene, the GL context or a write fails,\n"
    "2 for bad command-line usage.\n";

std::string helpText() {
    std::string help = kHelp;
    const std::string word = "REFERENCE_OPTIONS";
    help.replace(help.find(word), word.size(), referenceOptionsHelp());
    return help;
}

struct CompareOptions : MeasureOptions {
    bool byCause = false;
    bool glDebug = false;
    std::string referencePath;  // --reference FILE, or empty
    std::vector<std::string> overrides;
};

Result<CompareOptions> parseCompareOptions(const ParsedArgs& args) {
    auto common = measureOptionsFromArgs(args, "compare");
    if (!common.ok()) return common.error();
    CompareOptions options;
    static_cast<MeasureOptions&>(options) = std::move(*common);
    options.byCause = args.flags.count("errors") > 0;
    options.glDebug = args.flags.count("gl-debug") > 0;
    options.referencePath = args.get("reference", "");
    options.overrides = args.all("set");
    if (options.byCause) options.overrides.insert(options.overrides.begin(), "ssao.enabled=false");
    return options;
}

// The metrics of every comparison the options ask for.
Result<nlohmann::ordered_json> compareMetrics(const CompareOptions& options, Session& session, const ModeRenders& modes,
                                              const std::optional<Image>& reference, double* heatmapScaleMax,
                                              std::optional<ImageDifference>* difference) {
    nlohmann::ordered_json metrics;
    metrics["scene"] = options.scenePath;
    metrics["width"] = options.width;
    metrics["height"] = options.height;
    metrics["frames"] = options.frames;
    metrics["compared"] = "diffuse AOV (linear), texture space (test) against screen space (reference), SSS pixels";
    *heatmapScaleMax = addModeDifference(modes, metrics, difference);
    if (reference) {
        metrics["against_reference"] = againstReference(modes, *reference);
        metrics["against_reference"]["file"] = options.referencePath;
    }
    if (options.byCause) {
        ReferenceImages references(options.outDir, options.reference);
        auto meter = CauseMeter::create(session, references, reference);
        if (!meter.ok()) return meter.error();
        metrics["uncovered_pixels"] = meter->uncoveredPixels();
        auto errors = errorsByCause(session, *meter, modes, options.width, options.height);
        if (!errors.ok()) return errors.error();
        metrics["errors"] = *errors;
    }
    for (const auto& [mode, measured] : modes.renders) metrics["timings"][mode] = nlohmann::json::parse(measured.timingsJson);
    return metrics;
}

// MODE.exr (the diffuse AOV) and MODE.png (the final image) of every mode, the heatmap and metrics.json.
Status stageCompareOutputs(const CompareOptions& options, const ModeRenders& modes, const nlohmann::ordered_json& metrics,
                           double heatmapScaleMax, OutputFiles& outputs) {
    auto file = [&](const std::string& name) { return (options.outDir / name).string(); };
    for (const char* extension : {".exr", ".png"}) {
        for (const auto& [mode, measured] : modes.renders) {
            const Image& image = std::string(extension) == ".exr" ? measured.diffuse : measured.finalImage;
            if (const Status saved = outputs.stageImage(file(mode + extension), image); !saved.ok()) return saved;
        }
    }
    const Image heatmap = differenceHeatmap(modes.of(SssMode::ScreenSpace).diffuse,
                                            modes.of(SssMode::TextureSpace).diffuse, modes.sssMask, heatmapScaleMax);
    if (const Status saved = outputs.stageImage(file("difference.png"), heatmap); !saved.ok()) return saved;
    return outputs.stageText(file("metrics.json"), metrics.dump(2) + "\n");
}

}  // namespace

int runCompare(const std::vector<std::string>& rawArgs) {
    std::set<std::string> valued = {"out", "size", "frames", "set", "backend", "reference"};
    valued.insert(kReferenceOptionNames.begin(), kReferenceOptionNames.end());
    auto args = parseArgs(rawArgs, valued, {"errors", "gl-debug", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::fputs(helpText().c_str(), stdout), 0;
    auto options = parseCompareOptions(*args);
    if (!options.ok()) return usageError(options.error());
    log::setQuiet(args->flags.count("quiet") > 0);

    // Every file of the command, or none (docs/cli.md, "Outputs"); the folder
    // exists from here on (--errors computes its references into it) and goes
    // again, if this made it, when the command fails.
    OutputFiles outputs;
    if (Status prepared = outputs.prepareDirectory(options->outDir.string()); !prepared.ok()) return failure(prepared.error());
    auto session = Session::open(options->scenePath, options->overrides, options->backend, options->glDebug);
    if (!session.ok()) return failure(session.error());
    std::optional<Image> reference;
    if (!options->referencePath.empty()) {
        auto loaded = loadReferenceImage(options->referencePath, options->width, options->height, *session->scene);
        if (!loaded.ok()) return failure(loaded.error());
        reference = std::move(*loaded);
    }
    auto modes = renderEveryMode(*session, options->scenePath, options->width, options->height, options->frames);
    if (!modes.ok()) return failure(modes.error());
    double heatmapScaleMax = 0.0;
    std::optional<ImageDifference> difference;
    auto metrics = compareMetrics(*options, *session, *modes, reference, &heatmapScaleMax, &difference);
    if (!metrics.ok()) return failure(metrics.error());
    if (Status staged = stageCompareOutputs(*options, *modes, *metrics, heatmapScaleMax, outputs); !staged.ok())
        return failure(staged.error());
    if (const Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    if (!log::quiet() && difference) {
        std::printf("%zu SSS pixels: relative RMSE %.4f, max difference %.4g, PSNR %.1f dB\n", difference->pixels,
                    difference->relativeRmse, difference->maxAbsDifference, difference->psnrDb);
    }
    log::info("wrote " + options->outDir.string());
    return 0;
}

}  // namespace dermis::cli
