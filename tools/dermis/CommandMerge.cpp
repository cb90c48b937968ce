// dermis merge: the shards of a batch job (--shard K/N) back into one output
// (tools/shards/, docs/shards.md).
#include "Args.h"
#include "Commands.h"

#include "core/Log.h"
#include "core/OutputFiles.h"
#include "shards/ReferenceShards.h"
#include "shards/StressShards.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace dermis::cli {
namespace {

const char* const kHelp =
    "usage: dermis merge --out FILE.exr SHARD.exr...\n"
    "       dermis merge --out FILE.json SHARD.json...\n"
    "\n"
    "Joins the N shards of one job, each made with --shard K/N, into the output one run\n"
    "without --shard writes:\n"
    "  .exr   `dermis reference` shards (each SHARD.exr with its SHARD.exr.shard.json\n"
    "         beside it): the image, bit for bit\n"
    "  .json  `dermis stress` summaries: the summary, with the same values but for the\n"
    "         times (seconds, seconds_by_stage, slowest_cases)\n"
    "Every shard of the job must be given once; shards of another job (another scene,\n"
    "size, option, seed range or shard count) are refused. See docs/shards.md for running\n"
    "the shards with GNU parallel or a Slurm job array (tools/shards.sh).\n"
    "\n"
    "options:\n"
    "  --out FILE      the merged output, .exr or .json as the shards (required); written\n"
    "                  only on success\n"
    "  --quiet         no summary\n"
    "  --help          this text\n"
    "\n"
    "Exit status: 0 on success, 1 when a shard is missing, repeated, from another job or\n"
    "unreadable, or the output cannot be written, 2 for bad command-line usage.\n";

}  // namespace

int runMerge(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"out"}, {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::printf("%s", kHelp), 0;
    log::setQuiet(args->flags.count("quiet") > 0);
    if (!args->has("out") || args->get("out", "").empty()) return usageError(makeError("merge", "--out FILE is required"));
    const std::string outPath = args->get("out", "");
    const std::string extension = std::filesystem::path(outPath).extension().string();
    if (extension != ".exr" && extension != ".json") {
        return usageError(makeError("--out " + outPath, "expected FILE.exr (reference shards) or FILE.json (stress summaries)"));
    }
    if (args->positional.empty()) return usageError(makeError("merge", "expected the shards (SHARD" + extension + "...)"));
    for (const std::string& shard : args->positional) {
        if (std::filesystem::path(shard).extension() != extension) {
            return usageError(makeError(shard, "a shard of an " + extension + " output must be " + extension + " too"));
        }
    }
    if (extension == ".json") {
        auto summary = shards::mergeStressSummaries(args->positional);
        if (!summary.ok()) return failure(summary.error());
        OutputFiles out;
        if (Status staged = out.stageText(outPath, summary->dump(2) + "\n"); !staged.ok()) return failure(staged.error());
        if (Status committed = out.commit(); !committed.ok()) return failure(committed.error());
        log::info("merged " + std::to_string(args->positional.size()) + " stress summaries into " + outPath);
        return 0;
    }
    auto merged = shards::mergeReferenceShards(args->positional);
    if (!merged.ok()) return failure(merged.error());
    OutputFiles out;
    if (Status staged = out.stageImage(outPath, *merged); !staged.ok()) return failure(staged.error());
    if (Status committed = out.commit(); !committed.ok()) return failure(committed.error());
    log::info("merged " + std::to_string(args->positional.size()) + " shards into " + outPath + " (" +
              std::to_string(merged->width) + "x" + std::to_string(merged->height) + ")");
    return 0;
}

}  // namespace dermis::cli
