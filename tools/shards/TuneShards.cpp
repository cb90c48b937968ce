#include "shards/TuneShards.h"

#include "shards/ShardNote.h"

#include "bench/QualityTune.h"

#include <algorithm>
#include <filesystem>

namespace dermis::shards {
namespace {

constexpr const char* kKind = "dermis tune distances";

}  // namespace

std::string tuneShardNotePath(const std::string& tablePath) { return tablePath + ".shard.json"; }

std::string tuneShardNoteJson(const ShardSpec& shard, const std::string& identity, const std::vector<double>& distances,
                              double margin) {
    nlohmann::ordered_json json = shardNoteJson(kKind, shard, identity);
    json["distances"] = distances;
    json["margin"] = margin;
    return json.dump(2) + "\n";
}

bool isTuneShard(const std::string& tablePath) {
    std::error_code error;
    return std::filesystem::exists(tuneShardNotePath(tablePath), error);
}

Result<MergedTune> mergeTuneShards(const std::vector<std::string>& tablePaths) {
    ShardJob job;
    MergedTune merged;
    nlohmann::ordered_json table;
    for (const std::string& path : tablePaths) {
        auto note = readShardNote(tuneShardNotePath(path), kKind, "dermis tune");
        if (!note.ok()) return note.error();
        if (Status added = job.add(*note); !added.ok()) return added.error();
        if (!note->json.contains("margin") || !note->json["margin"].is_number()) {
            return makeError(note->path, "/margin: expected a number");
        }
        // Checked as a scene would read it, but joined as JSON: the reader keeps
        // fewer digits than the file holds.
        auto text = readQualityTableText(path);
        if (!text.ok()) return text.error();
        if (auto valid = parseQualityTable(*text, path); !valid.ok()) return valid.error();
        const nlohmann::ordered_json json = nlohmann::ordered_json::parse(*text);
        if (table.is_null()) {
            table = json;
            merged.margin = note->json["margin"].get<double>();
        } else {
            // The identity covers the budget, scene and size: one job's tables agree on them.
            for (const auto& row : json["rows"]) table["rows"].push_back(row);
        }
    }
    if (Status complete = job.complete(); !complete.ok()) return complete.error();
    std::stable_sort(table["rows"].begin(), table["rows"].end(), [](const auto& a, const auto& b) {
        return a["pixels_per_mm"].template get<double>() < b["pixels_per_mm"].template get<double>();
    });
    merged.json = table.dump(2) + "\n";
    auto parsed = parseQualityTable(merged.json, "merge");
    if (!parsed.ok()) return parsed.error();
    merged.table = std::move(*parsed);
    if (Status sorted = bench::sortQualityRows(merged.table, "merge"); !sorted.ok()) return sorted.error();
    return merged;
}

}  // namespace dermis::shards
