#include "bench/BenchRowJson.h"

#include <cmath>
#include <limits>
#include <optional>

namespace dermis::bench {
namespace {

nlohmann::ordered_json number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0.0 ? "inf" : "-inf";
    return x;
}

// Reads members of one JSON object; the first problem is kept, with its key.
class Reader {
public:
    Reader(const nlohmann::json& json, std::string where) : mJson(json), mWhere(std::move(where)) {
        if (!json.is_object()) fail("", "expected an object");
    }
    double number(const char* key) {
        const nlohmann::json* value = member(key);
        if (!value) return 0.0;
        if (value->is_number()) return value->get<double>();
        if (value->is_string()) {
            const std::string text = value->get<std::string>();
            if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
            if (text == "inf") return std::numeric_limits<double>::infinity();
            if (text == "-inf") return -std::numeric_limits<double>::infinity();
        }
        fail(key, "expected a number, \"nan\", \"inf\" or \"-inf\"");
        return 0.0;
    }
    template <class Integer>
    Integer integer(const char* key) {
        const nlohmann::json* value = member(key);
        if (value && (value->is_number_integer() || value->is_number_unsigned())) return value->get<Integer>();
        if (value) fail(key, "expected an integer");
        return Integer{};
    }
    std::string text(const char* key) {
        const nlohmann::json* value = member(key);
        if (value && value->is_string()) return value->get<std::string>();
        if (value) fail(key, "expected a string");
        return {};
    }
    bool boolean(const char* key) {
        const nlohmann::json* value = member(key);
        if (value && value->is_boolean()) return value->get<bool>();
        if (value) fail(key, "expected true or false");
        return false;
    }
    const nlohmann::json* array(const char* key) {
        const nlohmann::json* value = member(key);
        if (value && value->is_array()) return value;
        if (value) fail(key, "expected an array");
        return nullptr;
    }
    const nlohmann::json* optionalObject(const char* key) {
        const nlohmann::json* value = member(key);
        if (!value || value->is_null()) return nullptr;
        if (value->is_object()) return value;
        fail(key, "expected an object or null");
        return nullptr;
    }
    std::string where(const std::string& key) const { return mWhere + "/" + key; }
    void adopt(const Error& error) {
        if (!mError) mError = error;
    }
    const std::optional<Error>& error() const { return mError; }

private:
    const nlohmann::json* member(const char* key) {
        if (!mJson.is_object()) return nullptr;
        const auto found = mJson.find(key);
        if (found == mJson.end()) {
            fail(key, "missing");
            return nullptr;
        }
        return &*found;
    }
    void fail(const std::string& key, const std::string& problem) {
        if (!mError) mError = makeError(key.empty() ? mWhere : where(key), problem);
    }

    const nlohmann::json& mJson;
    std::string mWhere;
    std::optional<Error> mError;
};

nlohmann::ordered_json differenceToJson(const ImageDifference& d) {
    return {{"pixels", d.pixels},         {"rmse", number(d.rmse)},         {"relative_rmse", number(d.relativeRmse)},
            {"max_abs_difference", number(d.maxAbsDifference)}, {"peak", number(d.peak)}, {"psnr_db", number(d.psnrDb)}};
}

ImageDifference differenceFromJson(Reader& r) {
    ImageDifference d;
    d.pixels = r.integer<size_t>("pixels");
    d.rmse = r.number("rmse");
    d.relativeRmse = r.number("relative_rmse");
    d.maxAbsDifference = r.number("max_abs_difference");
    d.peak = r.number("peak");
    d.psnrDb = r.number("psnr_db");
    return d;
}

}  // namespace

