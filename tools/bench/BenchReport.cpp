#include "bench/BenchReport.h"

#include "bench/ParetoFront.h"
#include "scene/SceneEnums.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>

namespace dermis::bench {
namespace {

// RFC 4180: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double value) {
    if (!std::isfinite(value)) return "nan";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string joined(const std::vector<std::string>& parts) {
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : " ") + part;
    return text;
}

nlohmann::ordered_json finite(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); }

// "total_rel_rmse" for every SSS pixel, "total_rel_rmse_silhouette" for a region.
std::string errorColumn(const EnumEntry<ErrorCause>& cause, const EnumEntry<ErrorRegion>& region) {
    std::string name = std::string(cause.name) + "_rel_rmse";
    if (region.value != ErrorRegion::All) name += "_" + std::string(region.name);
    return name;
}

nlohmann::ordered_json rowJson(const BenchRow* row) {
    if (!row) return nullptr;
    return {{"id", row->id},
            {"label", row->label},
            {"frame_gpu_ms", finite(row->frameGpuMs)},
            {"sss_gpu_ms", finite(row->sssGpuMs)},
            {"relative_rmse", finite(row->relativeRmse)},
            {"max_abs_difference", finite(row->maxAbsDifference)},
            {"psnr_db", finite(row->psnrDb)},
            {"scatter_relative_rmse", finite(row->errors.relativeRmse(ErrorCause::Scatter))},
            {"overrides", row->overrides}};
}

}  // namespace

nlohmann::ordered_json causeErrorsJson(const CauseErrors& errors) {
    nlohmann::ordered_json json = nlohmann::ordered_json::object();
    for (const EnumEntry<ErrorCause>& cause : kErrorCauses) {
        for (const EnumEntry<ErrorRegion>& region : kErrorRegions) {
            const auto& figure = errors.at(cause.value, region.value);
            json[std::string(cause.name)][std::string(region.name)] =
                figure ? nlohmann::ordered_json{{"relative_rmse", finite(figure->relativeRmse)},
                                                {"max_abs_difference", finite(figure->maxAbsDifference)},
                                                {"pixels", figure->pixels}}
                       : nlohmann::ordered_json();
        }
    }
    return json;
}

namespace {

// The cheapest row of `mode` whose error is at most `limit`.
template <class ErrorOf>
const BenchRow* cheapestUnder(const std::vector<BenchRow>& rows, const std::string& mode, double limit, ErrorOf&& errorOf) {
    const BenchRow* cheapest = nullptr;
    for (const BenchRow& row : rows) {
        if (row.mode != mode || !std::isfinite(row.frameGpuMs) || !(errorOf(row) <= limit)) continue;
        if (!cheapest || row.frameGpuMs < cheapest->frameGpuMs) cheapest = &row;
    }
    return cheapest;
}

}  // namespace

bool isSssPass(const std::string& passName) {
    // The passes every frame has whatever its SSS technique
    // (frame/FrameDeclaration.cpp). Everything else a mode declares is its
    // subsurface scattering, so a new technique's passes count without
    // being listed here.
    static const std::array<std::string_view, 8> kFramePasses = {
        "gbuffer", "ssao", "ssao blur", "lighting", "composite", "tonemap", "aov", "lean specular"};
    constexpr std::string_view kShadowPrefix = "shadow:";
    if (passName.rfind(kShadowPrefix, 0) == 0) return false;
    return std::find(kFramePasses.begin(), kFramePasses.end(), passName) == kFramePasses.end();
}

std::string paretoGroup(const BenchRow& row) {
    return row.technique.empty() ? row.mode : row.mode + " " + row.technique;
}

