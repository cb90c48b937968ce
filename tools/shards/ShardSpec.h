#pragma once
// `--shard K/N`: run the K-th of N parts of a batch job, so that N processes
// (GNU parallel on one machine, a Slurm job array on a cluster; docs/shards.md)
// share it, and `dermis merge` puts the parts back together. Shards are
// numbered from 1, as job-array tasks usually are.

#include "core/Result.h"

#include <map>
#include <string>

namespace dermis::shards {

struct ShardSpec {
    int index = 1;  // K, 1..count
    int count = 1;  // N
    bool whole() const { return count == 1; }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// The largest N: more shards than this is a mistake, not a cluster.
constexpr int kMaxShards = 4096;

// "K/N" with 1 <= K <= N <= kMaxShards; errors name the option and the text.
Result<ShardSpec> parseShardSpec(const std::string& text);

// The part [first, first + count) of `items` things that shard K of N takes:
// consecutive, in order, sizes differing by at most one, together all of them.
struct ShardRange {
    int first = 0;
    int count = 0;
};
ShardRange shardRange(const ShardSpec& shard, int items);

// The items K-1, K-1+N, K-1+2N, ... of `items`, which shard K of N takes where
// the items differ in cost along their order (bench configurations: one
// mode's after the other's), so that each shard gets a like mix.
struct ShardStride {
    int first = 0;
    int step = 1;
    int count = 0;
    int item(int i) const { return first + i * step; }
};
ShardStride shardStride(const ShardSpec& shard, int items);

// The shards a merge was given: each K of N once, all of them.
class ShardSet {
public:
    explicit ShardSet(int count) : mCount(count) {}
    // Errors when shard `index` was already given (naming both files).
    Status add(int index, const std::string& path);
    // Errors listing the shards not given.
    Status complete() const;

private:
    int mCount;
    std::map<int, std::string> mPaths;  // by K
};

}  // namespace dermis::shards
