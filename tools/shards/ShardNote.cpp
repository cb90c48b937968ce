#include "shards/ShardNote.h"

#include "core/ContentHash.h"

#include <fstream>

namespace dermis::shards {

nlohmann::ordered_json shardNoteJson(const std::string& kind, const ShardSpec& shard, const std::string& identity) {
    return {{"kind", kind}, {"shard", shard.index}, {"of", shard.count}, {"identity", identity}};
}

std::string identityOf(const std::string& text) {
    return hex16(fnv1a(text.data(), text.size()));
}

Result<ShardNote> readShardNote(const std::string& path, const std::string& kind, const std::string& writtenBy) {
    std::ifstream in(path);
    if (!in) return makeError(path, "cannot be read: a shard of this job has this note (" + writtenBy + " --shard K/N)");
    ShardNote note;
    note.path = path;
    try {
        note.json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& error) {
        return makeError(path, std::string("not JSON: ") + error.what());
    }
    if (!note.json.is_object() || note.json.value("kind", "") != kind) {
        return makeError(path, "/kind: not \"" + kind + "\" (" + writtenBy + " --shard K/N writes it)");
    }
    note.kind = kind;
    for (const auto& [key, value] : {std::pair<const char*, int*>{"shard", &note.shard.index}, {"of", &note.shard.count}}) {
        if (!note.json.contains(key) || !note.json[key].is_number_integer()) {
            return makeError(path, std::string("/") + key + ": expected an integer");
        }
        *value = note.json[key].get<int>();
    }
    if (note.shard.count < 1 || note.shard.count > kMaxShards || note.shard.index < 1 || note.shard.index > note.shard.count) {
        return makeError(path, "/shard: " + note.shard.text() + " is not K/N with 1 <= K <= N <= " + std::to_string(kMaxShards));
    }
    if (!note.json.contains("identity") || !note.json["identity"].is_string()) return makeError(path, "/identity: expected a string");
    note.identity = note.json["identity"].get<std::string>();
    return note;
}

Status ShardJob::add(const ShardNote& note) {
    if (!mFirst) {
        mFirst = note;
        mGiven.emplace(note.shard.count);
    } else if (note.kind != mFirst->kind || note.identity != mFirst->identity || note.shard.count != mFirst->shard.count) {
        return makeError(note.path, "another job's shard: " + note.shard.text() + ", identity " + note.identity + ", against " +
                                        mFirst->shard.text() + ", identity " + mFirst->identity + " in " + mFirst->path);
    }
    return mGiven->add(note.shard.index, note.path);
}

Status ShardJob::complete() const {
    if (!mGiven) return makeError("merge", "no shard given");
    return mGiven->complete();
}

}  // namespace dermis::shards
