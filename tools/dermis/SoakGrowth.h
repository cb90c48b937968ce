#pragma once
// What `dermis soak` samples, and how it measures growth between the first
// half of the run after the warm-up and the second: each half is a whole
// number of periods, and the scene repeats every period (SoakMotion.h), so
// both windows hold the same frames of the cycle.
// - Resident memory: the floor (least sample) of each half. The resident
//   figure jumps between levels from one re-created renderer to the next
//   (llvmpipe, measured in docs/stress.md: with the copy present some 55 MiB
//   apart; in texture-space mode with one character 550 or 566 MiB, period by
//   period, with no trend over 1000 frames). The floor of several periods
//   finds the low level in each half; a leak raises every sample of the
//   second half, floor included, by at least the leak over the first half.
// - Texture-pool bytes: the peak of each window. The pool's contents are a
//   function of the frames since the renderer was created, which repeat, so
//   any difference is growth.

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
    uint64_t firstResidentFloor = 0, lastResidentFloor = 0;
    uint64_t firstPoolPeak = 0, lastPoolPeak = 0;

    int64_t residentBytes() const { return int64_t(lastResidentFloor) - int64_t(firstResidentFloor); }
    int64_t poolBytes() const { return int64_t(lastPoolPeak) - int64_t(firstPoolPeak); }
};

// One mode's samples, in frame order; frames >= warmupFrames + 2 * periodFrames.
// The first half holds floor(periods / 2) of the whole periods after the
// warm-up, the second half the rest.
SoakGrowth measureSoakGrowth(const std::vector<SoakSample>& samples, int warmupFrames, int periodFrames, int frames);

}  // namespace dermis::cli
