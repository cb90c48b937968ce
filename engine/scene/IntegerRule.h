#pragma once
// An integer setting's rule, for settings whose valid values are not a plain
// range (odd tap counts, powers of two) or that are listed in a table
// (scene/SssTechniques.h).

#include <string>

namespace dermis {

// An integer that must satisfy `valid`; `requirement` says how in messages
// ("must be an odd number of taps in [3, 33]").
struct IntegerRule {
    bool (*valid)(int);
    std::string requirement;
};

const IntegerRule& blurTapsRule();          // odd, in [kMinBlurTaps, kMaxBlurTaps]
const IntegerRule& separableSamplesRule();  // odd, in [kMinSeparableSamples, kMaxSeparableSamples]
const IntegerRule& diskSamplesRule();       // in [kMinDiskSamples, kMaxDiskSamples]
const IntegerRule& profileGaussiansRule();  // in [1, kMaxProfileGaussians]
const IntegerRule& tsSizeRule();            // a power of two in [kMinTsSize, kMaxTsSize]

}  // namespace dermis
