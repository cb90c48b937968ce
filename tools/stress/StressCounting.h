#pragma once
// What `dermis stress` counts in one case's frame (docs/stress.md, "Counting
// and reading every target"): the values each pass's sanitisers replaced
// (gl/SanitiseCounters.h) and every target each pass wrote, read back
// (gl/NonFiniteCounter.h); and the totals over all cases for the summary.

#include "frame/Renderer.h"
#include "gl/NonFiniteCounter.h"
#include "gl/SanitiseCounters.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace dermis::stress {

class CaseCounting {
public:
    // Turns counting on for `renderer` (and plants a NaN in `plantPass`, if
    // not empty) until this object is destroyed. Set before the frame.
    CaseCounting(Renderer& renderer, const std::string& plantPass);
    ~CaseCounting();
    CaseCounting(const CaseCounting&) = delete;
    CaseCounting& operator=(const CaseCounting&) = delete;

    // After the frame. NaN or Inf that a sanitiser replaced, or a bad texel
    // read back (non-finite, out of range): the case fails.
    uint64_t failures() const;
    // The first pass, in execution order, with a failure; empty for none.
    std::string firstFailingPass() const;
    bool planted() const { return mRenderer.sanitiseCounters().planted(); }
    // The read-back of every target, which the constructor installs as the
    // renderer's pass inspector; for a caller that wraps it (stress/StressHash.h).
    gl::PassInspector targetsInspector() { return mTargets.inspector(); }
    const gl::NonFiniteCounter& targets() const { return mTargets; }
    const std::vector<gl::PassSanitised>& sanitised() const { return mRenderer.sanitiseCounters().passes(); }

private:
    Renderer& mRenderer;
    gl::NonFiniteCounter mTargets;
};

// Sums over the cases, written into the summary JSON.
class CountingTotals {
public:
    void add(const CaseCounting& counting);
    nlohmann::ordered_json json() const;
    // One line: the totals per sanitised kind, texels read, bad texels.
    std::string line() const;
    double largestLit() const { return mLargestLit; }

private:
    gl::SanitisedCounts mSanitised;
    std::map<std::string, gl::SanitisedCounts> mPerPass;
    std::map<std::string, gl::TargetStats> mPerTarget;  // keyed "pass/texture"
    double mLargestLit = 0.0;
};

// A failing case's counts: the sanitised values of every pass with any and
// every target with a bad texel.
nlohmann::ordered_json failureJson(const CaseCounting& counting);
nlohmann::ordered_json sanitisedJson(const gl::SanitisedCounts& counts);

}  // namespace dermis::stress
