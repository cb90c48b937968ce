#include "render/FrameTimings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
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

namespace {

double percentileOfSorted(const std::vector<double>& values, double p) {
    if (values.empty()) return 0.0;
    const double position = std::clamp(p, 0.0, 100.0) / 100.0 * double(values.size() - 1);
    const size_t below = static_cast<size_t>(std::floor(position));
    const size_t above = std::min(below + 1, values.size() - 1);
    return values[below] + (position - double(below)) * (values[above] - values[below]);
}

}  // namespace

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    return percentileOfSorted(values, p);
}

Distribution distributionOf(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    // As median(): the middle value, or the mean of the two middle ones.
    const double centre = values.empty()         ? 0.0
                          : values.size() % 2 == 1 ? values[middle]
                                                   : 0.5 * (values[middle - 1] + values[middle]);
    return {centre, percentileOfSorted(values, 5.0), percentileOfSorted(values, 95.0)};
}

double FrameRecord::gpuMs() const {
    double sum = 0.0;
    for (const gl::PassTiming& pass : passes) sum += pass.gpuMs;
    return sum;
}

double FrameRecord::cpuMs() const {
    double sum = 0.0;
    for (const gl::PassTiming& pass : passes) sum += pass.cpuMs;
    return sum;
}

FrameRecord* FrameTimings::record(uint64_t frame) {
    const auto found = mFrameIndex.find(frame);
    return found == mFrameIndex.end() ? nullptr : &mFrames[found->second];
}

FrameRecord& FrameTimings::recordFor(uint64_t frame) {
    if (FrameRecord* existing = record(frame)) return *existing;
    mFrameIndex[frame] = mFrames.size();
    FrameRecord added;
    added.frame = frame;
    added.warmUp = mFrames.size() < mWarmUpFrames;
    mFrames.push_back(std::move(added));
    return mFrames.back();
}

void FrameTimings::addPassReports(uint64_t frame, const std::vector<graph::PassReport>& reports) {
    FrameRecord* existing = &recordFor(frame);
    for (const graph::PassReport& report : reports) {
        if (!report.executed) existing->culled.emplace_back(report.name, describeCull(report));
        if (existing->warmUp) continue;
        if (mRecords.find(report.name) == mRecords.end()) mOrder.push_back(report.name);
        PassRecord& pass = mRecords[report.name];
        ++pass.declared;
        if (report.executed) {
            ++pass.executed;
        } else {
            pass.lastCull = describeCull(report);
        }
    }
}

void FrameTimings::addTimings(const std::vector<gl::PassTiming>& timings) {
    // A frame's timers arrive a few frames after it: after a reset (the viewer
    // resets every frame) its report is gone, and its timers make a record of their own.
    for (const gl::PassTiming& t : timings) recordFor(t.frame).passes.push_back(t);
}

std::vector<PassSummary> FrameTimings::summary() const {
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> samples;  // gpu, cpu
    for (const FrameRecord& frame : mFrames) {
        if (frame.warmUp) continue;
        for (const gl::PassTiming& pass : frame.passes) {
            samples[pass.pass].first.push_back(pass.gpuMs);
            samples[pass.pass].second.push_back(pass.cpuMs);
        }
    }
    std::vector<PassSummary> out;
    for (const std::string& name : mOrder) {
        const PassRecord& record = mRecords.at(name);
        PassSummary s;
        s.name = name;
        s.executed = record.executed > 0;
        s.executedFrames = record.executed;
        s.frames = record.declared;
        s.culledBecause = record.lastCull;
        if (auto it = samples.find(name); it != samples.end()) {
            const auto& [gpu, cpu] = it->second;
            const Distribution gpuMs = distributionOf(gpu);
            const Distribution cpuMs = distributionOf(cpu);
            s.gpuMs = gpuMs.median;
            s.gpuP5Ms = gpuMs.p5;
            s.gpuP95Ms = gpuMs.p95;
            s.cpuMs = cpuMs.median;
            s.cpuP5Ms = cpuMs.p5;
            s.cpuP95Ms = cpuMs.p95;
            s.samples = gpu.size();
        }
        out.push_back(std::move(s));
    }
    return out;
}

Distribution FrameTimings::frameDistribution(double (FrameRecord::*sum)() const) const {
    std::vector<double> values;
    for (const FrameRecord& frame : mFrames) {
        if (!frame.warmUp && !frame.passes.empty()) values.push_back((frame.*sum)());
    }
    return distributionOf(std::move(values));
}

double FrameTimings::frameGpuMs() const { return frameDistribution(&FrameRecord::gpuMs).median; }

double FrameTimings::frameCpuMs() const { return frameDistribution(&FrameRecord::cpuMs).median; }

namespace {

nlohmann::ordered_json finiteOrNull(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); }


}  // namespace

