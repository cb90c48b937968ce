#include "scene/QualityTable.h"

#include "scene/JsonReader.h"
#include "scene/Scene.h"
#include "scene/SettingsFields.h"
#include "scene/SssTechniques.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace dermis {
namespace {

using json = nlohmann::json;

constexpr size_t kMaxQualityRows = 64;

// An integer key that must satisfy `rule`, as the scene's settings read it.
void ruledInteger(JsonObject& object, const char* key, int& out, const IntegerRule& rule) {
    int value = out;
    object.integer(key, value);
    if (object.has(key) &&
        object.context().check(rule.valid(value), object.pointer(key), rule.requirement + ", got " + std::to_string(value))) {
        out = value;
    }
}

void readChoice(JsonObject& row, SssChoice& choice) {
    const json* value = row.member("choice");
    if (!row.context().check(value != nullptr, row.pointer("choice"), "is required")) return;
    std::vector<std::string> keys = {"technique"};
    for (const SssTechniqueInfo& technique : sssTechniques()) {
        for (const SssSampleSetting& setting : technique.settings) keys.push_back(setting.key);
    }
    JsonObject object(row.context(), *value, row.pointer("choice"), keys);
    object.context().check(object.has("technique"), object.pointer("technique"), "is required");
    int technique = -1;
    object.choice("technique", std::string(kSssTechniques.noun()).c_str(), kSssTechniques.names(), technique);
    if (technique >= 0) choice.technique = kSssTechniques.begin()[technique].value;
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) ruledInteger(object, setting.key, choice.*setting.choice, setting.rule());
    }
}

void readNumber(JsonObject& object, const char* key, double& out, const Range& range) {
    float value = 0.0f;
    if (!object.context().check(object.has(key), object.pointer(key), "is required")) return;
    object.number(key, value, range);
    out = value;
}

}  // namespace

size_t QualityTable::rowFor(float pixelsPerMm) const {
    for (size_t i = 0; i < rows.size(); ++i) {
        if (pixelsPerMm <= rows[i].pixelsPerMm) return i;
    }
    return rows.size();
}

SssChoice QualityTable::choiceAt(size_t row) const {
    return row < rows.size() ? rows[row].choice : SssChoice::finest();
}

Result<QualityTable> parseQualityTable(const std::string& text, const std::string& path) {
    auto document = parseJsonText(text, path);
    if (!document.ok()) return document.error();
    QualityTable table;
    table.path = path;
    JsonContext context(path);
    JsonObject root(context, *document, "", {"budget", "tuned_on", "size", "rows"});
    readNumber(root, "budget", table.budget, Range::open(0.0, 1.0));
    root.string("tuned_on", table.tunedOn);
    if (const json* size = root.member("size")) {
        const bool shape = size->is_array() && size->size() == 2 && (*size)[0].is_number_integer() &&
                           (*size)[1].is_number_integer() && (*size)[0].get<long>() > 0 && (*size)[1].get<long>() > 0;
        if (context.check(shape, root.pointer("size"), "expected [width, height] in pixels, two positive integers")) {
            table.width = (*size)[0].get<int>();
            table.height = (*size)[1].get<int>();
        }
    }
    context.check(root.has("rows"), root.pointer("rows"), "is required");
    if (const json* rows = root.array("rows", kMaxQualityRows, "rows")) {
        context.check(!rows->empty(), root.pointer("rows"), "must have at least one row");
        for (size_t i = 0; i < rows->size() && !context.failed(); ++i) {
            const std::string pointer = root.pointer("rows") + "/" + std::to_string(i);
            JsonObject row(context, (*rows)[i], pointer, {"pixels_per_mm", "choice", "loss", "sss_ms", "finest_sss_ms"});
            QualityRow out;
            double pixelsPerMm = 0.0;
            readNumber(row, "pixels_per_mm", pixelsPerMm, Range::above(0.0));
            out.pixelsPerMm = static_cast<float>(pixelsPerMm);
            readChoice(row, out.choice);
            readNumber(row, "loss", out.loss, Range::atLeast(0.0));
            readNumber(row, "sss_ms", out.sssMs, Range::atLeast(0.0));
            readNumber(row, "finest_sss_ms", out.finestSssMs, Range::atLeast(0.0));
            if (context.failed()) break;
            if (!table.rows.empty()) {
                context.check(out.pixelsPerMm > table.rows.back().pixelsPerMm, row.pointer("pixels_per_mm"),
                              "rows must be sorted by pixels_per_mm, strictly increasing: " +
                                  formatNumberForMessage(out.pixelsPerMm) + " follows " +
                                  formatNumberForMessage(table.rows.back().pixelsPerMm));
            }
            table.rows.push_back(out);
        }
    }
    if (context.failed()) return context.error();
    return table;
}

Result<std::string> readQualityTableText(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return makeError(path, "cannot open the quality table: no such file");
    std::ifstream file(path, std::ios::binary);
    if (!file) return makeError(path, "cannot open the quality table");
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (file.bad()) return makeError(path, "cannot read the quality table");
    return text;
}

Result<QualityTable> loadQualityTable(const std::string& path) {
    auto text = readQualityTableText(path);
    if (!text.ok()) return text.error();
    return parseQualityTable(*text, path);
}

std::string qualityTableJson(const QualityTable& table) {
    nlohmann::ordered_json j;
    j["budget"] = table.budget;
    j["tuned_on"] = table.tunedOn;
    j["size"] = {table.width, table.height};
    j["rows"] = nlohmann::ordered_json::array();
    for (const QualityRow& row : table.rows) {
        j["rows"].push_back({{"pixels_per_mm", row.pixelsPerMm},
                             {"choice", sssChoiceJson(row.choice)},
                             {"loss", row.loss},
                             {"sss_ms", row.sssMs},
                             {"finest_sss_ms", row.finestSssMs}});
    }
    return j.dump(2) + "\n";
}

}  // namespace dermis
