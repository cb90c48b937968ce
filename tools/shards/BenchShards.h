#pragma once
// Shards of `dermis bench` (docs/shards.md): shard K of N measures the
// configurations shardStride(K/N, configurations) of the job's plan (K-1,
// K-1+N, ...: one mode's configurations cost more than the other's), in its
// output directory, which then holds the references it used, the error images
// of the defaults it measured, and its note (DIR/bench_shard.json):
//   {"kind": "dermis bench configurations", "shard": K, "of": N,
//    "identity": "...", "configurations": C,
//    "summary": {summary.json over this shard's rows},
//    "rows": [every field of each row, bench/BenchRowJson.h],
//    "error_images": ["error_ss.png", ...]}
// Every configuration is measured on its own, so the merged rows carry the
// errors one run measures, bit for bit; their times are what each shard's
// machine took (compare them only between shards run on alike machines, one
// shard per machine or the same share of one).

#include "shards/ShardSpec.h"

#include "bench/BenchReport.h"
#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace dermis::shards {

constexpr const char* kBenchShardNoteName = "bench_shard.json";

// True when `directory` holds a bench shard's note.
bool isBenchShard(const std::filesystem::path& directory);

std::string benchShardNoteJson(const ShardSpec& shard, const std::string& identity, int configurations,
                               const nlohmann::ordered_json& summary, const std::vector<bench::BenchRow>& rows,
                               const std::vector<std::string>& errorImages);

struct MergedBench {
    std::vector<bench::BenchRow> rows;  // in the plan's order; Pareto marks not set
    nlohmann::ordered_json summary;     // shard 1's, whose "modes" the caller makes again from every row
    std::vector<std::pair<std::string, std::filesystem::path>> errorImages;  // name, the shard's file
};

// The N shards of one job: each once, every configuration once. Errors name
// the file and the key.
Result<MergedBench> mergeBenchShards(const std::vector<std::filesystem::path>& directories);

}  // namespace dermis::shards