std::string FrameTimings::toJson(const RunInfo& info) const {
    nlohmann::ordered_json j;
    j["renderer"] = info.renderer;
    j["backend"] = info.backend;
    j["gl_version"] = info.glVersion;
    j["scene"] = info.scene;
    j["width"] = info.width;
    j["height"] = info.height;
    j["frames"] = info.frames;
    j["warm_up_frames"] = mWarmUpFrames;
    j["passes"] = nlohmann::ordered_json::array();
    for (const PassSummary& s : summary()) {
        nlohmann::ordered_json p;
        p["name"] = s.name;
        p["executed"] = s.executed;
        p["executed_frames"] = s.executedFrames;
        p["culled_because"] = s.culledBecause;
        p["gpu_ms"] = s.gpuMs;
        p["gpu_p5_ms"] = s.gpuP5Ms;
        p["gpu_p95_ms"] = s.gpuP95Ms;
        p["gpu_spread"] = Distribution{s.gpuMs, s.gpuP5Ms, s.gpuP95Ms}.spread();
        p["cpu_ms"] = s.cpuMs;
        p["cpu_p5_ms"] = s.cpuP5Ms;
        p["cpu_p95_ms"] = s.cpuP95Ms;
        p["samples"] = s.samples;
        j["passes"].push_back(p);
    }
    const Distribution frameGpu = frameDistribution(&FrameRecord::gpuMs);
    j["frame"] = {{"gpu_ms", frameGpu.median},
                  {"gpu_p5_ms", frameGpu.p5},
                  {"gpu_p95_ms", frameGpu.p95},
                  {"gpu_spread", frameGpu.spread()},
                  {"cpu_ms", frameCpuMs()},
                  {"wall_ms", info.wallMsPerFrame}};
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
    j["per_frame"] = nlohmann::ordered_json::array();
    for (const FrameRecord& frame : mFrames) {
        nlohmann::ordered_json f{{"frame", frame.frame}, {"warm_up", frame.warmUp}, {"gpu_ms", frame.gpuMs()},
                                 {"cpu_ms", frame.cpuMs()}, {"passes", nlohmann::ordered_json::array()},
                                 {"culled", nlohmann::ordered_json::array()}};
        for (const gl::PassTiming& pass : frame.passes) {
            f["passes"].push_back({{"name", pass.pass},
                                   {"gpu_ms", pass.gpuMs},
                                   {"cpu_ms", pass.cpuMs},
                                   {"gpu_begin_ms", finiteOrNull(pass.gpuBeginMs)},
                                   {"cpu_begin_ms", pass.cpuBeginMs}});
        }
        for (const auto& [name, because] : frame.culled) f["culled"].push_back({{"name", name}, {"because", because}});
        j["per_frame"].push_back(std::move(f));
    }
    return j.dump(2) + "\n";
}

std::string FrameTimings::toCsv() const {
    std::string out = "frame,warm_up,pass,gpu_ms,cpu_ms,gpu_begin_ms,cpu_begin_ms\n";
    char line[512];
    for (const FrameRecord& frame : mFrames) {
        for (const gl::PassTiming& pass : frame.passes) {
            // Pass names hold no comma or quote (graph passes are named in code).
            std::snprintf(line, sizeof line, "%llu,%d,%s,%.9g,%.9g,%.12g,%.12g\n", static_cast<unsigned long long>(frame.frame),
                          frame.warmUp ? 1 : 0, pass.pass.c_str(), pass.gpuMs, pass.cpuMs, pass.gpuBeginMs, pass.cpuBeginMs);
            out += line;
        }
    }
    return out;
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
    const std::string warmUp = mWarmUpFrames > 0 ? " after " + std::to_string(mWarmUpFrames) + " warm-up" : "";
    std::snprintf(line, sizeof line, "%s (%s), %dx%d, median and 5th-95th percentile of %d frames%s\n", info.renderer.c_str(),
                  info.backend.c_str(), info.width, info.height, info.frames - int(mWarmUpFrames), warmUp.c_str());
    out += line;
    std::snprintf(line, sizeof line, "%-28s %10s %19s %10s  %s\n", "pass", "gpu ms", "gpu p5-p95", "cpu ms", "");
    out += line;
    for (const PassSummary& s : summary()) {
        char range[64];
        std::snprintf(range, sizeof range, "%8.3f-%-8.3f", s.gpuP5Ms, s.gpuP95Ms);
        if (s.executed && s.executedFrames < s.frames) {
            std::snprintf(line, sizeof line, "%-28s %10.3f %19s %10.3f  ran in %zu of %zu frames, then %s\n", s.name.c_str(),
                          s.gpuMs, range, s.cpuMs, s.executedFrames, s.frames, s.culledBecause.c_str());
        } else if (s.executed) {
            std::snprintf(line, sizeof line, "%-28s %10.3f %19s %10.3f\n", s.name.c_str(), s.gpuMs, range, s.cpuMs);
        } else {
            std::snprintf(line, sizeof line, "%-28s %10s %19s %10s  culled: %s\n", s.name.c_str(), "-", "", "-",
                          s.culledBecause.c_str());
        }
        out += line;
    }
    const Distribution frameGpu = frameDistribution(&FrameRecord::gpuMs);
    char frameRange[64];
    std::snprintf(frameRange, sizeof frameRange, "%8.3f-%-8.3f", frameGpu.p5, frameGpu.p95);
    std::snprintf(line, sizeof line, "%-28s %10.3f %19s %10.3f\n", "frame (sum of passes)", frameGpu.median, frameRange,
                  frameCpuMs());
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

}  // namespace dermis
