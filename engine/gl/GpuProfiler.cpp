#include "gl/GpuProfiler.h"

#include <cassert>
#include <cmath>
#include <cstring>

namespace dermis::gl {

GpuProfiler::~GpuProfiler() {
    if (!mAllQueries.empty()) glDeleteQueries(static_cast<GLsizei>(mAllQueries.size()), mAllQueries.data());
}

GLuint GpuProfiler::newQuery(GLenum target) {
    std::vector<GLuint>& free = mFreeQueries[target];
    if (!free.empty()) {
        const GLuint query = free.back();
        free.pop_back();
        return query;
    }
    const GLuint query = createQuery(target, target == GL_TIMESTAMP ? "profiler: timestamp" : "profiler: elapsed time");
    mAllQueries.push_back(query);
    return query;
}

double GpuProfiler::cpuNowMs() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mEpoch).count();
}

void GpuProfiler::beginFrame(uint64_t frame) {
    if (mAllQueries.empty()) {
        // llvmpipe reports a time since some epoch (~17 minutes) for the first
        // GL_TIME_ELAPSED query that contains rendering; spend that one on a
        // 1x1 clear so no pass inherits it.
        GLint previousFramebuffer = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
        Texture texture = createTexture(GL_TEXTURE_2D, "profiler: first-query clear target");
        glTextureStorage2D(texture.get(), 1, GL_RGBA8, 1, 1);
        Framebuffer framebuffer = createFramebuffer("profiler: first-query clear target");
        glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, texture.get(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        const GLuint warmUp = newQuery(GL_TIME_ELAPSED);
        glBeginQuery(GL_TIME_ELAPSED, warmUp);
        glClear(GL_COLOR_BUFFER_BIT);
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 ignored = 0;
        glGetQueryObjectui64v(warmUp, GL_QUERY_RESULT, &ignored);
        mFreeQueries[GL_TIME_ELAPSED].push_back(warmUp);
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    }
    if (!mSplitBatchesKnown) {
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        mSplitBatches = renderer != nullptr && std::strstr(renderer, "llvmpipe") != nullptr;
        mSplitBatchesKnown = true;
    }
    if (!mClockPaired) {
        GLint counterBits = 0;
        glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &counterBits);
        mTimestamps = mTimestamps && counterBits > 0;
        GLint64 gpuNowNs = 0;
        glGetInteger64v(GL_TIMESTAMP, &gpuNowNs);
        mGpuToCpuMs = cpuNowMs() - double(gpuNowNs) * 1e-6;
        mClockPaired = true;
    }
    mFrame = frame;
    collect(false);
}

void GpuProfiler::beginPass(const std::string& name) {
    assert(!mInPass);
    mInPass = true;
    mPassName = name;
    mActiveTimestamp = 0;
    if (mTimestamps) {
        // Two stamps, before and after: the pass's time is their difference.
        mActiveTimestamp = newQuery(GL_TIMESTAMP);
        glQueryCounter(mActiveTimestamp, GL_TIMESTAMP);
    } else {
        mActiveQuery = newQuery(GL_TIME_ELAPSED);
        glBeginQuery(GL_TIME_ELAPSED, mActiveQuery);
    }
    // llvmpipe bins a batch's commands per 64x64 tile and runs each tile's
    // list in turn, all passes of the batch at once; a stamp reads the time
    // its last tile reached it. Two passes in one batch (the same
    // framebuffer, no flush between) so read as one, the whole batch's time
    // on the first. Ending the batch here keeps this pass out of the last one's.
    if (mSplitBatches) glFlush();
    mPassStart = std::chrono::steady_clock::now();
}

void GpuProfiler::endPass() {
    assert(mInPass);
    const auto end = std::chrono::steady_clock::now();
    if (mTimestamps) {
        mActiveQuery = newQuery(GL_TIMESTAMP);
        glQueryCounter(mActiveQuery, GL_TIMESTAMP);
    } else {
        glEndQuery(GL_TIME_ELAPSED);
    }
    PassTiming timing;
    timing.frame = mFrame;
    timing.pass = mPassName;
    timing.cpuMs = std::chrono::duration<double, std::milli>(end - mPassStart).count();
    timing.cpuBeginMs = std::chrono::duration<double, std::milli>(mPassStart - mEpoch).count();
    timing.gpuBeginMs = NAN;
    Pending pending{mActiveQuery, mActiveTimestamp, std::move(timing)};
    mPending.push_back(std::move(pending));
    mInPass = false;
}

void GpuProfiler::collect(bool wait) {
    // Results arrive in submission order, so stop at the first that is not ready.
    while (!mPending.empty()) {
        Pending& front = mPending.front();
        if (!wait) {
            GLuint available = GL_FALSE;
            glGetQueryObjectuiv(front.query, GL_QUERY_RESULT_AVAILABLE, &available);
            if (available != GL_TRUE) break;
        }
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(front.query, GL_QUERY_RESULT, &nanoseconds);
        if (front.timestamp != 0) {
            // `query` is the end stamp; the begin stamp was issued before it, so it is ready too.
            GLuint64 beginNs = 0;
            glGetQueryObjectui64v(front.timestamp, GL_QUERY_RESULT, &beginNs);
            front.timing.gpuMs = nanoseconds >= beginNs ? double(nanoseconds - beginNs) * 1e-6 : 0.0;
            front.timing.gpuBeginMs = double(beginNs) * 1e-6 + mGpuToCpuMs;
            mFreeQueries[GL_TIMESTAMP].push_back(front.timestamp);
            mFreeQueries[GL_TIMESTAMP].push_back(front.query);
        } else {
            front.timing.gpuMs = static_cast<double>(nanoseconds) * 1e-6;
            mFreeQueries[GL_TIME_ELAPSED].push_back(front.query);
        }
        mCompleted.push_back(std::move(front.timing));
        mPending.pop_front();
    }
}

void GpuProfiler::drain() { collect(true); }

std::vector<PassTiming> GpuProfiler::takeCompleted() {
    std::vector<PassTiming> out;
    out.swap(mCompleted);
    return out;
}

}  // namespace dermis::gl
