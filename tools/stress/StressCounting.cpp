#include "stress/StressCounting.h"

#include <cstdio>

namespace dermis::stress {
namespace {

void addCounts(gl::SanitisedCounts& sum, const gl::SanitisedCounts& counts) {
    sum.nan += counts.nan;
    sum.inf += counts.inf;
    sum.overflow += counts.overflow;
    sum.negative += counts.negative;
}

}  // namespace

CaseCounting::CaseCounting(Renderer& renderer, const std::string& plantPass) : mRenderer(renderer) {
    gl::SanitiseCounters& counters = renderer.sanitiseCounters();
    counters.reset();
    counters.setCounting(true);
    counters.setPlantPass(plantPass);
    renderer.setPassInspector(mTargets.inspector());
}

CaseCounting::~CaseCounting() {
    mRenderer.sanitiseCounters().setCounting(false);
    mRenderer.sanitiseCounters().setPlantPass("");
    mRenderer.setPassInspector(nullptr);
}

uint64_t CaseCounting::failures() const {
    uint64_t n = mTargets.totalBad();
    for (const gl::PassSanitised& p : sanitised()) n += p.counts.nonFinite();
    return n;
}

std::string CaseCounting::firstFailingPass() const {
    return gl::firstFaultyPass(mRenderer.framePasses(), sanitised(), mTargets);
}

nlohmann::ordered_json sanitisedJson(const gl::SanitisedCounts& counts) {
    nlohmann::ordered_json j;
    j["nan"] = counts.nan;
    j["inf"] = counts.inf;
    j["overflow"] = counts.overflow;
    j["negative"] = counts.negative;
    return j;
}

nlohmann::ordered_json failureJson(const CaseCounting& counting) {
    nlohmann::ordered_json j;
    j["pass"] = counting.firstFailingPass();
    nlohmann::ordered_json passes = nlohmann::ordered_json::object();
    for (const gl::PassSanitised& p : counting.sanitised()) {
        if (p.counts.total() > 0) passes[p.pass] = sanitisedJson(p.counts);
    }
    j["sanitised"] = passes;
    nlohmann::ordered_json targets = nlohmann::ordered_json::object();
    for (const auto& [target, stats] : counting.targets().targets()) {
        if (stats.bad() == 0) continue;
        targets[target] = {{"non_finite", stats.nonFinite}, {"out_of_range", stats.outOfRange}};
    }
    j["targets"] = targets;
    return j;
}

void CountingTotals::add(const CaseCounting& counting) {
    for (const gl::PassSanitised& p : counting.sanitised()) {
        addCounts(mSanitised, p.counts);
        addCounts(mPerPass[p.pass], p.counts);
    }
    for (const auto& [target, stats] : counting.targets().targets()) {
        gl::TargetStats& sum = mPerTarget[target];
        sum.format = stats.format;
        sum.lit = stats.lit;
        sum.texels += stats.texels;
        sum.nonFinite += stats.nonFinite;
        sum.outOfRange += stats.outOfRange;
        sum.atHalfMax += stats.atHalfMax;
        sum.largest = std::max(sum.largest, stats.largest);
        sum.largestLit = std::max(sum.largestLit, stats.largestLit);
    }
    mLargestLit = std::max(mLargestLit, counting.targets().largestLit());
}

nlohmann::ordered_json CountingTotals::json() const {
    nlohmann::ordered_json j;
    j["sanitised"] = sanitisedJson(mSanitised);
    nlohmann::ordered_json passes = nlohmann::ordered_json::object();
    for (const auto& [pass, counts] : mPerPass) passes[pass] = sanitisedJson(counts);
    j["sanitised_per_pass"] = passes;
    uint64_t texels = 0, bad = 0, atHalfMax = 0;
    nlohmann::ordered_json targets = nlohmann::ordered_json::object();
    for (const auto& [target, stats] : mPerTarget) {
        texels += stats.texels;
        bad += stats.bad();
        atHalfMax += stats.atHalfMax;
        nlohmann::ordered_json t;
        t["format"] = stats.format;
        t["texels"] = stats.texels;
        t["non_finite"] = stats.nonFinite;
        t["out_of_range"] = stats.outOfRange;
        t["at_half_max"] = stats.atHalfMax;
        t["largest_finite"] = stats.largest;
        t["lit"] = stats.lit;
        targets[target] = t;
    }
    j["texels_read"] = texels;
    j["bad_texels"] = bad;
    j["texels_at_half_max"] = atHalfMax;
    j["largest_lit_value"] = mLargestLit;
    j["targets"] = targets;
    return j;
}

std::string CountingTotals::line() const {
    uint64_t texels = 0, bad = 0, atHalfMax = 0;
    for (const auto& [target, stats] : mPerTarget) {
        texels += stats.texels;
        bad += stats.bad();
        atHalfMax += stats.atHalfMax;
    }
    char text[320];
    std::snprintf(text, sizeof(text),
                  "sanitised nan %llu, inf %llu, overflow %llu, negative %llu; %llu texels read in %zu targets, %llu bad, "
                  "%llu at fp16 max, largest lit value %.3g",
                  static_cast<unsigned long long>(mSanitised.nan), static_cast<unsigned long long>(mSanitised.inf),
                  static_cast<unsigned long long>(mSanitised.overflow),
                  static_cast<unsigned long long>(mSanitised.negative), static_cast<unsigned long long>(texels),
                  mPerTarget.size(), static_cast<unsigned long long>(bad), static_cast<unsigned long long>(atHalfMax),
                  mLargestLit);
    std::string line = text;
    // The passes that replaced anything, with their non-zero counters.
    std::string byPass;
    for (const auto& [pass, counts] : mPerPass) {
        if (counts.total() == 0) continue;
        std::string kinds;
        const std::pair<const char*, uint64_t> named[] = {
            {"nan", counts.nan}, {"inf", counts.inf}, {"overflow", counts.overflow}, {"negative", counts.negative}};
        for (const auto& [name, n] : named) {
            if (n > 0) kinds += (kinds.empty() ? "" : " ") + std::string(name) + " " + std::to_string(n);
        }
        byPass += (byPass.empty() ? "" : ", ") + pass + " (" + kinds + ")";
    }
    if (!byPass.empty()) line += "; by pass: " + byPass;
    return line;
}

}  // namespace dermis::stress
