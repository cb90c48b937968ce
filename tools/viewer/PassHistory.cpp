#include "viewer/PassHistory.h"

#include <algorithm>

namespace dermis::viewer {

void SampleRing::push(float value) {
    if (mValues.empty()) return;
    mValues[mNext] = value;
    mNext = (mNext + 1) % mValues.size();
    mCount = std::min(mCount + 1, mValues.size());
}

float SampleRing::latest() const {
    if (mCount == 0) return 0.0f;
    return mValues[(mNext + mValues.size() - 1) % mValues.size()];
}

float SampleRing::mean() const {
    if (mCount == 0) return 0.0f;
    double sum = 0.0;
    for (size_t i = 0; i < mCount; ++i) sum += mValues[(mNext + mValues.size() - 1 - i) % mValues.size()];
    return static_cast<float>(sum / static_cast<double>(mCount));
}

float SampleRing::max() const {
    float best = 0.0f;
    for (size_t i = 0; i < mCount; ++i) best = std::max(best, mValues[(mNext + mValues.size() - 1 - i) % mValues.size()]);
    return best;
}

void SampleRing::clear() {
    std::fill(mValues.begin(), mValues.end(), 0.0f);
    mNext = 0;
    mCount = 0;
}

void PassHistory::update(const std::vector<PassSummary>& frame) {
    for (auto& [name, track] : mTracks) track.declared = false;
    mOrder.clear();
    float total = 0.0f;
    for (const PassSummary& summary : frame) {
        PassTrack& track = mTracks[summary.name];
        track.name = summary.name;
        track.declared = true;
        track.executed = summary.executedFrames > 0;
        track.culledBecause = track.executed ? "" : summary.culledBecause;
        // The samples are those that arrived during this frame, from some
        // earlier frame; the summary gives their median (usually one sample).
        if (summary.samples > 0) {
            track.gpuMs.push(static_cast<float>(summary.gpuMs));
            track.cpuMs.push(static_cast<float>(summary.cpuMs));
        }
        if (track.executed) total += track.gpuMs.latest();
        mOrder.push_back(summary.name);
    }
    mFrameGpuMs.push(total);
    ++mFrames;
}

void PassHistory::clear() {
    mOrder.clear();
    mTracks.clear();
    mFrameGpuMs.clear();
    mFrames = 0;
}

std::vector<const PassTrack*> PassHistory::passes() const {
    std::vector<const PassTrack*> out;
    for (const std::string& name : mOrder) out.push_back(&mTracks.at(name));
    return out;
}

}  // namespace dermis::viewer
