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

nlohmann::ordered_json rowJson(const BenchRow* row) {
    if (!row) return nullptr;
    auto finite = [](double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); };
    return {{"id", row->id},
            {"label", row->label},
            {"frame_gpu_ms", finite(row->frameGpuMs)},
            {"sss_gpu_ms", finite(row->sssGpuMs)},
            {"relative_rmse", finite(row->relativeRmse)},
            {"max_abs_difference", finite(row->maxAbsDifference)},
            {"psnr_db", finite(row->psnrDb)},
            {"overrides", row->overrides}};
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

void markParetoFronts(std::vector<BenchRow>& rows) {
    for (const EnumEntry<SssMode>& entry : kSssModes) {
        const std::string mode(entry.name);
        std::vector<size_t> members;
        std::vector<CostError> points;
        for (size_t i = 0; i < rows.size(); ++i) {
            if (rows[i].mode != mode) continue;
            members.push_back(i);
            points.push_back({rows[i].frameGpuMs, rows[i].relativeRmse});
        }
        const std::vector<bool> front = paretoFront(points);
        for (size_t k = 0; k < members.size(); ++k) rows[members[k]].onParetoFront = front[k];
    }
}

std::string resultsCsv(const std::vector<BenchRow>& rows) {
    std::string csv =
        "id,mode,label,default,pareto,width,height,frames,frame_gpu_ms,sss_gpu_ms,wall_ms,relative_rmse,"
        "max_abs_difference,psnr_db,overrides\n";
    for (const BenchRow& row : rows) {
        csv += std::to_string(row.id) + "," + row.mode + "," + csvField(row.label) + "," + (row.isDefault ? "1" : "0") +
               "," + (row.onParetoFront ? "1" : "0") + "," + std::to_string(row.width) + "," +
               std::to_string(row.height) + "," + std::to_string(row.frames) + "," + number(row.frameGpuMs) + "," +
               number(row.sssGpuMs) + "," + number(row.wallMs) + "," + number(row.relativeRmse) + "," +
               number(row.maxAbsDifference) + "," + number(row.psnrDb) + "," + csvField(joined(row.overrides)) + "\n";
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
        auto cheapestUnder = [&](double limit) {
            const BenchRow* cheapest = nullptr;
            for (const BenchRow& row : rows) {
                if (row.mode != mode || !std::isfinite(row.frameGpuMs) || !(row.relativeRmse <= limit)) continue;
                if (!cheapest || row.frameGpuMs < cheapest->frameGpuMs) cheapest = &row;
            }
            return cheapest;
        };
        summary[mode] = {{"default", rowJson(defaultRow)},
                         {"most_accurate", rowJson(best)},
                         {"error_limit", errorLimit},
                         {"cheapest_within_limit", rowJson(cheapestUnder(errorLimit))},
                         {"cheapest_within_limit_of_most_accurate", rowJson(cheapestUnder(best->relativeRmse + errorLimit))}};
    }
    return summary;
}

}  // namespace dermis::bench
