#include "SoakGrowth.h"

#include <algorithm>

namespace dermis::cli {

SoakGrowth measureSoakGrowth(const std::vector<SoakSample>& samples, int warmupFrames, int periodFrames, int frames) {
    SoakGrowth growth;
    const int periods = (frames - warmupFrames) / periodFrames;
    growth.firstWindowStart = warmupFrames;
    growth.firstWindowEnd = warmupFrames + (periods / 2) * periodFrames;
    growth.lastWindowStart = growth.firstWindowEnd;
    growth.lastWindowEnd = frames;
    growth.firstResidentFloor = UINT64_MAX;
    growth.lastResidentFloor = UINT64_MAX;
    for (const SoakSample& s : samples) {
        if (s.frame > growth.firstWindowStart && s.frame <= growth.firstWindowEnd) {
            growth.firstResidentFloor = std::min(growth.firstResidentFloor, s.residentBytes);
            growth.firstPoolPeak = std::max(growth.firstPoolPeak, s.poolBytes);
        }
        if (s.frame > growth.lastWindowStart && s.frame <= growth.lastWindowEnd) {
            growth.lastResidentFloor = std::min(growth.lastResidentFloor, s.residentBytes);
            growth.lastPoolPeak = std::max(growth.lastPoolPeak, s.poolBytes);
        }
    }
    return growth;
}

}  // namespace dermis::cli
