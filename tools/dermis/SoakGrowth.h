#pragma once
// What `dermis soak` samples, and how it measures growth: the peak over the
// samples of the last period minus the peak over the samples of the first
// period after the warm-up. The scene repeats every period (SoakMotion.h), so
// both windows hold the same frames of the cycle, the character copy
// included; a peak is steadier than a single sample under allocator noise.

#include <cstdint>
#include <string>
#include <vector>

namespace dermis::cli {

struct SoakSample {
    int frame = 0;  // frames rendered in this mode when it was taken
    int characters = 0;
    uint64_t residentBytes = 0;
    uint64_t poolBytes = 0;
};

struct SoakGrowth {
    int firstWindowStart = 0, firstWindowEnd = 0;  // frames (start, end]
    int lastWindowStart = 0, lastWindowEnd = 0;
    uint64_t firstResidentPeak = 0, lastResidentPeak = 0;
    uint64_t firstPoolPeak = 0, lastPoolPeak = 0;

    int64_t residentBytes() const { return int64_t(lastResidentPeak) - int64_t(firstResidentPeak); }
    int64_t poolBytes() const { return int64_t(lastPoolPeak) - int64_t(firstPoolPeak); }
};

// One mode's samples, in frame order; frames >= warmupFrames + 2 * periodFrames.
SoakGrowth measureSoakGrowth(const std::vector<SoakSample>& samples, int warmupFrames, int periodFrames, int frames);

}  // namespace dermis::cli
