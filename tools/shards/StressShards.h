#pragma once
// Shards of `dermis stress` (docs/shards.md): shard K of N runs the cases
// shardRange(K/N, cases) of the job's seeds, and its summary carries
//   "shard": {"index": K, "of": N, "job_first_seed": S, "job_cases": C}
// beside the usual keys. mergeStressSummaries adds N such summaries up into
// the summary one run of the job writes: the same keys and, but for the times
// ("seconds", "seconds_by_stage", "slowest_cases"), the same values.
//   numbers: summed, except "largest_*" (the largest) and "first_seed" (the job's);
//   "format", "renderer", "plant_*": equal in every shard, or an error;
//   "lit": true when true in any shard;
//   "hashes", "failures": concatenated in seed order;
//   "slowest_cases": the slowest of all, as many as one summary lists.

#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis::shards {

// Errors name the file and the key: a missing or repeated shard, another job's.
Result<nlohmann::ordered_json> mergeStressSummaries(const std::vector<std::string>& summaryPaths);

}  // namespace dermis::shards
