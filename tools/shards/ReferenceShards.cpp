#include "shards/ReferenceShards.h"

#include "shards/ShardNote.h"

#include <nlohmann/json.hpp>

namespace dermis::shards {
namespace {

constexpr const char* kKind = "dermis reference rows";

}  // namespace

std::string referenceShardNotePath(const std::string& imagePath) { return imagePath + ".shard.json"; }

std::string referenceShardNoteJson(const ReferenceShardNote& note) {
    nlohmann::ordered_json json = shardNoteJson(kKind, note.shard, note.identity);
    json["width"] = note.width;
    json["height"] = note.height;
    json["first_row"] = note.firstRow;
    json["rows"] = note.rows;
    return json.dump(2) + "\n";
}

namespace {

Result<std::pair<ShardNote, ReferenceShardNote>> readNotes(const std::string& imagePath) {
    auto common = readShardNote(referenceShardNotePath(imagePath), kKind, "dermis reference");
    if (!common.ok()) return common.error();
    const std::string& path = common->path;
    ReferenceShardNote note;
    note.shard = common->shard;
    note.identity = common->identity;
    const std::pair<const char*, int*> integers[] = {{"width", &note.width}, {"height", &note.height},
                                                     {"first_row", &note.firstRow}, {"rows", &note.rows}};
    for (const auto& [key, value] : integers) {
        if (!common->json.contains(key) || !common->json[key].is_number_integer()) {
            return makeError(path, std::string("/") + key + ": expected an integer");
        }
        *value = common->json[key].get<int>();
    }
    const ShardRange range = shardRange(note.shard, note.height);
    if (note.width < 1 || note.height < 1 || note.firstRow != range.first || note.rows != range.count) {
        return makeError(path, "/first_row, /rows: shard " + note.shard.text() + " of " + std::to_string(note.height) +
                                   " rows has rows " + std::to_string(range.first) + " to " +
                                   std::to_string(range.first + range.count - 1));
    }
    return std::make_pair(std::move(*common), note);
}

}  // namespace

Result<ReferenceShardNote> readReferenceShardNote(const std::string& imagePath) {
    auto notes = readNotes(imagePath);
    if (!notes.ok()) return notes.error();
    return notes->second;
}

Result<Image> mergeReferenceShards(const std::vector<std::string>& imagePaths) {
    if (imagePaths.empty()) return makeError("merge", "no shard given");
    ShardJob job;
    Image merged;
    for (const std::string& path : imagePaths) {
        auto notes = readNotes(path);
        if (!notes.ok()) return notes.error();
        // The identity holds the size: shards of one job have one size.
        if (Status added = job.add(notes->first); !added.ok()) return added.error();
        const ReferenceShardNote& note = notes->second;
        if (merged.texels.empty()) {
            merged.width = note.width;
            merged.height = note.height;
            merged.colourSpace = ColourSpace::Linear;
            merged.texels.assign(size_t(note.width) * size_t(note.height), glm::vec4(0.0f));
        }
        int nonFinite = 0;
        auto image = loadImage(path, ColourSpace::Linear, &nonFinite);
        if (!image.ok()) return image.error();
        if (nonFinite > 0) return makeError(path, std::to_string(nonFinite) + " texels are NaN or infinite");
        if (image->width != note.width || image->height != note.height) {
            return makeError(path, "the image is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                                       ", its note says " + std::to_string(note.width) + "x" + std::to_string(note.height));
        }
        merged.attributes = image->attributes;  // what it is a reference of: one job, one scene (the identity)
        const size_t begin = size_t(note.firstRow) * size_t(note.width);
        const size_t end = begin + size_t(note.rows) * size_t(note.width);
        std::copy(image->texels.begin() + long(begin), image->texels.begin() + long(end), merged.texels.begin() + long(begin));
    }
    if (Status complete = job.complete(); !complete.ok()) return complete.error();
    return merged;
}

}  // namespace dermis::shards
