#include "stress/StressRun.h"

#include "core/ContentHash.h"
#include "frame/Renderer.h"
#include "scene/SceneLoader.h"
#include "stress/InvariantFrame.h"
#include "stress/InvariantJson.h"
#include "stress/StressHash.h"
#include "stress/StressLoading.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace dermis::stress {
namespace {

// Seconds since the last call (or construction).
class Lap {
public:
    double next() {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - mLast).count();
        mLast = now;
        return seconds;
    }

private:
    std::chrono::steady_clock::time_point mLast = std::chrono::steady_clock::now();
};


// Renders the case's frames, each inspected and hashed (the scene moves
// between them), then runs the wrong-image detectors on the last frame's scene.
void renderCase(const StressCase& c, Scene& scene, const CaseOptions& options, CountingTotals& totals,
                Lap& lap, CaseResult& result) {
    auto renderer = Renderer::create(scene, options.programs);
    result.setUpSeconds += lap.next();
    if (!renderer.ok()) {
        result.error = renderer.error().message();
        return;
    }
    {
        CaseCounting counting(**renderer, options.plantPass);
        CaseHash hash;
        (*renderer)->setPassInspector(hash.inspector(counting.targetsInspector()));
        for (int frame = 0; frame < c.frames; ++frame) {
            if (frame > 0) advanceFrame(c, scene);
            if (const Status status = (*renderer)->renderFrame({c.width, c.height, c.aov}); !status.ok()) {
                result.error = "frame " + std::to_string(frame) + ": " + status.error().message();
                return;
            }
            auto output = (*renderer)->readOutput();
            if (!output.ok()) {
                result.error = output.error().message();
                return;
            }
            hash.addImage(*output);
        }
        result.hash = hash.value();
        totals.add(counting);
        result.nonFinite = counting.failures();
        if (result.nonFinite > 0) result.counts = failureJson(counting);
        result.passes = (*renderer)->framePasses();
        result.planted = counting.planted();
    }
    result.frameSeconds = lap.next();
    auto invariants = checkCaseInvariants(**renderer, scene, c, options.plant, options.programs);
    if (!invariants.ok()) result.error = invariants.error().message();
    else result.invariants = *invariants;
    result.detectorSeconds = lap.next();
}

// `message` with the case's asset folder (per process) written as "ASSETS".
std::string withoutAssetDirectory(std::string message, const std::string& directory) {
    if (directory.empty()) return message;
    for (size_t at = message.find(directory); at != std::string::npos; at = message.find(directory, at)) {
        message.replace(at, directory.size(), "ASSETS");
    }
    return message;
}

}  // namespace

CaseResult runCase(const StressCase& c, const CaseOptions& options, CountingTotals& totals) {
    CaseResult result;
    result.seed = c.seed;
    result.description = c.description;
    Lap lap;
    Result<Scene> loaded = loadCaseScene(c);
    result.setUpSeconds = lap.next();
    if (c.path == CasePath::Hostile) {
        result.error = refusalProblem(c, loaded);
        result.refused = result.error.empty();
        CaseHash hash;  // of the refusal, so that a changed message changes the hash
        if (!loaded.ok()) hash.addText(withoutAssetDirectory(loaded.error().message(), c.assetDirectory));
        result.hash = hash.value();
        return result;
    }
    if (!loaded.ok()) {
        result.error = "the loader refused a legal case: " + loaded.error().message();
        return result;
    }
    Scene scene = std::move(*loaded);  // outlives the renderer, which holds a reference
    renderCase(c, scene, options, totals, lap, result);
    if (result.failed()) result.sceneJson = sceneToJson(scene);
    return result;
}

