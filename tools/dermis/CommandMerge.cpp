// dermis merge: the shards of a batch job (--shard K/N) back into one output
// (tools/shards/, docs/shards.md).
#include "Args.h"
#include "BenchFiles.h"
#include "Commands.h"
#include "QualityTableFiles.h"

#include "core/Log.h"
#include "core/OutputFiles.h"
#include "measure/BenchSweep.h"
#include "shards/BenchShards.h"
#include "shards/ReferenceShards.h"
#include "shards/StressShards.h"
#include "shards/TuneShards.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace dermis::cli {
namespace {

const char* const kHelp =
    "usage: dermis merge --out FILE.exr SHARD.exr...\n"
    "       dermis merge --out FILE.json SHARD.json...\n"
    "       dermis merge --out DIR SHARD_DIR...\n"
    "\n"
    "Joins the N shards of one job, each made with --shard K/N, into the output one run\n"
    "without --shard writes:\n"
    "  .exr   `dermis reference` shards (each SHARD.exr with its SHARD.exr.shard.json\n"
    "         beside it): the image, bit for bit\n"
    "  .json  `dermis tune` tables (each SHARD.json with its SHARD.json.shard.json beside\n"
    "         it): the quality table and its .md, the rows of every shard's distances\n"
    "         `dermis stress` summaries: the summary, with the same values but for the\n"
    "         times (seconds, seconds_by_stage, slowest_cases)\n"
    "  DIR    `dermis bench` directories (each with its bench_shard.json): results.csv,\n"
    "         passes.csv, summary.json, the error images and the plots; every error as\n"
    "         one run measures it, the times as each shard's machine took them\n"
    "Every shard of the job must be given once; shards of another job (another scene,\n"
    "size, option, seed range or shard count) are refused. See docs/shards.md for running\n"
    "the shards with GNU parallel or a Slurm job array (tools/shards.sh).\n"
    "\n"
    "options:\n"
    "  --out FILE|DIR  the merged output, .exr, .json or a directory as the shards\n"
    "                  (required); written only on success\n"
    "  --no-plots      bench directories: no PNG plots and no errors.md (no Python needed)\n"
    "  --quiet         no summary (warnings stay)\n"
    "  --help          this text\n"
    "\n"
    "Exit status: 0 on success, 1 when a shard is missing, repeated, from another job or\n"
    "unreadable, or the output cannot be written, 2 for bad command-line usage.\n";

// Bench shard directories into outDir, as one `dermis bench` run writes it.
int mergeBench(const std::string& outDir, const ParsedArgs& args) {
    namespace fs = std::filesystem;
    std::vector<fs::path> directories;
    for (const std::string& shard : args.positional) {
        std::error_code error;
        if (!fs::is_directory(shard, error)) return usageError(makeError(shard, "a shard of a bench job is a directory"));
        directories.emplace_back(shard);
    }
    auto merged = shards::mergeBenchShards(directories);
    if (!merged.ok()) return failure(merged.error());
    bench::markParetoFronts(merged->rows);
    merged->summary["modes"] = bench::benchSummary(merged->rows, measure::kBenchErrorLimit);
    OutputFiles out;  // every file, or none (docs/cli.md, "Outputs")
    if (Status prepared = out.prepareDirectory(outDir); !prepared.ok()) return failure(prepared.error());
    for (const auto& [name, source] : merged->errorImages) {
        // A copy beside the target, moved into place at the commit: the shards keep theirs.
        const fs::path copy = fs::path(outDir) / (".merge.dermis-" + name);
        std::error_code error;
        fs::copy_file(source, copy, fs::copy_options::overwrite_existing, error);
        if (error) return failure(makeError(source.string(), "cannot be copied into " + outDir + ": " + error.message()));
        if (Status staged = out.stageFile((fs::path(outDir) / name).string(), copy); !staged.ok()) return failure(staged.error());
    }
    if (Status staged = stageBenchTables(outDir, merged->rows, merged->summary, !args.flags.count("no-plots"), out); !staged.ok())
        return failure(staged.error());
    if (Status committed = out.commit(); !committed.ok()) return failure(committed.error());
    printBenchDefaults(merged->summary);
    log::info("merged " + std::to_string(directories.size()) + " bench shards (" + std::to_string(merged->rows.size()) +
              " configurations) into " + outDir);
    return 0;
}

}  // namespace

int runMerge(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"out"}, {"no-plots", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::printf("%s", kHelp), 0;
    log::setQuiet(args->flags.count("quiet") > 0);
    if (!args->has("out") || args->get("out", "").empty()) return usageError(makeError("merge", "--out FILE is required"));
    const std::string outPath = args->get("out", "");
    if (args->positional.empty()) return usageError(makeError("merge", "expected the shards"));
    for (const std::string& shard : args->positional) {
        std::error_code missing;
        if (!std::filesystem::exists(shard, missing)) return failure(makeError(shard, "no such file or directory"));
        // The merge would replace one of its own shards (and leave that shard's note beside it).
        std::error_code ignored;
        if (std::filesystem::equivalent(shard, outPath, ignored))
            return usageError(makeError("--out " + outPath, "is one of the shards; give the merged output a path of its own"));
    }
    std::error_code error;
    const std::string extension = std::filesystem::path(outPath).extension().string();
    if (std::filesystem::is_directory(args->positional[0], error)) {
        if (extension == ".exr" || extension == ".json") {
            return usageError(makeError("--out " + outPath, "bench shard directories merge into a directory, not a " +
                                                            extension + " file"));
        }
        return mergeBench(outPath, *args);
    }
    if (extension != ".exr" && extension != ".json") {
        return usageError(makeError("--out " + outPath, "expected FILE.exr (reference shards), FILE.json (tune tables or stress "
                                                        "summaries) or a directory (bench shard directories)"));
    }
    for (const std::string& shard : args->positional) {
        if (std::filesystem::path(shard).extension() != extension) {
            return usageError(makeError(shard, "a shard of an " + extension + " output must be " + extension + " too"));
        }
    }
    if (extension == ".json" && shards::isTuneShard(args->positional[0])) {
        auto merged = shards::mergeTuneShards(args->positional);
        if (!merged.ok()) return failure(merged.error());
        OutputFiles out;
        if (Status staged = stageQualityTable(merged->json, merged->table, merged->margin, outPath, out); !staged.ok()) return failure(staged.error());
        if (Status committed = out.commit(); !committed.ok()) return failure(committed.error());
        log::info("merged " + std::to_string(args->positional.size()) + " tune shards into " + outPath + " and " +
                  markdownPath(outPath));
        return 0;
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
