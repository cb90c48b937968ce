#pragma once
// Live per-pass timings for the profiler panel. The renderer's FrameTimings
// gathers pass reports and the GPU timer results that have arrived (a few
// frames late: the queries are read only when ready, so nothing stalls). The
// viewer folds them in here once per frame and then resets FrameTimings, so
// each summary holds one frame's reports and the samples that arrived since.

#include "render/FrameTimings.h"

#include <map>
#include <string>
#include <vector>

namespace dermis::viewer {

// A fixed-length ring of samples, in the layout ImGui::PlotLines reads.
class SampleRing {
public:
    explicit SampleRing(size_t capacity = 120) : mValues(capacity, 0.0f) {}
    void push(float value);
    float latest() const;
    float mean() const;
    float max() const;
    size_t count() const { return mCount; }
    const float* data() const { return mValues.data(); }
    int size() const { return static_cast<int>(mValues.size()); }
    int offset() const { return static_cast<int>(mNext); }  // the oldest sample, once full
    void clear();

private:
    std::vector<float> mValues;
    size_t mNext = 0;
    size_t mCount = 0;
};

struct PassTrack {
    std::string name;
    bool declared = false;  // in the latest frame
    bool executed = false;  // in the latest frame
    std::string culledBecause;
    SampleRing gpuMs;
    SampleRing cpuMs;
};

class PassHistory {
public:
    // One frame's summary: the passes it declared, in order.
    void update(const std::vector<PassSummary>& frame);
    void clear();

    // Passes of the latest frame, in frame order.
    std::vector<const PassTrack*> passes() const;
    // Sum over the latest frame's executed passes of their latest GPU time.
    float frameGpuMs() const { return mFrameGpuMs.latest(); }
    const SampleRing& frameGpuHistory() const { return mFrameGpuMs; }
    size_t frames() const { return mFrames; }

private:
    std::vector<std::string> mOrder;  // the latest frame's pass names
    std::map<std::string, PassTrack> mTracks;
    SampleRing mFrameGpuMs;
    size_t mFrames = 0;
};

}  // namespace dermis::viewer
