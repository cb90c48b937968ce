#include "gl/SanitiseCounters.h"

#include "include/SharedConstants.glsl"

#include <algorithm>

namespace dermis::gl {
namespace {
using uint = unsigned int;
#include "include/Sanitise.glsl"
static_assert(sizeof(SanitiseBlock) == 8 * 4, "SanitiseBlock must match std430");
}  // namespace

void SanitiseCounters::bind() {
    if (mBuffer.get() == 0) {
        mBuffer = createBuffer("sanitise counters");
        const SanitiseBlock zero{};
        glNamedBufferStorage(mBuffer.get(), sizeof(SanitiseBlock), &zero, GL_DYNAMIC_STORAGE_BIT);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DERMIS_BINDING_SANITISE_COUNTERS, mBuffer.get());
}

void SanitiseCounters::beginPass(std::string_view pass) {
    bind();
    mCurrentPass = std::string(pass);
    mPlanting = !mPlantPass.empty() && mCurrentPass == mPlantPass;
    // Without counting or planting the buffer holds zeros (written once after
    // counting stops), so the shaders neither count nor plant.
    if (!mCounting && !mPlanting && !mBufferCounting) return;
    SanitiseBlock block{};
    block.plantNan = mPlanting ? 1u : 0u;
    block.counting = mCounting ? 1u : 0u;
    mBufferCounting = mCounting;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // after the previous pass's atomics
    glNamedBufferSubData(mBuffer.get(), 0, sizeof(block), &block);
    mPlanted = mPlanted || mPlanting;
}

void SanitiseCounters::endPass() {
    if (mPlanting) {
        // No shader outside the planted pass (the next frame's prepare step
        // included) may see the flag.
        const SanitiseBlock zero{};
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        if (mCounting) readCounts();
        glNamedBufferSubData(mBuffer.get(), 0, sizeof(zero), &zero);
        mBufferCounting = false;
        mPlanting = false;
        return;
    }
    if (!mCounting) return;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    readCounts();
}

void SanitiseCounters::readCounts() {
    SanitiseBlock block{};
    glGetNamedBufferSubData(mBuffer.get(), 0, sizeof(block), &block);
    auto it = std::find_if(mPasses.begin(), mPasses.end(), [&](const PassSanitised& p) { return p.pass == mCurrentPass; });
    if (it == mPasses.end()) it = mPasses.insert(mPasses.end(), PassSanitised{mCurrentPass, {}});
    it->counts.nan += block.nanCount;
    it->counts.inf += block.infCount;
    it->counts.overflow += block.overflowCount;
    it->counts.negative += block.negativeCount;
}

SanitisedCounts SanitiseCounters::total() const {
    SanitisedCounts sum;
    for (const PassSanitised& p : mPasses) {
        sum.nan += p.counts.nan;
        sum.inf += p.counts.inf;
        sum.overflow += p.counts.overflow;
        sum.negative += p.counts.negative;
    }
    return sum;
}

void SanitiseCounters::reset() {
    mPasses.clear();
    mPlanted = false;
}

}  // namespace dermis::gl
