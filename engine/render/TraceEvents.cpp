#include "render/TraceEvents.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

constexpr int kProcess = 1;
constexpr int kCpuThread = 1;
constexpr int kGpuThread = 2;

nlohmann::ordered_json metadata(const char* what, int thread, const std::string& name) {
    nlohmann::ordered_json event{{"name", what}, {"ph", "M"}, {"pid", kProcess}};
    if (thread != 0) event["tid"] = thread;
    event["args"] = {{"name", name}};
    return event;
}

nlohmann::ordered_json slice(const std::string& name, const char* category, int thread, double beginUs, double durationUs,
                             nlohmann::ordered_json args) {
    return {{"name", name}, {"cat", category}, {"ph", "X"},  {"pid", kProcess},
            {"tid", thread}, {"ts", beginUs},   {"dur", durationUs}, {"args", std::move(args)}};
}

}  // namespace

std::string traceEventsJson(const FrameTimings& timings, const RunInfo& info) {
    nlohmann::ordered_json events = nlohmann::ordered_json::array();
    events.push_back(metadata("process_name", 0, "dermis " + info.scene));
    events.push_back(metadata("thread_name", kCpuThread, "CPU (recording the passes)"));
    events.push_back(metadata("thread_name", kGpuThread, "GPU (" + info.renderer + ")"));
    double gpuEndUs = -INFINITY;  // where the GPU thread's last slice ended
    for (const FrameRecord& frame : timings.frames()) {
        if (frame.passes.empty()) continue;
        const char* category = frame.warmUp ? "pass,warm_up" : "pass";
        const std::string frameName = "frame " + std::to_string(frame.frame);
        const nlohmann::ordered_json frameArgs{{"frame", frame.frame}, {"warm_up", frame.warmUp}};
        double cpuBegin = INFINITY, cpuEnd = -INFINITY;
        for (const gl::PassTiming& pass : frame.passes) {
            cpuBegin = std::min(cpuBegin, pass.cpuBeginMs * 1e3);
            cpuEnd = std::max(cpuEnd, (pass.cpuBeginMs + pass.cpuMs) * 1e3);
        }
        events.push_back(slice(frameName, "frame", kCpuThread, cpuBegin, cpuEnd - cpuBegin, frameArgs));
        for (const auto& [name, because] : frame.culled) {
            events.push_back({{"name", "culled: " + name},
                              {"cat", "cull"},
                              {"ph", "i"},
                              {"s", "t"},
                              {"pid", kProcess},
                              {"tid", kCpuThread},
                              {"ts", cpuBegin},
                              {"args", {{"frame", frame.frame}, {"pass", name}, {"because", because}}}});
        }
        for (const gl::PassTiming& pass : frame.passes) {
            events.push_back(slice(pass.pass, category, kCpuThread, pass.cpuBeginMs * 1e3, pass.cpuMs * 1e3, frameArgs));
        }
        if (!std::isfinite(frame.passes.front().gpuBeginMs)) continue;  // no timestamps: no GPU thread
        std::vector<nlohmann::ordered_json> gpuSlices;
        double gpuBegin = INFINITY;
        for (const gl::PassTiming& pass : frame.passes) {
            const double stampedUs = pass.gpuBeginMs * 1e3;
            const double beginUs = std::max(stampedUs, gpuEndUs);
            nlohmann::ordered_json args = frameArgs;
            args["stamped_ts"] = stampedUs;
            gpuSlices.push_back(slice(pass.pass, category, kGpuThread, beginUs, pass.gpuMs * 1e3, std::move(args)));
            gpuBegin = std::min(gpuBegin, beginUs);
            gpuEndUs = beginUs + pass.gpuMs * 1e3;
        }
        events.push_back(slice(frameName, "frame", kGpuThread, gpuBegin, gpuEndUs - gpuBegin, frameArgs));
        for (nlohmann::ordered_json& gpuSlice : gpuSlices) events.push_back(std::move(gpuSlice));
    }
    nlohmann::ordered_json trace;
    trace["traceEvents"] = std::move(events);
    trace["displayTimeUnit"] = "ms";
    trace["otherData"] = {{"renderer", info.renderer}, {"backend", info.backend},   {"gl_version", info.glVersion},
                          {"scene", info.scene},       {"width", info.width},        {"height", info.height},
                          {"frames", info.frames},     {"warm_up_frames", timings.warmUpFrames()}};
    return trace.dump(1) + "\n";
}

}  // namespace dermis
