#include "gl/GpuProfiler.h"

#include <cassert>

namespace dermis::gl {

GpuProfiler::~GpuProfiler() {
    if (!mAllQueries.empty()) glDeleteQueries(static_cast<GLsizei>(mAllQueries.size()), mAllQueries.data());
}

GLuint GpuProfiler::newQuery() {
    if (!mFreeQueries.empty()) {
        const GLuint query = mFreeQueries.back();
        mFreeQueries.pop_back();
        return query;
    }
    GLuint query = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &query);
    mAllQueries.push_back(query);
    return query;
}

void GpuProfiler::beginFrame(uint64_t frame) {
    if (mAllQueries.empty()) {
        // llvmpipe reports a time since some epoch (~17 minutes) for the first
        // GL_TIME_ELAPSED query that contains rendering; spend that one on a
        // 1x1 clear so no pass inherits it.
        GLint previousFramebuffer = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
        Texture texture = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(texture.get(), 1, GL_RGBA8, 1, 1);
        Framebuffer framebuffer = createFramebuffer();
        glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, texture.get(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        const GLuint warmUp = newQuery();
        glBeginQuery(GL_TIME_ELAPSED, warmUp);
        glClear(GL_COLOR_BUFFER_BIT);
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 ignored = 0;
        glGetQueryObjectui64v(warmUp, GL_QUERY_RESULT, &ignored);
        mFreeQueries.push_back(warmUp);
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    }
    mFrame = frame;
    collect(false);
}

void GpuProfiler::beginPass(const std::string& name) {
    assert(!mInPass);
    mInPass = true;
    mPassName = name;
    mActiveQuery = newQuery();
    glBeginQuery(GL_TIME_ELAPSED, mActiveQuery);
    mPassStart = std::chrono::steady_clock::now();
}

void GpuProfiler::endPass() {
    assert(mInPass);
    const auto end = std::chrono::steady_clock::now();
    glEndQuery(GL_TIME_ELAPSED);
    Pending pending{mActiveQuery, PassTiming{mFrame, mPassName, 0.0,
                                             std::chrono::duration<double, std::milli>(end - mPassStart).count()}};
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
        front.timing.gpuMs = static_cast<double>(nanoseconds) * 1e-6;
        mCompleted.push_back(std::move(front.timing));
        mFreeQueries.push_back(front.query);
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
