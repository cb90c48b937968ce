#pragma once
// One run of `dermis stress`: each case loaded, rendered frame by frame with
// every target counted and hashed, and checked by the invariants
// (Invariants.h); and the run's totals, its summary JSON and its one line.

#include "core/OutputFiles.h"
#include "render/Programs.h"
#include "stress/Invariants.h"
#include "stress/StressCases.h"
#include "stress/StressCounting.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dermis::stress {

struct CaseResult {
    uint64_t seed = 0;
    std::string description;
    uint64_t nonFinite = 0;
    bool refused = false;  // a hostile case the loader refused as it must
    uint64_t hash = 0;     // stress/StressHash.h: every texel inspected and every frame's output
    std::string error;
    nlohmann::ordered_json counts;  // a failing case's (stress/StressCounting.h)
    std::vector<std::string> passes;
    bool planted = false;
    InvariantReport invariants;
    std::string sceneJson;  // the case's scene after its frames (scene/SceneLoader.h)
    bool failed() const { return nonFinite > 0 || !error.empty() || invariants.anyViolated(); }
    // Wall-clock seconds by stage: loading the scene and creating the
    // renderer, the inspected frames, the detectors.
    double setUpSeconds = 0.0, frameSeconds = 0.0, detectorSeconds = 0.0;
    double seconds() const { return setUpSeconds + frameSeconds + detectorSeconds; }
};

// What a case is run with besides its own seed.
struct CaseOptions {
    std::shared_ptr<Programs> programs;  // compiled once for every case
    std::string plantPass;               // --plant-nan
    Plant plant = Plant::None;
};

CaseResult runCase(const StressCase& c, const CaseOptions& options, CountingTotals& totals);

// The totals of a run, case by case.
class StressRun {
public:
    // `failedScenesDir`: where a failed case's scene is staged (empty: nowhere).
    void add(const CaseResult& result, const std::string& failedScenesDir, OutputFiles& outputs);
    const CountingTotals& counting() const { return mCounting; }
    CountingTotals& counting() { return mCounting; }
    int failed() const { return mFailed; }
    bool planted() const { return mPlanted; }
    const std::vector<std::string>& passesSeen() const { return mPassesSeen; }
    const InvariantReport& invariants() const { return mInvariants; }
    // summary.json's content (docs/stress.md); `header` holds the run's own settings, first.
    nlohmann::ordered_json summary(nlohmann::ordered_json header, double seconds) const;
    // The run in one line: cases, failures and their passes, refusals, the counts, the invariants.
    std::string line(int cases, double seconds, const std::string& outPath) const;

private:
    CountingTotals mCounting;
    nlohmann::ordered_json mFailures = nlohmann::ordered_json::array();
    nlohmann::ordered_json mHashes = nlohmann::ordered_json::array();  // per case, in seed order
    uint64_t mNonFinite = 0;
    std::vector<std::string> mPassesSeen;  // for --plant-nan's usage error
    bool mPlanted = false;
    int mFailed = 0;
    int mRefused = 0;
    InvariantReport mInvariants;
    double mSetUpSeconds = 0.0, mFrameSeconds = 0.0, mDetectorSeconds = 0.0;
    std::vector<std::pair<double, uint64_t>> mCaseSeconds;  // (seconds, seed), for the slowest cases
};

}  // namespace dermis::stress
