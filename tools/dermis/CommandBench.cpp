// dermis bench: run time against error. Sweeps the quality knobs of both SSS
// modes, times each configuration and measures its error against the CPU
// reference.
#include "Args.h"
#include "BenchFiles.h"
#include "Commands.h"
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
#include "scene/SceneLoader.h"
#include "shards/BenchShards.h"
#include "shards/ShardNote.h"

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
    "  --reference FILE   an existing full reference .exr of this scene at --size (skips computing it);\n"
    "                     one whose header records another scene, or an 8-bit image, is refused\n"
    "REFERENCE_OPTIONS"
    "  --set PATH=VALUE   override a scene value for every configuration; repeatable\n"
    "  --shard K/N        measure only configurations K, K+N, K+2N, ... (K from 1) of the plan;\n"
    "                     DIR then holds the references, the error images of the defaults\n"
    "                     this part measured and bench_shard.json, and `dermis merge` joins\n"
    "                     the N directories into the files above (docs/shards.md)\n"
    "  --backend NAME     egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --no-plots         no matplotlib plots and no errors.md (no Python needed); the CSV and\n"
    "                     JSON files and the error images above are still written\n"
    "  --quiet            no progress (warnings stay)\n"
    "  --help             this text\n"
    "\n"
    "The plots are drawn by tools/plot_bench.py with matplotlib (Debian: python3-matplotlib).\n"
    "Exit status: 0 on success, 1 when the scene, a configuration, the reference, a write or\n"
    "the plotting fails, 2 for bad command-line usage. Every configuration is checked before\n"
    "anything is rendered.\n";

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
    shards::ShardSpec shard;
    int configurations = 0;  // of the whole job; `planned` holds the shard's
    shards::ShardStride configurationsOfShard;  // the job's numbers of `planned`
    BenchSweepSettings sweep() const {
        return {scenePath, width, height, frames, true, configurationsOfShard.first, configurationsOfShard.step};
    }
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
    if (args.has("shard")) {
        auto shard = shards::parseShardSpec(args.get("shard", ""));
        if (!shard.ok()) return shard.error();
        options.shard = *shard;
    }
    *usage = false;
    auto planned = bench::planConfigs(options.scenePath, options.base, *sweep);
    if (!planned.ok()) return planned.error();
    options.configurations = int(planned->size());
    if (options.shard.count > options.configurations) {
        *usage = true;
        return makeError("--shard " + options.shard.text(),
                         "more shards than configurations (" + std::to_string(options.configurations) + ")");
    }
    options.configurationsOfShard = shards::shardStride(options.shard, options.configurations);
    for (int i = 0; i < options.configurationsOfShard.count; ++i)
        options.planned.push_back(std::move((*planned)[size_t(options.configurationsOfShard.item(i))]));
    return options;
}

// Everything the rows depend on but the program and the machine: the scene as
// loaded with every --set, the size, frames, sweep and the references' settings.
std::string benchIdentity(const BenchOptions& options, const Scene& scene) {
    const ReferenceSettings& r = options.reference;
    std::string text = "bench " + std::to_string(options.width) + "x" + std::to_string(options.height) + " frames " +
                       std::to_string(options.frames) + " sweep " + options.sweepSpec + " density " +
                       std::to_string(r.density) + " spp " + std::to_string(r.samplesPerPixel) + " irradiance " +
                       std::to_string(r.irradianceSizeTexels) + " change spp " + std::to_string(r.changeSamplesPerPixel) +
                       " target " + std::to_string(r.progressive.targetRelativeRmse) + " passes " +
                       std::to_string(r.progressive.maxPasses) + " reference " + options.givenReference +
                       " configurations " + std::to_string(options.configurations);
    return shards::identityOf(text + "\n" + sceneToJson(scene));
}

}  // namespace

int runBench(const std::vector<std::string>& rawArgs) {
    std::set<std::string> valued = {"out", "sweep", "size", "frames", "reference", "set", "backend", "shard"};
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
    auto session = Session::open(options->scenePath, options->base, options->backend, false);
    if (!session.ok()) return failure(session.error());
    std::optional<Image> givenReference;
    if (!options->givenReference.empty()) {
        auto loaded = loadReferenceImage(options->givenReference, options->width, options->height, *session->scene);
        if (!loaded.ok()) return failure(loaded.error());
        givenReference = std::move(*loaded);
    }
    const std::string identity = benchIdentity(*options, *session->scene);  // before any configuration changes it
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
    std::vector<std::string> errorImages;
    for (const auto& [name, image] : result->errorImages) {
        if (Status saved = outputs.stageImage((options->outDir / name).string(), image); !saved.ok()) return failure(saved.error());
        errorImages.push_back(name);
    }
    if (options->shard.whole()) {
        if (Status staged = stageBenchTables(options->outDir, result->rows, summary, options->plots, outputs); !staged.ok())
            return failure(staged.error());
    } else {
        const std::string note = shards::benchShardNoteJson(options->shard, identity,
                                                            options->configurations, summary, result->rows, errorImages);
        const std::string notePath = (options->outDir / shards::kBenchShardNoteName).string();
        if (Status written = outputs.stageText(notePath, note); !written.ok()) return failure(written.error());
    }
    if (Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    if (options->shard.whole()) printBenchDefaults(summary);
    log::info("wrote " + options->outDir.string());
    return 0;
}

}  // namespace dermis::cli
