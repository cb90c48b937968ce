#include "render/FrameTimings.h"

#include "core/TextFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace dermis {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle), values.end());
    if (values.size() % 2 == 1) return values[middle];
    const double upper = values[middle];
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
    return 0.5 * (lower + upper);
}

std::string describeCull(const graph::PassReport& report) {
    switch (report.reason) {
        case graph::CullReason::None: return "";
        case graph::CullReason::Predicate: return "predicate: " + report.detail;
        case graph::CullReason::MissingInput: return "input '" + report.detail + "' not produced";
        case graph::CullReason::Unused: return "nothing reads its output";
    }
    return "";
}

void FrameTimings::addPassReports(const std::vector<graph::PassReport>& reports) {
    for (const graph::PassReport& report : reports) {
        if (mRecords.find(report.name) == mRecords.end()) mOrder.push_back(report.name);
        PassRecord& record = mRecords[report.name];
        ++record.declared;
        if (report.executed) {
            ++record.executed;
        } else {
            record.lastCull = describeCull(report);
        }
    }
}

void FrameTimings::addTimings(const std::vector<gl::PassTiming>& timings) {
    for (const gl::PassTiming& t : timings) {
        mGpu[t.pass].push_back(t.gpuMs);
        mCpu[t.pass].push_back(t.cpuMs);
        mFrameGpu[t.frame] += t.gpuMs;
        mFrameCpu[t.frame] += t.cpuMs;
    }
}

std::vector<PassSummary> FrameTimings::summary() const {
    std::vector<PassSummary> out;
    for (const std::string& name : mOrder) {
        const PassRecord& record = mRecords.at(name);
        PassSummary s;
        s.name = name;
        s.executed = record.executed > 0;
        s.executedFrames = record.executed;
        s.frames = record.declared;
        s.culledBecause = record.lastCull;
        if (auto it = mGpu.find(name); it != mGpu.end()) {
            s.gpuMs = median(it->second);
            s.samples = it->second.size();
        }
        if (auto it = mCpu.find(name); it != mCpu.end()) s.cpuMs = median(it->second);
        out.push_back(std::move(s));
    }
    return out;
}

double FrameTimings::frameGpuMs() const {
    std::vector<double> values;
    for (const auto& [frame, ms] : mFrameGpu) values.push_back(ms);
    return median(values);
}

double FrameTimings::frameCpuMs() const {
    std::vector<double> values;
    for (const auto& [frame, ms] : mFrameCpu) values.push_back(ms);
    return median(values);
}

std::string FrameTimings::toJson(const RunInfo& info) const {
    nlohmann::ordered_json j;
    j["renderer"] = info.renderer;
    j["backend"] = info.backend;
    j["gl_version"] = info.glVersion;
    j["scene"] = info.scene;
    j["width"] = info.width;
    j["height"] = info.height;
    j["frames"] = info.frames;
    j["passes"] = nlohmann::ordered_json::array();
    for (const PassSummary& s : summary()) {
        nlohmann::ordered_json p;
        p["name"] = s.name;
        p["executed"] = s.executed;
        p["executed_frames"] = s.executedFrames;
        p["culled_because"] = s.culledBecause;
        p["gpu_ms"] = s.gpuMs;
        p["cpu_ms"] = s.cpuMs;
        p["samples"] = s.samples;
        j["passes"].push_back(p);
    }
    j["frame"] = {{"gpu_ms", frameGpuMs()}, {"cpu_ms", frameCpuMs()}, {"wall_ms", info.wallMsPerFrame}};
    if (!info.characters.empty()) {
        j["characters"] = nlohmann::ordered_json::array();
        for (const CharacterReport& c : info.characters) {
            j["characters"].push_back({{"name", c.name},
                                       {"visible", c.visible},
                                       {"culled_because", c.culledBecause},
                                       {"animated", c.animated},
                                       {"clip_time_s", c.clipTimeS},
                                       {"texture_space_size", c.textureSpaceSize},
                                       {"texture_space_fallback", c.textureSpaceFallback},
                                       {"lod", c.lod},
                                       {"lod_error_px", c.lodErrorPx}});
            nlohmann::ordered_json sss;  // null
            if (c.hasSss) {
                sss = sssChoiceJson(c.sssChoice);
                sss["pixels_per_mm"] = c.pixelsPerMm;
                sss["source"] = c.sssChoiceSource;
            }
            j["characters"].back()["sss"] = std::move(sss);
        }
    }
    return j.dump(2) + "\n";
}

std::string describeCharacterSss(const CharacterReport& character) {
    if (!character.hasSss) return {};
    char scale[32];
    std::snprintf(scale, sizeof scale, "%.2f px/mm", character.pixelsPerMm);
    std::string lod;
    if (character.lod > 0) {
        char text[64];
        std::snprintf(text, sizeof text, ", level of detail %d (%.2f px)", character.lod, character.lodErrorPx);
        lod = text;
    }
    return character.name + ": " + describeSssChoice(character.sssChoice) + ", " + scale + " (" +
           character.sssChoiceSource + ")" + lod;
}

std::string FrameTimings::toTable(const RunInfo& info) const {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%s (%s), %dx%d, median of %d frames\n", info.renderer.c_str(),
                  info.backend.c_str(), info.width, info.height, info.frames);
    out += line;
    std::snprintf(line, sizeof line, "%-28s %10s %10s  %s\n", "pass", "gpu ms", "cpu ms", "");
    out += line;
    for (const PassSummary& s : summary()) {
        if (s.executed && s.executedFrames < s.frames) {
            std::snprintf(line, sizeof line, "%-28s %10.3f %10.3f  ran in %zu of %zu frames, then %s\n", s.name.c_str(),
                          s.gpuMs, s.cpuMs, s.executedFrames, s.frames, s.culledBecause.c_str());
        } else if (s.executed) {
            std::snprintf(line, sizeof line, "%-28s %10.3f %10.3f\n", s.name.c_str(), s.gpuMs, s.cpuMs);
        } else {
            std::snprintf(line, sizeof line, "%-28s %10s %10s  culled: %s\n", s.name.c_str(), "-", "-",
                          s.culledBecause.c_str());
        }
        out += line;
    }
    std::snprintf(line, sizeof line, "%-28s %10.3f %10.3f\n", "frame (sum of passes)", frameGpuMs(), frameCpuMs());
    out += line;
    std::snprintf(line, sizeof line, "%-28s %10.3f\n", "frame wall clock", info.wallMsPerFrame);
    out += line;
    bool heading = false;
    for (const CharacterReport& character : info.characters) {
        const std::string choice = describeCharacterSss(character);
        if (choice.empty()) continue;
        if (!heading) out += "screen-space SSS per character (last frame):\n";
        heading = true;
        out += "  " + choice + "\n";
    }
    return out;
}

Status FrameTimings::writeJson(const std::string& path, const RunInfo& info) const {
    return writeTextFileAtomically(path, toJson(info));
}

}  // namespace dermis
