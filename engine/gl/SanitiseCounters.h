#pragma once
// Per-pass counts of the values the shaders' sanitisers replaced (NaN, Inf,
// clamped above or below the range: shaders/include/Sanitise.glsl), and the
// planted NaN of `dermis stress --plant-nan` (docs/stress.md, "Counting and
// reading every target"). The graph backend calls beginPass/endPass around
// every pass: it zeroes the counters and sets the plant flag of the named pass
// only; when counting is on, it reads the counters back after the pass (a
// pipeline stall, so off by default: timings are unaffected).

#include "gl/GlObjects.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace dermis::gl {

struct SanitisedCounts {
    uint64_t nan = 0;
    uint64_t inf = 0;
    uint64_t overflow = 0;  // finite values clamped above the range (fp16 max for colours, 1 for AO)
    uint64_t negative = 0;  // finite values clamped below the range (0 for colours and AO)
    uint64_t nonFinite() const { return nan + inf; }
    uint64_t total() const { return nan + inf + overflow + negative; }
};

struct PassSanitised {
    std::string pass;
    SanitisedCounts counts;
};

class SanitiseCounters {
public:
    void setCounting(bool counting) { mCounting = counting; }
    bool counting() const { return mCounting; }
    // The pass whose shaders return NaN from debugPlant; empty for none.
    void setPlantPass(std::string pass) { mPlantPass = std::move(pass); }
    const std::string& plantPass() const { return mPlantPass; }

    // Binds the counters' buffer to DERMIS_BINDING_SANITISE_COUNTERS (made on first use).
    void bind();
    void beginPass(std::string_view pass);
    void endPass();

    // Every pass counted, in the order of first execution, summed over frames.
    const std::vector<PassSanitised>& passes() const { return mPasses; }
    SanitisedCounts total() const;
    // Whether the plant pass has run since the last reset.
    bool planted() const { return mPlanted; }
    void reset();

private:
    void readCounts();

    Buffer mBuffer;
    bool mCounting = false;
    bool mPlanted = false;
    bool mPlanting = false;  // the current pass is the plant pass
    bool mBufferCounting = false;  // the buffer's counting flag is set
    std::string mPlantPass;
    std::string mCurrentPass;
    std::vector<PassSanitised> mPasses;
};

}  // namespace dermis::gl
