#pragma once
// Shards of `dermis reference` (docs/shards.md): shard K of N computes the
// image rows shardRange(K/N, height) and writes the full-size image with the
// other rows 0 (FILE.exr), and beside it a note (FILE.exr.shard.json):
//   {"kind": "dermis reference rows", "shard": K, "of": N, "width": W,
//    "height": H, "first_row": R, "rows": C, "identity": "<16 hex digits>"}
// The identity is a hash of everything the pixels depend on (the scene as
// loaded, the reference's options, the content), so that shards of different
// jobs are never merged. Each pixel is computed on its own, so the merged
// image equals a single run's bit for bit.

#include "shards/ShardSpec.h"

#include "core/Image.h"
#include "core/Result.h"

#include <string>
#include <vector>

namespace dermis::shards {

struct ReferenceShardNote {
    ShardSpec shard;
    int width = 0;
    int height = 0;
    int firstRow = 0;
    int rows = 0;
    std::string identity;  // 16 hex digits
};

std::string referenceShardNotePath(const std::string& imagePath);
std::string referenceShardNoteJson(const ReferenceShardNote& note);
// The note beside `imagePath`; errors name the file and the key.
Result<ReferenceShardNote> readReferenceShardNote(const std::string& imagePath);

// The image of N shards: every shard of one job (the same identity, size and
// N, each K once), each contributing its rows. Errors name the file and the
// problem: a missing or repeated shard, another job's shard, a size that
// differs from its note.
Result<Image> mergeReferenceShards(const std::vector<std::string>& imagePaths);

}  // namespace dermis::shards
