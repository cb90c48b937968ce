#pragma once
// Per-pass timings over many frames: every frame's samples (each pass's GPU
// and CPU ms and where it began, the passes culled and why), and over the
// measured frames (all but the first warmUpFrames) which passes ran and the
// median, 5th and 95th percentile of their GPU and CPU ms. Writes the timings
// JSON, the per-frame CSV and the table `dermis render` prints; the trace
// (render/TraceEvents.h) is made from the same frames.
//
// JSON layout:
// { "renderer": "...", "backend": "...", "gl_version": "...", "width": W, "height": H,
//   "frames": N, "warm_up_frames": K, "scene": "...",
//   "passes": [ {"name": "...", "executed": true, "executed_frames": 10, "culled_because": "",
//                "gpu_ms": 1.2, "gpu_p5_ms": 1.1, "gpu_p95_ms": 1.5, "gpu_spread": 0.33,
//                "cpu_ms": 0.1, "cpu_p5_ms": ..., "cpu_p95_ms": ..., "samples": 10}, ... ],
//   "frame": {"gpu_ms": ..., "gpu_p5_ms": ..., "gpu_p95_ms": ..., "cpu_ms": ..., "wall_ms": ...},
//   "per_frame": [ {"frame": 0, "warm_up": true, "gpu_ms": ..., "cpu_ms": ...,
//                   "passes": [{"name", "gpu_ms", "cpu_ms", "gpu_begin_ms", "cpu_begin_ms"}],
//                   "culled": [{"name", "because"}]}, ... ],
//   "characters": [ {"name": "...", ..., "sss": {"technique": "gaussians", "taps": 9, "gaussians": 6,
//                    "separable_samples": 17, "disk_samples": 40, "pixels_per_mm": 2.1,
//                    "source": "settings" | "table" | "finest" | "merged"}}, ... ] }
// "sss" is null for a character without SSS and in texture space.
// `executed` is true when the pass ran in at least one measured frame; a
// cached pass (a shadow map) runs in the first frame only. `culled_because`
// says why it was culled in the last frame it did not run. gpu_ms and cpu_ms
// are medians over the measured frames in which the pass ran (0 if it never
// ran), p5 and p95 percentiles (linear between order statistics), spread
// (p95 - p5) / median; the frame figures are over per-frame sums. *_begin_ms
// are ms since the renderer's profiler was made, the GPU's moved onto the
// CPU's clock (gl/GpuProfiler.h); null where the GL has no timestamps.

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
    double gpuMs = 0.0;  // median
    double cpuMs = 0.0;
    double gpuP5Ms = 0.0, gpuP95Ms = 0.0;
    double cpuP5Ms = 0.0, cpuP95Ms = 0.0;
    size_t samples = 0;
};

// One frame as recorded: its passes in the order they ran, and those culled.
struct FrameRecord {
    uint64_t frame = 0;
    bool warmUp = false;
    std::vector<gl::PassTiming> passes;
    std::vector<std::pair<std::string, std::string>> culled;  // pass, why
    double gpuMs() const;  // sums over the passes
    double cpuMs() const;
};

// One character as the last frame planned it (plan/FramePlan.h), for the
// timings JSON: what it cost depends on these choices.
struct CharacterReport {
    std::string name;
    bool visible = true;
    std::string culledBecause;  // why not visible
    float footprintPixels = 0.0f;  // its bounds' area on screen (plan/ScreenFootprint.h)
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
// The p-th percentile (p in [0, 100]), linear between order statistics (as
// numpy.percentile's default); 0 for no values.
double percentile(std::vector<double> values, double p);

// A set of samples summarised as the timings report them (one sort).
struct Distribution {
    double median = 0.0;
    double p5 = 0.0;
    double p95 = 0.0;
    double spread() const { return median > 0.0 ? (p95 - p5) / median : 0.0; }  // (p95 - p5) / median
};
Distribution distributionOf(std::vector<double> values);
// "near: separable samples=7, 3.21 px/mm (table row <= 4 px/mm)": one character's
// screen-space SSS choice as the viewer's panel and the render's table print it;
// empty when it has no SSS.
std::string describeCharacterSss(const CharacterReport& character);
std::string describeCull(const graph::PassReport& report);

class FrameTimings {
public:
    // The first `frames` frames reported are warm-up: recorded and marked, not summarised.
    void setWarmUpFrames(size_t frames) { mWarmUpFrames = frames; }
    size_t warmUpFrames() const { return mWarmUpFrames; }

    void addPassReports(uint64_t frame, const std::vector<graph::PassReport>& reports);  // once per frame, in pass order
    void addTimings(const std::vector<gl::PassTiming>& timings);

    std::vector<PassSummary> summary() const;
    double frameGpuMs() const;  // median over measured frames of the sum over passes
    double frameCpuMs() const;
    // Every frame reported, in order (a frame's timings arrive a few frames later).
    const std::vector<FrameRecord>& frames() const { return mFrames; }

    std::string toJson(const RunInfo& info) const;
    // One row per pass per frame: frame,warm_up,pass,gpu_ms,cpu_ms,gpu_begin_ms,cpu_begin_ms
    std::string toCsv() const;
    std::string toTable(const RunInfo& info) const;

private:
    FrameRecord* record(uint64_t frame);
    FrameRecord& recordFor(uint64_t frame);  // made when first seen
    // Over the frames after the warm-up that have timers.
    Distribution frameDistribution(double (FrameRecord::*sum)() const) const;

    size_t mWarmUpFrames = 0;
    std::vector<std::string> mOrder;  // pass names in declaration order, as first seen
    struct PassRecord {
        size_t declared = 0;
        size_t executed = 0;
        std::string lastCull;
    };
    std::map<std::string, PassRecord> mRecords;  // over measured frames
    std::vector<FrameRecord> mFrames;
    std::map<uint64_t, size_t> mFrameIndex;  // frame number -> mFrames index
};

}  // namespace dermis
