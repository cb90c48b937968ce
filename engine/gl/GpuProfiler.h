#pragma once
// Per-pass GPU and CPU time. GPU time comes from GL_TIME_ELAPSED queries kept
// in flight for several frames: beginFrame() collects only results that are
// already available, so reading them never stalls the pipeline. drain() waits
// for the rest (at the end of a run, when a stall no longer matters).
//
// CPU time is the wall-clock time the pass took to record its commands.

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
};

class GpuProfiler {
public:
    GpuProfiler() = default;
    ~GpuProfiler();
    GpuProfiler(const GpuProfiler&) = delete;
    GpuProfiler& operator=(const GpuProfiler&) = delete;

    void beginFrame(uint64_t frame);
    void beginPass(const std::string& name);
    void endPass();
    void drain();  // blocking; call when done rendering

    // Completed samples, oldest first; the caller takes them.
    std::vector<PassTiming> takeCompleted();
    size_t pendingCount() const { return mPending.size(); }

private:
    struct Pending {
        GLuint query;
        PassTiming timing;
    };
    GLuint newQuery();
    void collect(bool wait);

    std::deque<Pending> mPending;
    std::vector<GLuint> mFreeQueries;
    std::vector<GLuint> mAllQueries;
    std::vector<PassTiming> mCompleted;
    uint64_t mFrame = 0;
    bool mInPass = false;
    std::string mPassName;
    GLuint mActiveQuery = 0;
    std::chrono::steady_clock::time_point mPassStart;
};

}  // namespace dermis::gl
