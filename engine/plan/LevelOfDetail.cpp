#include "plan/LevelOfDetail.h"

#include <algorithm>
#include <cmath>

namespace dermis {

int chooseLodLevel(const std::vector<float>& errorsObject, float pixelsPerObjectUnit, float maxErrorPx, int previousLevel) {
    if (!(maxErrorPx > 0.0f) || !std::isfinite(pixelsPerObjectUnit)) return 0;
    const int levels = int(errorsObject.size());
    auto fits = [&](int level, float limitPx) {
        return level == 0 || errorsObject[size_t(level - 1)] * pixelsPerObjectUnit <= limitPx;
    };
    int coarsest = 0;
    for (int level = levels; level > 0; --level) {
        if (fits(level, maxErrorPx)) {
            coarsest = level;
            break;
        }
    }
    const int previous = std::clamp(previousLevel, -1, levels);
    if (previous < 0 || previous >= coarsest) return coarsest;  // a first frame, or a level that no longer fits
    for (int level = coarsest; level > previous; --level) {
        if (fits(level, maxErrorPx * kLodHysteresis)) return level;
    }
    return previous;
}

}  // namespace dermis
