// dermis bench: run time against error. Sweeps the quality knobs of both SSS
// modes, times each configuration and measures its error against the CPU
// reference.
#include "Args.h"
#include "Commands.h"
#include "Python.h"
#include "ReferenceOptions.h"

#include "bench/BenchReport.h"
#include "bench/SweepPlan.h"
#include "bench/SweepSpec.h"
#include "core/Image.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/TextFile.h"
#include "measure/BenchSweep.h"
#include "measure/CauseMeter.h"
#include "measure/MeasuredRender.h"
#include "measure/Session.h"
#include "scene/SceneEnums.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>

#include <unistd.h>

namespace dermis::cli {

using namespace measure;
namespace {

// The reference takes ambient occlusion as 1 (reference/ReferenceRenderer.h),
// so every configuration is rendered without SSAO: like is compared with like.
// Light through thin parts is in the reference (the profile over 3-D distance),
// so transmittance and the translucent shadow map stay as the scene sets them.
const std::vector<std::string> kReferenceDefinition = {"ssao.enabled=false"};

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
        // What the plot script draws: the PNGs and errors.md (the inputs it read stay behind).
        if (entry.path().extension() != ".png" && entry.path().filename() != "errors.md") continue;
        const std::string target = (outDir / entry.path().filename()).string();
        if (Status staged = outputs.stageFile(target, entry.path()); !staged.ok()) return staged;
    }
    if (error) return makeError(drawing.string(), "could not list the plots: " + error.message());
    return success();
}

std::string helpText() {
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
    return help;
}

struct BenchOptions : MeasureOptions {
    std::string sweepSpec;
    std::vector<std::string> base;  // --set strings of every configuration, after kReferenceDefinition
    std::vector<bench::PlannedConfig> planned;
    std::string givenReference;  // --reference FILE, or empty
    bool plots = true;
    BenchSweepSettings sweep() const { return {scenePath, width, height, frames}; }
};

// Every option checked, and every configuration loaded, before anything is rendered.
// A usage error is marked by `usage`.
Result<BenchOptions> parseBenchOptions(const ParsedArgs& args, bool* usage) {
    *usage = true;
    auto common = measureOptionsFromArgs(args, "bench");
    if (!common.ok()) return common.error();
    BenchOptions options;
    static_cast<MeasureOptions&>(options) = std::move(*common);
    options.sweepSpec = args.get("sweep", bench::kDefaultSweepSpec);
    auto axes = bench::parseSweepSpec(options.sweepSpec);
    if (!axes.ok()) return axes.error();
    auto sweep = bench::expandSweep(*axes);
    if (!sweep.ok()) return sweep.error();
    options.givenReference = args.get("reference", "");
    options.plots = !args.flags.count("no-plots");
    options.base = kReferenceDefinition;
    for (const std::string& change : args.all("set")) options.base.push_back(change);
    *usage = false;
    auto planned = bench::planConfigs(options.scenePath, options.base, *sweep);
    if (!planned.ok()) return planned.error();
    options.planned = std::move(*planned);
    return options;
}

// Stages results.csv, passes.csv, summary.json, the error images and (unless
// --no-plots) the plots.
Status stageBenchOutputs(const BenchOptions& options, const BenchSweepResult& result,
                         const nlohmann::ordered_json& summary, OutputFiles& outputs) {
    auto file = [&](const std::string& name) { return (options.outDir / name).string(); };
    for (const auto& [name, image] : result.errorImages)
        if (Status saved = outputs.stageImage(file(name), image); !saved.ok()) return saved;
    const std::vector<std::pair<std::string, std::string>> texts = {{"results.csv", bench::resultsCsv(result.rows)},
                                                                     {"passes.csv", bench::passesCsv(result.rows)},
                                                                     {"summary.json", summary.dump(2) + "\n"}};
    for (const auto& [name, text] : texts)
        if (Status written = outputs.stageText(file(name), text); !written.ok()) return written;
    return options.plots ? stagePlots(options.outDir, texts, outputs) : success();
}

void printDefaults(const nlohmann::ordered_json& summary) {
    for (const auto& [mode, entry] : summary["modes"].items()) {
        if (log::quiet() || entry["default"].is_null()) continue;
        std::printf("%s default: %.1f ms, relative RMSE %.2f%% (scatter %.2f%%)\n", mode.c_str(),
                    entry["default"]["frame_gpu_ms"].get<double>(), 100.0 * entry["default"]["relative_rmse"].get<double>(),
                    entry["default"]["scatter_relative_rmse"].is_null()
                        ? NAN : 100.0 * entry["default"]["scatter_relative_rmse"].get<double>());
    }
}

}  // namespace

int runBench(const std::vector<std::string>& rawArgs) {
    std::set<std::string> valued = {"out", "sweep", "size", "frames", "reference", "set", "backend"};
    valued.insert(kReferenceOptionNames.begin(), kReferenceOptionNames.end());
    auto args = parseArgs(rawArgs, valued, {"no-plots", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::fputs(helpText().c_str(), stdout), 0;
    log::setQuiet(args->flags.count("quiet") > 0);
    bool usage = false;
    auto options = parseBenchOptions(*args, &usage);
    if (!options.ok()) return usage ? usageError(options.error()) : failure(options.error());

    OutputFiles outputs;  // every file of the command, or none (docs/cli.md, "Outputs")
    if (Status prepared = outputs.prepareDirectory(options->outDir.string()); !prepared.ok())
        return failure(prepared.error());
    std::optional<Image> givenReference;
    if (!options->givenReference.empty()) {
        auto loaded = loadReferenceImage(options->givenReference, options->width, options->height);
        if (!loaded.ok()) return failure(loaded.error());
        givenReference = std::move(*loaded);
    }
    auto session = Session::open(options->scenePath, options->base, options->backend, false);
    if (!session.ok()) return failure(session.error());
    ReferenceImages references(options->outDir, options->reference);
    auto meter = CauseMeter::create(*session, references, std::move(givenReference));
    if (!meter.ok()) return failure(meter.error());

    log::info("bench: " + std::to_string(options->planned.size()) + " configurations of " + options->scenePath +
              " at " + std::to_string(options->width) + "x" + std::to_string(options->height) + ", " +
              std::to_string(options->frames) + " frames each");
    auto result = measureBenchSweep(*session, *meter, options->planned, options->sweep());
    if (!result.ok()) return failure(result.error());
    nlohmann::ordered_json summary = benchSummaryJson(options->sweep(), *result, *meter, *session);
    summary["sweep"] = options->sweepSpec;
    summary["every_configuration"] = options->base;
    summary["reference"] =
        options->givenReference.empty() ? (options->outDir / "reference.exr").string() : options->givenReference;
    summary["reference_spp"] = options->reference.samplesPerPixel;
    summary["irradiance_size_texels"] = options->reference.irradianceSizeTexels;
    if (Status staged = stageBenchOutputs(*options, *result, summary, outputs); !staged.ok()) return failure(staged.error());
    if (Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    printDefaults(summary);
    log::info("wrote " + options->outDir.string());
    return 0;
}

}  // namespace dermis::cli