nlohmann::ordered_json benchRowToJson(const BenchRow& row) {
    nlohmann::ordered_json errors = nlohmann::ordered_json::object();
    for (const EnumEntry<ErrorCause>& cause : kErrorCauses) {
        for (const EnumEntry<ErrorRegion>& region : kErrorRegions) {
            const auto& figure = row.errors.at(cause.value, region.value);
            errors[std::string(cause.name)][std::string(region.name)] =
                figure ? differenceToJson(*figure) : nlohmann::ordered_json();
        }
    }
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const PassSummary& pass : row.passes) {
        passes.push_back({{"name", pass.name},
                          {"executed", pass.executed},
                          {"executed_frames", pass.executedFrames},
                          {"frames", pass.frames},
                          {"culled_because", pass.culledBecause},
                          {"gpu_ms", number(pass.gpuMs)},
                          {"cpu_ms", number(pass.cpuMs)},
                          {"gpu_p5_ms", number(pass.gpuP5Ms)},
                          {"gpu_p95_ms", number(pass.gpuP95Ms)},
                          {"cpu_p5_ms", number(pass.cpuP5Ms)},
                          {"cpu_p95_ms", number(pass.cpuP95Ms)},
                          {"samples", pass.samples}});
    }
    return {{"id", row.id},
            {"mode", row.mode},
            {"technique", row.technique},
            {"label", row.label},
            {"is_default", row.isDefault},
            {"width", row.width},
            {"height", row.height},
            {"frames", row.frames},
            {"frame_gpu_ms", number(row.frameGpuMs)},
            {"sss_gpu_ms", number(row.sssGpuMs)},
            {"wall_ms", number(row.wallMs)},
            {"relative_rmse", number(row.relativeRmse)},
            {"max_abs_difference", number(row.maxAbsDifference)},
            {"psnr_db", number(row.psnrDb)},
            {"errors", errors},
            {"overrides", row.overrides},
            {"passes", passes}};
}

Result<BenchRow> benchRowFromJson(const nlohmann::json& json, const std::string& where) {
    Reader r(json, where);
    BenchRow row;
    row.id = r.integer<int>("id");
    row.mode = r.text("mode");
    row.technique = r.text("technique");
    row.label = r.text("label");
    row.isDefault = r.boolean("is_default");
    row.width = r.integer<int>("width");
    row.height = r.integer<int>("height");
    row.frames = r.integer<int>("frames");
    row.frameGpuMs = r.number("frame_gpu_ms");
    row.sssGpuMs = r.number("sss_gpu_ms");
    row.wallMs = r.number("wall_ms");
    row.relativeRmse = r.number("relative_rmse");
    row.maxAbsDifference = r.number("max_abs_difference");
    row.psnrDb = r.number("psnr_db");
    if (const nlohmann::json* errors = r.optionalObject("errors")) {
        for (const EnumEntry<ErrorCause>& cause : kErrorCauses) {
            const std::string causeWhere = r.where("errors/" + std::string(cause.name));
            static const nlohmann::json kMissing;  // Reader keeps a reference: no temporary here
            const std::string causeName(cause.name);
            const nlohmann::json& byCause = errors->contains(causeName) ? errors->at(causeName) : kMissing;
            Reader byRegion(byCause, causeWhere);
            for (const EnumEntry<ErrorRegion>& region : kErrorRegions) {
                const std::string regionName(region.name);
                if (const nlohmann::json* figure = byRegion.optionalObject(regionName.c_str())) {
                    Reader difference(*figure, byRegion.where(regionName));
                    row.errors.table[size_t(cause.value)][size_t(region.value)] = differenceFromJson(difference);
                    if (difference.error()) r.adopt(*difference.error());
                }
            }
            if (byRegion.error()) r.adopt(*byRegion.error());
        }
    }
    if (const nlohmann::json* overrides = r.array("overrides")) {
        for (size_t i = 0; i < overrides->size(); ++i) {
            if (!(*overrides)[i].is_string()) {
                r.adopt(makeError(r.where("overrides/" + std::to_string(i)), "expected a string"));
                break;
            }
            row.overrides.push_back((*overrides)[i].get<std::string>());
        }
    }
    if (const nlohmann::json* passes = r.array("passes")) {
        for (size_t i = 0; i < passes->size(); ++i) {
            Reader p((*passes)[i], r.where("passes/" + std::to_string(i)));
            PassSummary pass;
            pass.name = p.text("name");
            pass.executed = p.boolean("executed");
            pass.executedFrames = p.integer<size_t>("executed_frames");
            pass.frames = p.integer<size_t>("frames");
            pass.culledBecause = p.text("culled_because");
            pass.gpuMs = p.number("gpu_ms");
            pass.cpuMs = p.number("cpu_ms");
            pass.gpuP5Ms = p.number("gpu_p5_ms");
            pass.gpuP95Ms = p.number("gpu_p95_ms");
            pass.cpuP5Ms = p.number("cpu_p5_ms");
            pass.cpuP95Ms = p.number("cpu_p95_ms");
            pass.samples = p.integer<size_t>("samples");
            if (p.error()) r.adopt(*p.error());
            row.passes.push_back(std::move(pass));
        }
    }
    if (r.error()) return *r.error();
    return row;
}

}  // namespace dermis::bench
