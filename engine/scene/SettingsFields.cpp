#include "scene/SettingsFields.h"

namespace dermis {

const IntegerRule& blurTapsRule() {
    static const IntegerRule kRule{
        [](int taps) { return taps >= kMinBlurTaps && taps <= kMaxBlurTaps && taps % 2 == 1; },
        "must be an odd number of taps in [" + std::to_string(kMinBlurTaps) + ", " + std::to_string(kMaxBlurTaps) + "]"};
    return kRule;
}

const IntegerRule& separableSamplesRule() {
    static const IntegerRule kRule{
        [](int samples) {
            return samples >= kMinSeparableSamples && samples <= kMaxSeparableSamples && samples % 2 == 1;
        },
        "must be an odd number of samples in [" + std::to_string(kMinSeparableSamples) + ", " +
            std::to_string(kMaxSeparableSamples) + "]"};
    return kRule;
}

const IntegerRule& tsSizeRule() {
    static const IntegerRule kRule{
        [](int size) { return size >= kMinTsSize && size <= kMaxTsSize && (size & (size - 1)) == 0; },
        "must be a power of two in [" + std::to_string(kMinTsSize) + ", " + std::to_string(kMaxTsSize) + "]"};
    return kRule;
}

}  // namespace dermis
