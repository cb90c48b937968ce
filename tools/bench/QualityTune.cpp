#include "bench/QualityTune.h"

#include "scene/JsonReader.h"
#include "scene/SssTechniques.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace dermis::bench {

const std::vector<SssChoice>& tuneCandidates() {
    static const std::vector<SssChoice> kCandidates = [] {
        std::vector<SssChoice> out;
        for (const SssTechniqueInfo& technique : sssTechniques()) {
            for (const SssChoice& choice : technique.candidates) out.push_back(choice.canonical());
        }
        return out;
    }();
    return kCandidates;
}

std::string describeTuneCandidates() {
    std::string out;
    SssTechnique current = SssTechnique::Gaussians;
    bool first = true;
    for (const SssChoice& choice : tuneCandidates()) {
        if (first || choice.technique != current) {
            out += std::string(first ? "" : "\n") + "  " + std::string(kSssTechniques.name(choice.technique)) + ":";
            current = choice.technique;
            first = false;
        }
        const std::string text = describeSssChoice(choice);
        out += " " + text.substr(text.find(' ') + 1) + ";";
    }
    return out + "\n";
}

Result<double> parseBudget(const std::string& text) {
    const bool percent = !text.empty() && text.back() == '%';
    const std::string number = percent ? text.substr(0, text.size() - 1) : text;
    char* end = nullptr;
    const double value = number.empty() ? NAN : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value)) {
        return makeError("--budget " + text, "expected a fraction (0.01) or a percentage (1%)");
    }
    const double budget = percent ? value / 100.0 : value;
    if (!(budget > 0.0 && budget < 1.0)) {
        return makeError("--budget " + text, "must be in (0, 1) as a fraction, (0%, 100%) as a percentage");
    }
    return budget;
}

QualityRow cheapestWithin(float pixelsPerMm, const std::vector<TuneMeasurement>& measured, double budget,
                          double finestSssMs) {
    QualityRow row;
    row.pixelsPerMm = pixelsPerMm;
    row.choice = SssChoice::finest();
    row.loss = 0.0;
    row.sssMs = finestSssMs;
    row.finestSssMs = finestSssMs;
    // Equal losses are the same image (several `gaussians` choices whose every
    // Gaussian is under min_width_px: no pass of theirs runs), so the same
    // work: each counts at the least time measured for its image, and the
    // first in candidate order is taken, not the luckier timing, so that
    // reruns and shards agree.
    const auto imageMs = [&](const TuneMeasurement& m) {
        double ms = m.sssMs;
        for (const TuneMeasurement& other : measured) ms = other.loss == m.loss ? std::min(ms, other.sssMs) : ms;
        return ms;
    };
    double cheapestMs = finestSssMs;  // the finest is a candidate too, with loss 0
    for (const TuneMeasurement& m : measured) {
        if (m.loss <= budget) cheapestMs = std::min(cheapestMs, m.sssMs);
    }
    const double tiedMs = cheapestMs * (1.0 + kTuneTimingTie);
    if (finestSssMs <= tiedMs) return row;  // nothing clearly cheaper than the finest: it has the lowest loss
    const TuneMeasurement* best = nullptr;  // some candidate is at cheapestMs, so one is found
    for (const TuneMeasurement& m : measured) {
        if (m.loss > budget || imageMs(m) > tiedMs) continue;
        if (!best || m.loss < best->loss) best = &m;
    }
    row.choice = best->choice;
    row.loss = best->loss;
    row.sssMs = best->sssMs;
    return row;
}

Status sortQualityRows(QualityTable& table, const std::string& where) {
    std::sort(table.rows.begin(), table.rows.end(),
              [](const QualityRow& a, const QualityRow& b) { return a.pixelsPerMm < b.pixelsPerMm; });
    for (size_t i = 1; i < table.rows.size(); ++i) {
        if (table.rows[i].pixelsPerMm <= table.rows[i - 1].pixelsPerMm) {
            return makeError(where, "two distances give the same scale (" + formatNumberForMessage(table.rows[i].pixelsPerMm) +
                                        " px/mm): choose distance factors further apart");
        }
    }
    return success();
}

std::string qualityTableMarkdown(const QualityTable& table, double margin) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "Quality table: error budget %.3g%% (relative RMSE of the diffuse AOV over SSS pixels against the finest "
                  "choice), tuned on %s at %dx%d.\n\n",
                  100.0 * table.budget, table.tunedOn.c_str(), table.width, table.height);
    std::string out = line;
    out += "| pixels per mm (up to) | choice | loss | SSS GPU ms | finest SSS GPU ms | SSS cost / finest |\n";
    out += "|---:|---|---:|---:|---:|---:|\n";
    for (const QualityRow& row : table.rows) {
        std::snprintf(line, sizeof line, "| %.3g | %s | %.2f%% | %.3f | %.3f | %.2f |\n", row.pixelsPerMm,
                      describeSssChoice(row.choice).c_str(), 100.0 * row.loss, row.sssMs, row.finestSssMs,
                      row.finestSssMs > 0.0 ? row.sssMs / row.finestSssMs : NAN);
        out += line;
    }
    out += "\nAbove the largest scale a character uses the finest choice (" + describeSssChoice(SssChoice::finest()) +
           "); between two scales, the row of the larger one (docs/quality.md).\n";
    std::snprintf(line, sizeof line, "\nA candidate qualified when its loss was at most %.3g x the budget (--margin).\n", margin);
    return out + line;
}

}  // namespace dermis::bench
