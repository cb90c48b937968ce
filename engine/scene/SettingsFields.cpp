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

const IntegerRule& diskSamplesRule() {
    static const IntegerRule kRule{[](int samples) { return samples >= kMinDiskSamples && samples <= kMaxDiskSamples; },
                                   Range::closed(kMinDiskSamples, kMaxDiskSamples).describe()};
    return kRule;
}

const IntegerRule& profileGaussiansRule() {
    static const IntegerRule kRule{[](int count) { return count >= 1 && count <= kMaxProfileGaussians; },
                                   Range::closed(1, kMaxProfileGaussians).describe()};
    return kRule;
}

const IntegerRule& tsSizeRule() {
    static const IntegerRule kRule{
        [](int size) { return size >= kMinTsSize && size <= kMaxTsSize && (size & (size - 1)) == 0; },
        "must be a power of two in [" + std::to_string(kMinTsSize) + ", " + std::to_string(kMaxTsSize) + "]"};
    return kRule;
}

}  // namespace dermis