void markParetoFronts(std::vector<BenchRow>& rows) {
    std::vector<std::string> groups;
    for (const BenchRow& row : rows) {
        if (std::find(groups.begin(), groups.end(), paretoGroup(row)) == groups.end()) groups.push_back(paretoGroup(row));
    }
    for (const std::string& group : groups) {
        std::vector<size_t> members;
        std::vector<CostError> total, scatter;
        for (size_t i = 0; i < rows.size(); ++i) {
            if (paretoGroup(rows[i]) != group) continue;
            members.push_back(i);
            total.push_back({rows[i].frameGpuMs, rows[i].relativeRmse});
            scatter.push_back({rows[i].frameGpuMs, rows[i].errors.relativeRmse(ErrorCause::Scatter)});
        }
        const std::vector<bool> totalFront = paretoFront(total);
        const std::vector<bool> scatterFront = paretoFront(scatter);
        for (size_t k = 0; k < members.size(); ++k) {
            rows[members[k]].onParetoFront = totalFront[k];
            rows[members[k]].onScatterParetoFront = scatterFront[k];
        }
    }
}

std::string resultsCsv(const std::vector<BenchRow>& rows) {
    std::string csv =
        "id,mode,technique,label,default,pareto,pareto_scatter,width,height,frames,frame_gpu_ms,sss_gpu_ms,wall_ms,relative_rmse,"
        "max_abs_difference,psnr_db";
    for (const EnumEntry<ErrorCause>& cause : kErrorCauses) {
        for (const EnumEntry<ErrorRegion>& region : kErrorRegions) csv += "," + errorColumn(cause, region);
    }
    csv += ",overrides\n";
    for (const BenchRow& row : rows) {
        csv += std::to_string(row.id) + "," + row.mode + "," + row.technique + "," + csvField(row.label) + "," + (row.isDefault ? "1" : "0") +
               "," + (row.onParetoFront ? "1" : "0") + "," + (row.onScatterParetoFront ? "1" : "0") + "," +
               std::to_string(row.width) + "," + std::to_string(row.height) + "," + std::to_string(row.frames) + "," +
               number(row.frameGpuMs) + "," + number(row.sssGpuMs) + "," + number(row.wallMs) + "," +
               number(row.relativeRmse) + "," + number(row.maxAbsDifference) + "," + number(row.psnrDb);
        for (const EnumEntry<ErrorCause>& cause : kErrorCauses) {
            for (const EnumEntry<ErrorRegion>& region : kErrorRegions) {
                csv += "," + number(row.errors.relativeRmse(cause.value, region.value));
            }
        }
        csv += "," + csvField(joined(row.overrides)) + "\n";
    }
    return csv;
}

std::string passesCsv(const std::vector<BenchRow>& rows) {
    std::string csv = "id,mode,pass,gpu_ms\n";
    for (const BenchRow& row : rows) {
        for (const PassSummary& pass : row.passes) {
            csv += std::to_string(row.id) + "," + row.mode + "," + csvField(pass.name) + "," + number(pass.gpuMs) + "\n";
        }
    }
    return csv;
}

nlohmann::ordered_json benchSummary(const std::vector<BenchRow>& rows, double errorLimit) {
    nlohmann::ordered_json summary = nlohmann::ordered_json::object();
    for (const EnumEntry<SssMode>& entry : kSssModes) {
        const std::string mode(entry.name);
        const BenchRow* defaultRow = nullptr;
        const BenchRow* best = nullptr;
        for (const BenchRow& row : rows) {
            if (row.mode != mode || !std::isfinite(row.relativeRmse) || !std::isfinite(row.frameGpuMs)) continue;
            if (row.isDefault) defaultRow = &row;
            if (!best || row.relativeRmse < best->relativeRmse) best = &row;
        }
        if (!best) continue;
        auto total = [](const BenchRow& row) { return row.relativeRmse; };
        auto scatter = [](const BenchRow& row) { return row.errors.relativeRmse(ErrorCause::Scatter); };
        summary[mode] = {{"default", rowJson(defaultRow)},
                         {"default_errors", defaultRow ? causeErrorsJson(defaultRow->errors) : nlohmann::ordered_json()},
                         {"most_accurate", rowJson(best)},
                         {"error_limit", errorLimit},
                         {"cheapest_within_limit", rowJson(cheapestUnder(rows, mode, errorLimit, total))},
                         {"cheapest_within_limit_of_most_accurate",
                          rowJson(cheapestUnder(rows, mode, best->relativeRmse + errorLimit, total))},
                         {"cheapest_within_scatter_limit", rowJson(cheapestUnder(rows, mode, kScatterErrorLimit, scatter))}};
    }
    return summary;
}

}  // namespace dermis::bench
