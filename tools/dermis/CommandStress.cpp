// dermis stress: numerical fuzzing of scenes and settings; every intermediate
// target is checked for non-finite texels.
#include "Args.h"
#include "Commands.h"
#include "measure/Session.h"

#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/Suggest.h"
#include "core/TextFile.h"
#include "gl/GlContext.h"
#include "frame/Renderer.h"
#include "scene/SceneLoader.h"
#include "shards/ShardSpec.h"
#include "stress/StressCases.h"

#include <unistd.h>
#include "stress/StressCounting.h"
#include "stress/StressRun.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis stress [options]\n"
    "\n"
    "Renders N random scenes with extreme settings (SSS widths and tap counts, both\n"
    "SSS modes and every variant, every AOV, frames from 1x1 to 1280x720, near and\n"
    "far planes, a camera inside a character, degenerate triangles, glTFs without\n"
    "normals or UVs or with duplicate vertices, NaN/Inf texels, lights past fp16\n"
    "and of every size, no lights and 64 lights), 1 to 4 frames each with the\n"
    "camera and a light moving. A quarter of the scenes go through a JSON file, the\n"
    "scene loader and --set overrides; 1 in 16 cases holds a value the loader must\n"
    "refuse (counted as refused, not rendered). Each case is a function of its seed\n"
    "and gets a hash of every texel read and every output (the summary's\n"
    "\"hashes\", in seed order).\n"
    "Every pass counts the values its shaders' sanitisers replace (NaN, Inf,\n"
    "clamped above or below the range), and every target it writes is read back:\n"
    "float targets for NaN/Inf, the packed SSS chain half by half, the depth key's\n"
    "slot, unorm targets in [0, 1]. A NaN or Inf made by a pass, or a bad texel,\n"
    "fails the case, which names the first such pass; clamps are only counted.\n"
    "See docs/stress.md.\n"
    "\n"
    "options:\n"
    "  --cases N       how many cases (default 200)\n"
    "  --seed S        the first case's seed; case i uses S + i (default 1)\n"
    "  --out FILE      the summary JSON (default out/stress.json)\n"
    "  --backend NAME  egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --plant-nan PASS  make the pass named PASS (e.g. lighting, \"shadow:light0(dir)\")\n"
    "                output NaN in every case, to show that it is caught: each case\n"
    "                whose PASS shades a pixel then fails and names PASS; a name no\n"
    "                case's frame runs is a usage error that lists the passes run\n"
    "  --plant-violation NAME  plant a wrong image for one detector (docs/stress.md):\n"
    "                  none|coverage|energy|black|ss-ts|more-light (default none)\n"
    "  --failed-scenes DIR  write each failed case's scene, as its detectors saw\n"
    "                it (after the last frame's move), to DIR/seed-N.json, to\n"
    "                reproduce it with dermis render\n"
    "  --shard K/N     run only the K-th of N parts of the cases (K from 1); the\n"
    "                summary says which, and `dermis merge` adds the N summaries up\n"
    "                into the one a single run writes (docs/shards.md)\n"
    "  --quiet         no progress (warnings stay)\n"
    "  --help          this text\n"
    "\n"
    "Each case also runs the wrong-image detectors (coverage, energy, black,\n"
    "ss-ts, more-light; docs/stress.md) and fails when one is violated.\n"
    "\n"
    "Exit status: 0 when no case produced a NaN, an Inf or a bad texel or violated\n"
    "a detector, 1 otherwise or on error, 2 for bad usage. The summary lists every\n"
    "failing case with its seed; a case that cannot be set up at all (e.g. a frame\n"
    "larger than the GL allows), a legal scene the loader refuses, or a hostile\n"
    "value it accepts (or refuses without naming the file or override, the key and\n"
    "the range) is listed as an error and also fails the run.\n";

struct StressOptions {
    int cases = 200;
    int seed = 1;
    gl::Backend backend = gl::Backend::Auto;
    stress::Plant plant = stress::Plant::None;
    std::string outPath;
    std::string plantPass;        // --plant-nan
    std::string failedScenesDir;  // --failed-scenes
    bool quiet = false;
    shards::ShardSpec shard;  // --shard: cases and seed are then this shard's part of the job's
    int jobCases = 0;
    int jobSeed = 0;
};

Result<StressOptions> parseStressOptions(const ParsedArgs& args, bool* usage) {
    *usage = true;
    if (!args.positional.empty()) return makeError("stress", "takes no positional arguments");
    auto cases = parsePositiveInt("--cases", args.get("cases", "200"));
    if (!cases.ok()) return cases.error();
    auto seed = parsePositiveInt("--seed", args.get("seed", "1"));
    if (!seed.ok()) return seed.error();
    auto backend = parseBackend(args.get("backend", "auto"));
    if (!backend.ok()) return backend.error();
    const auto plant = stress::kPlants.parse(args.get("plant-violation", "none"));
    if (!plant)
        return makeError("--plant-violation " + args.get("plant-violation", ""),
                         "expected " + stress::kPlants.list() + didYouMean(args.get("plant-violation", ""), stress::kPlants.names()));
    StressOptions options;
    options.cases = *cases;
    options.seed = *seed;
    options.backend = *backend;
    options.plant = *plant;
    options.outPath = args.get("out", "out/stress.json");
    options.plantPass = args.get("plant-nan", "");
    options.failedScenesDir = args.get("failed-scenes", "");
    options.quiet = args.flags.count("quiet") > 0;
    options.jobCases = options.cases;
    options.jobSeed = options.seed;
    if (args.has("shard")) {
        auto shard = shards::parseShardSpec(args.get("shard", ""));
        if (!shard.ok()) return shard.error();
        if (shard->count > options.cases) {
            return makeError("--shard " + shard->text(), "more shards than cases (" + std::to_string(options.cases) + ")");
        }
        options.shard = *shard;
        const shards::ShardRange range = shards::shardRange(*shard, options.cases);
        options.seed += range.first;
        options.cases = range.count;
    }
    *usage = false;
    return options;
}

