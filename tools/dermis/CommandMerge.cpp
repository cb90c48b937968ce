// dermis merge: the shards of a batch job (--shard K/N) back into one output
// (tools/shards/, docs/shards.md).
#include "Args.h"
#include "Commands.h"

#include "core/Log.h"
#include "core/OutputFiles.h"
#include "shards/ReferenceShards.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace dermis::cli {
namespace {

const char* const kHelp =
    "usage: dermis merge --out FILE.exr SHARD.exr...\n"
    "\n"
    "Joins the N shards of one `dermis reference --shard K/N` job (each SHARD.exr with its\n"
    "SHARD.exr.shard.json beside it) into FILE.exr, the image one run without --shard\n"
    "writes, bit for bit. Every shard of the job must be given once; shards of another\n"
    "job (another scene, size, option or shard count) are refused. See docs/shards.md for\n"
    "running the shards with GNU parallel or a Slurm job array (tools/shards.sh).\n"
    "\n"
    "options:\n"
    "  --out FILE.exr  the merged image (required); written only on success\n"
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
    if (!args->has("out") || args->get("out", "").empty()) return usageError(makeError("merge", "--out FILE.exr is required"));
    const std::string outPath = args->get("out", "");
    if (std::filesystem::path(outPath).extension() != ".exr") {
        return usageError(makeError("--out " + outPath, "the merged reference is linear float: the file must end in .exr"));
    }
    if (args->positional.empty()) return usageError(makeError("merge", "expected the shards' images (SHARD.exr...)"));
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
