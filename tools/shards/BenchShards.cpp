#include "shards/BenchShards.h"

#include "shards/ShardNote.h"

#include "bench/BenchRowJson.h"

#include <algorithm>

namespace dermis::shards {
namespace {

constexpr const char* kKind = "dermis bench configurations";

// The summary's keys that differ between the shards of one job: "modes" is
// over each shard's rows, "reference" names each shard's directory.
nlohmann::json sharedPart(nlohmann::json summary) {
    summary.erase("modes");
    summary.erase("reference");
    return summary;
}

}  // namespace

bool isBenchShard(const std::filesystem::path& directory) {
    std::error_code error;
    return std::filesystem::exists(directory / kBenchShardNoteName, error);
}

std::string benchShardNoteJson(const ShardSpec& shard, const std::string& identity, int configurations,
                               const nlohmann::ordered_json& summary, const std::vector<bench::BenchRow>& rows,
                               const std::vector<std::string>& errorImages) {
    nlohmann::ordered_json json = shardNoteJson(kKind, shard, identity);
    json["configurations"] = configurations;
    json["summary"] = summary;
    json["rows"] = nlohmann::ordered_json::array();
    for (const bench::BenchRow& row : rows) json["rows"].push_back(bench::benchRowToJson(row));
    json["error_images"] = errorImages;
    return json.dump(1) + "\n";
}

Result<MergedBench> mergeBenchShards(const std::vector<std::filesystem::path>& directories) {
    ShardJob job;
    MergedBench merged;
    int configurations = 0;
    for (const std::filesystem::path& directory : directories) {
        auto note = readShardNote((directory / kBenchShardNoteName).string(), kKind, "dermis bench");
        if (!note.ok()) return note.error();
        if (Status added = job.add(*note); !added.ok()) return added.error();
        const nlohmann::json& json = note->json;
        const std::string& path = note->path;
        if (!json.contains("configurations") || !json["configurations"].is_number_integer() || json["configurations"].get<int>() < 1) {
            return makeError(path, "/configurations: expected a positive integer");
        }
        if (!json.contains("summary") || !json["summary"].is_object()) return makeError(path, "/summary: expected an object");
        for (const char* key : {"rows", "error_images"}) {
            if (!json.contains(key) || !json[key].is_array()) return makeError(path, std::string("/") + key + ": expected an array");
        }
        if (merged.summary.is_null()) {
            configurations = json["configurations"].get<int>();
            merged.summary = json["summary"];
        } else if (sharedPart(json["summary"]) != sharedPart(merged.summary)) {
            // The identity covers the job; what it cannot, is the machine.
            return makeError(path, "/summary: differs from " + job.first().path + " (another renderer: \"" +
                                       json["summary"].value("renderer", "") + "\" against \"" +
                                       merged.summary.value("renderer", "") + "\"?)");
        }
        const ShardStride taken = shardStride(note->shard, configurations);
        if (int(json["rows"].size()) != taken.count) {
            return makeError(path, "/rows: " + std::to_string(json["rows"].size()) + " rows, shard " + note->shard.text() + " of " +
                                       std::to_string(configurations) + " configurations measures " + std::to_string(taken.count));
        }
        for (size_t i = 0; i < json["rows"].size(); ++i) {
            auto row = bench::benchRowFromJson(json["rows"][i], path + ": /rows/" + std::to_string(i));
            if (!row.ok()) return row.error();
            if (row->id != taken.item(int(i))) {
                return makeError(path, "/rows/" + std::to_string(i) + "/id: " + std::to_string(row->id) + ", expected " +
                                           std::to_string(taken.item(int(i))));
            }
            merged.rows.push_back(std::move(*row));
        }
        for (size_t i = 0; i < json["error_images"].size(); ++i) {
            const nlohmann::json& name = json["error_images"][i];
            if (!name.is_string() || std::filesystem::path(name.get<std::string>()).has_parent_path()) {
                return makeError(path, "/error_images/" + std::to_string(i) + ": expected a file name");
            }
            merged.errorImages.emplace_back(name.get<std::string>(), directory / name.get<std::string>());
        }
    }
    if (Status complete = job.complete(); !complete.ok()) return complete.error();
    std::sort(merged.rows.begin(), merged.rows.end(), [](const bench::BenchRow& a, const bench::BenchRow& b) { return a.id < b.id; });
    return merged;
}

}  // namespace dermis::shards
