#include "shards/ShardSpec.h"

#include <cerrno>
#include <cstdlib>

namespace dermis::shards {
namespace {

bool parseCount(const std::string& text, int& value) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9) return false;
    value = std::atoi(text.c_str());
    return true;
}

}  // namespace

Result<ShardSpec> parseShardSpec(const std::string& text) {
    const size_t slash = text.find('/');
    ShardSpec shard;
    if (slash == std::string::npos || !parseCount(text.substr(0, slash), shard.index) ||
        !parseCount(text.substr(slash + 1), shard.count)) {
        return makeError("--shard " + text, "expected K/N, e.g. 1/4: the K-th of N parts, counted from 1");
    }
    if (shard.count < 1 || shard.count > kMaxShards) {
        return makeError("--shard " + text, "N must be 1 to " + std::to_string(kMaxShards));
    }
    if (shard.index < 1 || shard.index > shard.count) {
        return makeError("--shard " + text, "K must be 1 to N (" + std::to_string(shard.count) + ")");
    }
    return shard;
}

ShardRange shardRange(const ShardSpec& shard, int items) {
    const auto begin = [&](int k) { return int(int64_t(items) * int64_t(k) / int64_t(shard.count)); };
    const int first = begin(shard.index - 1);
    return {first, begin(shard.index) - first};
}

ShardStride shardStride(const ShardSpec& shard, int items) {
    const int first = shard.index - 1;
    return {first, shard.count, first < items ? (items - first + shard.count - 1) / shard.count : 0};
}

Status ShardSet::add(int index, const std::string& path) {
    if (auto [at, added] = mPaths.emplace(index, path); !added) {
        return makeError(path, "shard " + ShardSpec{index, mCount}.text() + " is also " + at->second);
    }
    return success();
}

Status ShardSet::complete() const {
    std::string missing;
    for (int k = 1; k <= mCount; ++k) {
        if (mPaths.count(k) == 0) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    }
    if (missing.empty()) return success();
    return makeError("merge", "shards missing of " + std::to_string(mCount) + ": " + missing);
}

}  // namespace dermis::shards