void StressRun::add(const CaseResult& r, const std::string& failedScenesDir, OutputFiles& outputs) {
    mInvariants.add(r.invariants);
    mNonFinite += r.nonFinite;
    mPlanted = mPlanted || r.planted;
    mRefused += r.refused ? 1 : 0;
    mHashes.push_back(hex16(r.hash));
    mSetUpSeconds += r.setUpSeconds;
    mFrameSeconds += r.frameSeconds;
    mDetectorSeconds += r.detectorSeconds;
    mCaseSeconds.emplace_back(r.seconds(), r.seed);
    for (const std::string& pass : r.passes) {
        if (std::find(mPassesSeen.begin(), mPassesSeen.end(), pass) == mPassesSeen.end()) mPassesSeen.push_back(pass);
    }
    if (!r.failed()) return;
    ++mFailed;
    nlohmann::ordered_json f;
    f["seed"] = r.seed;
    f["description"] = r.description;
    f["non_finite"] = r.nonFinite;
    f["pass"] = r.counts.is_object() ? r.counts.value("pass", "") : "";
    f["counts"] = r.counts;
    f["error"] = r.error;
    f["invariants"] = violationsJson(r.invariants);
    if (!failedScenesDir.empty() && !r.sceneJson.empty()) {
        const std::string path =
            (std::filesystem::path(failedScenesDir) / ("seed-" + std::to_string(r.seed) + ".json")).string();
        if (const Status written = outputs.stageText(path, r.sceneJson); written.ok())
            f["scene"] = path;
        else
            f["scene_error"] = written.error().message();
    }
    mFailures.push_back(f);
}

nlohmann::ordered_json StressRun::summary(nlohmann::ordered_json header, double seconds) const {
    nlohmann::ordered_json summary = std::move(header);
    summary["failed_cases"] = mFailed;
    summary["refused"] = mRefused;
    summary["non_finite_texels"] = mNonFinite;
    summary["counting"] = mCounting.json();
    summary["invariants"] = countsJson(mInvariants);
    summary["seconds"] = seconds;
    summary["seconds_by_stage"] = {{"set_up", mSetUpSeconds}, {"frames", mFrameSeconds}, {"detectors", mDetectorSeconds}};
    constexpr size_t kSlowestListed = 5;
    std::vector<std::pair<double, uint64_t>> caseSeconds = mCaseSeconds;
    std::sort(caseSeconds.rbegin(), caseSeconds.rend());
    nlohmann::ordered_json slowest = nlohmann::ordered_json::array();
    for (size_t i = 0; i < std::min(kSlowestListed, caseSeconds.size()); ++i)
        slowest.push_back({{"seed", caseSeconds[i].second}, {"seconds", caseSeconds[i].first}});
    summary["slowest_cases"] = slowest;
    summary["failures"] = mFailures;
    summary["hashes"] = mHashes;
    return summary;
}

std::string StressRun::line(int cases, double seconds, const std::string& outPath) const {
    std::string failedPasses;
    for (const auto& f : mFailures) {
        const std::string pass = f.value("pass", "");
        if (!pass.empty() && failedPasses.find("'" + pass + "'") == std::string::npos)
            failedPasses += (failedPasses.empty() ? " in " : ", ") + ("'" + pass + "'");
    }
    // The failed seeds, the first few, to rerun (dermis stress --seed S --cases 1).
    constexpr size_t kSeedsShown = 8;
    std::string seeds;
    size_t shown = 0;
    for (const auto& f : mFailures) {
        if (shown++ == kSeedsShown) {
            seeds += ", ...";
            break;
        }
        seeds += (seeds.empty() ? " (seed " : ", ") + std::to_string(f.value("seed", uint64_t(0)));
    }
    if (!seeds.empty()) seeds += ")";
    failedPasses = seeds + failedPasses;
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%d cases in %.1f s: %d failed%s, %d refused as they must be, %llu NaN/Inf/bad values; %s; "
                  "invariants %s (%s)",
                  cases, seconds, mFailed, failedPasses.c_str(), mRefused, static_cast<unsigned long long>(mNonFinite),
                  mCounting.line().c_str(), countsLine(mInvariants).c_str(), outPath.c_str());
    return text;
}

}  // namespace dermis::stress
