#include "shards/ReferenceShards.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <optional>

namespace dermis::shards {
namespace {

constexpr const char* kKind = "dermis reference rows";

}  // namespace

std::string referenceShardNotePath(const std::string& imagePath) { return imagePath + ".shard.json"; }

std::string referenceShardNoteJson(const ReferenceShardNote& note) {
    nlohmann::ordered_json json{{"kind", kKind},          {"shard", note.shard.index}, {"of", note.shard.count},
                                {"width", note.width},    {"height", note.height},     {"first_row", note.firstRow},
                                {"rows", note.rows},      {"identity", note.identity}};
    return json.dump(2) + "\n";
}

Result<ReferenceShardNote> readReferenceShardNote(const std::string& imagePath) {
    const std::string path = referenceShardNotePath(imagePath);
    std::ifstream in(path);
    if (!in) return makeError(path, "cannot be read: a reference shard has this note beside it (dermis reference --shard K/N)");
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& error) {
        return makeError(path, std::string("not JSON: ") + error.what());
    }
    if (!json.is_object() || json.value("kind", "") != kKind) return makeError(path, std::string("/kind: not \"") + kKind + "\"");
    ReferenceShardNote note;
    const std::pair<const char*, int*> integers[] = {{"shard", &note.shard.index}, {"of", &note.shard.count},
                                                     {"width", &note.width},       {"height", &note.height},
                                                     {"first_row", &note.firstRow}, {"rows", &note.rows}};
    for (const auto& [key, value] : integers) {
        if (!json.contains(key) || !json[key].is_number_integer()) return makeError(path, std::string("/") + key + ": expected an integer");
        *value = json[key].get<int>();
    }
    if (!json.contains("identity") || !json["identity"].is_string()) return makeError(path, "/identity: expected a string");
    note.identity = json["identity"].get<std::string>();
    if (note.shard.count < 1 || note.shard.index < 1 || note.shard.index > note.shard.count) {
        return makeError(path, "/shard: " + note.shard.text() + " is not K/N with 1 <= K <= N");
    }
    const ShardRange range = shardRange(note.shard, note.height);
    if (note.width < 1 || note.height < 1 || note.firstRow != range.first || note.rows != range.count) {
        return makeError(path, "/first_row, /rows: shard " + note.shard.text() + " of " + std::to_string(note.height) +
                                   " rows has rows " + std::to_string(range.first) + " to " +
                                   std::to_string(range.first + range.count - 1));
    }
    return note;
}

Result<Image> mergeReferenceShards(const std::vector<std::string>& imagePaths) {
    if (imagePaths.empty()) return makeError("merge", "no shard given");
    std::optional<ShardSet> given;
    std::string firstPath;
    ReferenceShardNote first;
    Image merged;
    for (const std::string& path : imagePaths) {
        auto note = readReferenceShardNote(path);
        if (!note.ok()) return note.error();
        if (!given) {
            given.emplace(note->shard.count);
            firstPath = path;
            first = *note;
            merged.width = note->width;
            merged.height = note->height;
            merged.colourSpace = ColourSpace::Linear;
            merged.texels.assign(size_t(note->width) * size_t(note->height), glm::vec4(0.0f));
        } else if (note->identity != first.identity || note->shard.count != first.shard.count ||
                   note->width != first.width || note->height != first.height) {
            return makeError(path, "another job's shard: " + note->shard.text() + ", " + std::to_string(note->width) + "x" +
                                       std::to_string(note->height) + ", identity " + note->identity + ", against " +
                                       first.shard.text() + ", " + std::to_string(first.width) + "x" +
                                       std::to_string(first.height) + ", identity " + first.identity + " in " + firstPath);
        }
        if (Status added = given->add(note->shard.index, path); !added.ok()) return added.error();
        int nonFinite = 0;
        auto image = loadImage(path, ColourSpace::Linear, &nonFinite);
        if (!image.ok()) return image.error();
        if (nonFinite > 0) return makeError(path, std::to_string(nonFinite) + " texels are NaN or infinite");
        if (image->width != note->width || image->height != note->height) {
            return makeError(path, "the image is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                                       ", its note says " + std::to_string(note->width) + "x" + std::to_string(note->height));
        }
        const size_t begin = size_t(note->firstRow) * size_t(note->width);
        const size_t end = begin + size_t(note->rows) * size_t(note->width);
        std::copy(image->texels.begin() + long(begin), image->texels.begin() + long(end), merged.texels.begin() + long(begin));
    }
    if (Status complete = given->complete(); !complete.ok()) return complete.error();
    return merged;
}

}  // namespace dermis::shards
