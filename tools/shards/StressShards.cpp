#include "shards/StressShards.h"

#include "shards/ShardSpec.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>

namespace dermis::shards {
namespace {

using Json = nlohmann::ordered_json;

bool startsWith(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// Adds `from` (a later shard's value) into `into` by the rules of the header.
Status mergeValue(const std::string& key, const std::string& where, Json& into, const Json& from) {
    if (into.is_object() && from.is_object()) {
        for (const auto& [name, value] : from.items()) {
            if (!into.contains(name)) {
                into[name] = value;
            } else if (Status merged = mergeValue(name, where + "/" + name, into[name], value); !merged.ok()) {
                return merged;
            }
        }
        return success();
    }
    if (key == "lit" && into.is_boolean() && from.is_boolean()) {
        into = into.get<bool>() || from.get<bool>();
        return success();
    }
    if (into.is_number() && from.is_number()) {
        if (startsWith(key, "largest")) {
            into = std::max(into.get<double>(), from.get<double>());
        } else if (into.is_number_integer() && from.is_number_integer()) {
            into = into.get<int64_t>() + from.get<int64_t>();
        } else {
            into = into.get<double>() + from.get<double>();
        }
        return success();
    }
    if (into.is_array() && from.is_array()) {
        for (const Json& item : from) into.push_back(item);
        return success();
    }
    if (into != from) return makeError(where, "differs between shards: " + into.dump() + " and " + from.dump());
    return success();
}

}  // namespace

Result<Json> mergeStressSummaries(const std::vector<std::string>& summaryPaths) {
    if (summaryPaths.empty()) return makeError("merge", "no shard given");
    struct Shard {
        std::string path;
        Json summary;
    };
    std::map<int, Shard> shards;  // by K
    std::optional<ShardSet> given;
    Json job;                      // the first shard's "shard" object
    for (const std::string& path : summaryPaths) {
        std::ifstream in(path);
        if (!in) return makeError(path, "cannot be read");
        Json summary;
        try {
            summary = Json::parse(in);
        } catch (const nlohmann::json::exception& error) {
            return makeError(path, std::string("not JSON: ") + error.what());
        }
        if (!summary.is_object() || !summary.contains("shard") || !summary["shard"].is_object()) {
            return makeError(path, "not a shard: a stress shard (dermis stress --shard K/N) has /shard, and a tune "
                                   "shard (dermis tune --shard K/N) a note beside it");
        }
        Json shard = summary["shard"];
        for (const char* key : {"index", "of", "job_first_seed", "job_cases"}) {
            if (!shard.contains(key) || !shard[key].is_number_integer()) {
                return makeError(path, std::string("/shard/") + key + ": expected an integer");
            }
        }
        const int index = shard["index"].get<int>();
        if (job.is_null()) {
            job = shard;
            given.emplace(job["of"].get<int>());
        }
        Json sameJob = shard;
        sameJob["index"] = job["index"];
        if (sameJob != job) return makeError(path, "another job's shard: " + shard.dump() + ", against " + job.dump());
        if (index < 1 || index > job["of"].get<int>()) return makeError(path, "/shard/index: " + std::to_string(index) + " is not 1 to N");
        const ShardRange range = shardRange({index, job["of"].get<int>()}, job["job_cases"].get<int>());
        if (summary.value("first_seed", -1) != job["job_first_seed"].get<int>() + range.first || summary.value("cases", -1) != range.count) {
            return makeError(path, "/first_seed, /cases: not the seeds of shard " + std::to_string(index) + "/" + job["of"].dump());
        }
        if (Status added = given->add(index, path); !added.ok()) return added.error();
        shards.emplace(index, Shard{path, std::move(summary)});
    }
    if (Status complete = given->complete(); !complete.ok()) return complete.error();
    // In seed order (K order), so that the hashes and failures come in the order one run lists them.
    Json merged;
    size_t slowestListed = 0;
    for (auto& [index, shard] : shards) {
        slowestListed = std::max(slowestListed, shard.summary.value("slowest_cases", Json::array()).size());
        shard.summary.erase("shard");
        if (merged.is_null()) {
            merged = std::move(shard.summary);
            continue;
        }
        for (const auto& [key, value] : shard.summary.items()) {
            if (key == "first_seed") continue;
            if (!merged.contains(key)) {
                merged[key] = value;
            } else if (Status status = mergeValue(key, shard.path + ": /" + key, merged[key], value); !status.ok()) {
                return status.error();
            }
        }
    }
    if (merged.contains("slowest_cases") && merged["slowest_cases"].is_array()) {
        std::vector<Json> slowest(merged["slowest_cases"].begin(), merged["slowest_cases"].end());
        std::stable_sort(slowest.begin(), slowest.end(),
                         [](const Json& a, const Json& b) { return a.value("seconds", 0.0) > b.value("seconds", 0.0); });
        slowest.resize(std::min(slowest.size(), slowestListed));
        merged["slowest_cases"] = slowest;
    }
    return merged;
}

}  // namespace dermis::shards
