#pragma once
// What every shard of a job records about itself (docs/shards.md), so that
// `dermis merge` joins only the shards of one job, each once:
//   {"kind": "<what the job is>", "shard": K, "of": N, "identity": "<16 hex digits>", ...}
// The identity is a hash of everything the job's results depend on (the
// scene as loaded, the command's options), computed by the command.

#include "shards/ShardSpec.h"

#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace dermis::shards {

struct ShardNote {
    std::string kind;
    ShardSpec shard;
    std::string identity;
    nlohmann::json json;  // the whole note, for the job's own keys
    std::string path;     // the file it was read from
};

// The note's common keys; a job adds its own.
nlohmann::ordered_json shardNoteJson(const std::string& kind, const ShardSpec& shard, const std::string& identity);

// 16 hex digits of a 64-bit hash of `text` (the job's identity).
std::string identityOf(const std::string& text);

// Reads and checks the common keys; errors name the file and the key, and say
// which command writes such a note (`writtenBy`).
Result<ShardNote> readShardNote(const std::string& path, const std::string& kind, const std::string& writtenBy);

// The notes given to one merge: of one job (the same kind, identity and N),
// each K once, and in the end all of them.
class ShardJob {
public:
    Status add(const ShardNote& note);
    Status complete() const;
    const ShardNote& first() const { return *mFirst; }

private:
    std::optional<ShardNote> mFirst;
    std::optional<ShardSet> mGiven;
};

}  // namespace dermis::shards
