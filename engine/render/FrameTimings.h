#pragma once
// Aggregates per-pass timings over many frames: which passes ran, and the
// median GPU and CPU milliseconds of each. Writes the timings JSON and the
// table `dermis render` prints.
//
// JSON layout:
// { "renderer": "...", "backend": "...", "gl_version": "...", "width": W, "height": H,
//   "frames": N, "scene": "...",
//   "passes": [ {"name": "...", "executed": true, "executed_frames": 10, "culled_because": "",
//                "gpu_ms": 1.2, "cpu_ms": 0.1}, ... ],
//   "frame": {"gpu_ms": ..., "cpu_ms": ..., "wall_ms": ...},
//   "characters": [ {"name": "...", ..., "sss": {"technique": "gaussians", "taps": 9, "gaussians": 6,
//                    "separable_samples": 17, "disk_samples": 40, "pixels_per_mm": 2.1,
//                    "source": "settings" | "table" | "finest" | "merged"}}, ... ] }
// "sss" is null for a character without SSS and in texture space.
// `executed` is true when the pass ran in at least one frame; a cached pass
// (a shadow map) runs in the first frame only. `culled_because` says why it
// was culled in the last frame it did not run. gpu_ms and cpu_ms are medians
// over the frames in which the pass ran (0 if it never ran); the frame
// figures are medians of per-frame sums.

#include "core/Result.h"
#include "gl/GpuProfiler.h"
#include "graph/RenderGraph.h"
#include "scene/QualityTable.h"

#include <map>
#include <string>
#include <vector>

namespace dermis {

struct PassSummary {
    std::string name;
    bool executed = false;      // in at least one frame
    size_t executedFrames = 0;
    size_t frames = 0;          // frames in which the pass was declared
    std::string culledBecause;  // why it was culled when it last was; empty if never
    double gpuMs = 0.0;
    double cpuMs = 0.0;
    size_t samples = 0;
};

// One character as the last frame planned it (plan/FramePlan.h), for the
// timings JSON: what it cost depends on these choices.
struct CharacterReport {
    std::string name;
    bool visible = true;
    std::string culledBecause;  // why not visible
    bool animated = false;
    float clipTimeS = 0.0f;
    int textureSpaceSize = 0;      // irradiance texture side; 0 when texture space does not draw it
    std::string textureSpaceFallback;
    // Screen space: the SSS choice it renders with (plan/SssPlan.h CharacterSssChoice); absent when it has no SSS.
    bool hasSss = false;
    SssChoice sssChoice;
    float pixelsPerMm = 0.0f;
    std::string sssChoiceSource;
    // Its level of detail (plan/LevelOfDetail.h; 0: the full mesh) and that level's error on screen.
    int lod = 0;
    float lodErrorPx = 0.0f;
};

struct RunInfo {
    std::string renderer;
    std::string backend;
    std::string glVersion;
    std::string scene;
    int width = 0;
    int height = 0;
    int frames = 0;
    double wallMsPerFrame = 0.0;
    std::vector<CharacterReport> characters;  // empty: the JSON has no "characters" key
};

double median(std::vector<double> values);
// "near: separable samples=7, 3.21 px/mm (table row <= 4 px/mm)": one character's
// screen-space SSS choice as the viewer's panel and the render's table print it;
// empty when it has no SSS.
std::string describeCharacterSss(const CharacterReport& character);
std::string describeCull(const graph::PassReport& report);

class FrameTimings {
public:
    void addPassReports(const std::vector<graph::PassReport>& reports);  // once per frame, in pass order
    void addTimings(const std::vector<gl::PassTiming>& timings);

    std::vector<PassSummary> summary() const;
    double frameGpuMs() const;  // median over frames of the sum over passes
    double frameCpuMs() const;

    std::string toJson(const RunInfo& info) const;
    std::string toTable(const RunInfo& info) const;
    Status writeJson(const std::string& path, const RunInfo& info) const;

private:
    std::vector<std::string> mOrder;  // pass names in declaration order, as first seen
    struct PassRecord {
        size_t declared = 0;
        size_t executed = 0;
        std::string lastCull;
    };
    std::map<std::string, PassRecord> mRecords;
    std::map<std::string, std::vector<double>> mGpu;
    std::map<std::string, std::vector<double>> mCpu;
    std::map<uint64_t, double> mFrameGpu;
    std::map<uint64_t, double> mFrameCpu;
};

}  // namespace dermis
