#pragma once
// Shards of `dermis tune` (docs/shards.md): shard K of N tunes the distance
// factors shardRange(K/N, distances) of the job and writes their rows as a
// quality table (FILE.json, loadable on its own) and beside it a note
// (FILE.json.shard.json):
//   {"kind": "dermis tune distances", "shard": K, "of": N, "identity": "...",
//    "distances": [the job's factors], "margin": M}
// Each distance is tuned on its own, so the merged table has the rows one run
// writes: the same scales and losses; a row's choice can differ only where
// two candidates' timings are within the tie (bench/QualityTune.h), as it can
// between two single runs.

#include "shards/ShardSpec.h"

#include "core/Result.h"
#include "scene/QualityTable.h"

#include <string>
#include <vector>

namespace dermis::shards {

std::string tuneShardNotePath(const std::string& tablePath);
std::string tuneShardNoteJson(const ShardSpec& shard, const std::string& identity, const std::vector<double>& distances,
                              double margin);
// True when `tablePath` has a tune shard's note beside it.
bool isTuneShard(const std::string& tablePath);

struct MergedTune {
    std::string json;  // the table's file: the shards' rows with every digit they hold
    QualityTable table;
    double margin = 0.0;
};

// The table of N shards of one job, rows sorted by scale. Errors name the file
// and the problem: a missing, repeated or foreign shard, an unreadable table.
Result<MergedTune> mergeTuneShards(const std::vector<std::string>& tablePaths);

}  // namespace dermis::shards
