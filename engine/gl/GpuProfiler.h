#pragma once
// Per-pass GPU and CPU time. GPU time comes from a pair of GL_TIMESTAMP
// queries (glQueryCounter) around each pass, kept in flight for several
// frames: beginFrame() collects only results that are already available, so
// reading them never stalls the pipeline. drain() waits for the rest (at the
// end of a run, when a stall no longer matters). The begin stamp also places
// the pass in a trace (render/TraceEvents.h), moved onto the CPU's clock by
// one pair of readings (GL_TIMESTAMP now, the steady clock now) taken at the
// first frame. Without a timestamp counter (or with setTimestamps(false)) a
// GL_TIME_ELAPSED query measures the pass instead, and it has no place.
//
// CPU time is the wall-clock time the pass took to record its commands.
// Begin times are ms since the profiler was made.

#include "gl/GlObjects.h"

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace dermis::gl {

struct PassTiming {
    uint64_t frame = 0;
    std::string pass;
    double gpuMs = 0.0;
    double cpuMs = 0.0;
    double cpuBeginMs = 0.0;
    double gpuBeginMs = 0.0;  // NaN when the GL has no timestamp counter, or timestamps are off
};

class GpuProfiler {
public:
    GpuProfiler() = default;
    ~GpuProfiler();
    GpuProfiler(const GpuProfiler&) = delete;
    GpuProfiler& operator=(const GpuProfiler&) = delete;

    // Off: GL_TIME_ELAPSED queries, no place in time (gpuBeginMs NaN); what the stamps cost is benchmarked against it.
    void setTimestamps(bool on) { mTimestamps = on; }
    // On llvmpipe (found at the first frame unless set before it), each pass starts a new batch of
    // work (glFlush) so that its stamps do not take the time of another pass that shares its framebuffer.
    void setSplitBatches(bool on) {
        mSplitBatches = on;
        mSplitBatchesKnown = true;
    }

    void beginFrame(uint64_t frame);
    void beginPass(const std::string& name);
    void endPass();
    void drain();  // blocking; call when done rendering

    // Completed samples, oldest first; the caller takes them.
    std::vector<PassTiming> takeCompleted();
    size_t pendingCount() const { return mPending.size(); }

private:
    struct Pending {
        GLuint query;      // the end stamp, or the elapsed-time query
        GLuint timestamp;  // the begin stamp; 0 for an elapsed-time query
        PassTiming timing;
    };
    GLuint newQuery(GLenum target);
    void collect(bool wait);
    double cpuNowMs() const;

    std::deque<Pending> mPending;
    std::map<GLenum, std::vector<GLuint>> mFreeQueries;  // by target
    std::vector<GLuint> mAllQueries;
    std::chrono::steady_clock::time_point mEpoch = std::chrono::steady_clock::now();
    bool mTimestamps = true;
    bool mSplitBatches = false;  // glFlush at each pass's start: on llvmpipe (GpuProfiler.cpp says why)
    bool mSplitBatchesKnown = false;
    bool mClockPaired = false;
    double mGpuToCpuMs = 0.0;  // add to a GL_TIMESTAMP in ms to get ms since mEpoch
    std::vector<PassTiming> mCompleted;
    uint64_t mFrame = 0;
    bool mInPass = false;
    std::string mPassName;
    GLuint mActiveQuery = 0;
    GLuint mActiveTimestamp = 0;
    std::chrono::steady_clock::time_point mPassStart;
};

}  // namespace dermis::gl