// Every case in seed order, with a progress bar unless quiet.
void runCases(const StressOptions& options, const stress::CaseOptions& caseOptions, const std::string& assets,
              stress::StressRun& run, OutputFiles& outputs) {
    log::setQuiet(true);  // per-case loading messages would drown the progress bar
    std::unique_ptr<log::Progress> progress;
    if (!options.quiet) {
        log::setQuiet(false);
        progress = std::make_unique<log::Progress>("stress", static_cast<size_t>(options.cases));
        log::setQuiet(true);
    }
    for (int i = 0; i < options.cases; ++i) {
        const stress::StressCase c = stress::makeStressCase(uint64_t(options.seed) + uint64_t(i), assets);
        run.add(stress::runCase(c, caseOptions, run.counting()), options.failedScenesDir, outputs);
        if (progress) {
            log::setQuiet(false);
            progress->advance();
            log::setQuiet(true);
        }
    }
    log::setQuiet(options.quiet);
}

}  // namespace

int runStress(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"cases", "seed", "out", "backend", "plant-nan", "plant-violation", "failed-scenes", "shard"}, {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::printf("%s", kHelp), 0;
    bool usage = false;
    auto options = parseStressOptions(*args, &usage);
    if (!options.ok()) return usage ? usageError(options.error()) : failure(options.error());
    auto context = gl::createHeadlessContext({options->backend, false});
    if (!context.ok()) return failure(context.error());
    // One folder per process: shards running side by side (docs/shards.md)
    // would otherwise read each other's half-written assets.
    const std::filesystem::path assets =
        std::filesystem::temp_directory_path() / ("dermis-stress-assets-" + std::to_string(::getpid()));
    std::error_code ec;
    std::filesystem::create_directories(assets, ec);
    struct RemoveOnExit {
        std::filesystem::path path;
        ~RemoveOnExit() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    } removeAssets{assets};
    if (const Status written = stress::writeStressAssets(assets.string()); !written.ok()) return failure(written.error());
    // Compiled once for every case (most of a renderer's set-up time); the
    // test Stress.SameSeedsGiveTheSameCaseHashes checks that no case leaves
    // state in them that changes a later one.
    auto built = Programs::build();
    if (!built.ok()) return failure(built.error());
    const stress::CaseOptions caseOptions{std::make_shared<Programs>(std::move(*built)), options->plantPass, options->plant};

    const auto start = std::chrono::steady_clock::now();
    // The report and the failed cases' scenes, all or none (docs/cli.md,
    // "Outputs"): failed cases are results, so a run that ends commits them.
    // Their folder is checked before the cases run, not found unwritable after.
    OutputFiles outputs;
    if (!options->failedScenesDir.empty()) {
        if (const Status prepared = outputs.prepareDirectory(options->failedScenesDir); !prepared.ok())
            return failure(Error{"--failed-scenes " + prepared.error().where, prepared.error().what});
    }
    stress::StressRun run;
    runCases(*options, caseOptions, assets.string(), run, outputs);
    if (!options->plantPass.empty() && !run.planted()) {
        std::string names;
        for (const std::string& pass : run.passesSeen()) names += (names.empty() ? "" : ", ") + pass;
        return usageError(makeError("--plant-nan", "no case's frame runs a pass named '" + options->plantPass +
                                                       "'; the frames ran: " + names));
    }
    const std::string plantName(stress::kPlants.name(options->plant));
    const stress::InvariantTally* plantedCheck =
        options->plant == stress::Plant::None ? nullptr : &run.invariants()[stress::plantedInvariant(options->plant)];
    if (plantedCheck != nullptr && plantedCheck->checked == 0) {
        return usageError(makeError("--plant-violation", "no case ran the '" + plantName + "' check (seeds " +
                                                             std::to_string(options->seed) + " to " +
                                                             std::to_string(options->seed + uint64_t(options->cases) - 1) +
                                                             "), so the planted violation was never tested; run more cases"));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::ordered_json header = {{"cases", options->cases},       {"first_seed", options->seed},
                                     {"renderer", (*context)->renderer()}, {"plant_nan", options->plantPass},
                                     {"plant_violation", stress::kPlants.name(options->plant)}};
    if (!options->shard.whole()) {
        header["shard"] = {{"index", options->shard.index},
                           {"of", options->shard.count},
                           {"job_first_seed", options->jobSeed},
                           {"job_cases", options->jobCases}};
    }
    const nlohmann::ordered_json summary = run.summary(std::move(header), seconds);
    if (const Status written = outputs.stageText(options->outPath, summary.dump(2) + "\n"); !written.ok())
        return failure(written.error());
    if (const Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    std::printf("%s\n", run.line(options->cases, seconds, options->outPath).c_str());
    // A plant that nothing caught fails the run: it was there to show a detector works.
    if (!options->plantPass.empty() && run.failed() == 0)
        return failure(makeError("--plant-nan", "the pass '" + options->plantPass +
                                                    "' ran with its planted NaN, but no case failed: no counter or check saw it"));
    if (plantedCheck != nullptr && plantedCheck->violated == 0)
        return failure(makeError("--plant-violation", "the '" + plantName + "' check ran " +
                                                          std::to_string(plantedCheck->checked) +
                                                          " times on the planted violation and never failed"));
    return run.failed() == 0 ? 0 : 1;
}

}  // namespace dermis::cli
