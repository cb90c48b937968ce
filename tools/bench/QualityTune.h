#pragma once
// What `dermis tune` decides, without GL: the candidate screen-space SSS
// choices, the cheapest one within an error budget at one scale, the budget's
// syntax and the Markdown form of a quality table (scene/QualityTable.h,
// docs/quality.md).

#include "core/Result.h"
#include "scene/QualityTable.h"

#include <string>
#include <vector>

namespace dermis::bench {

// Every choice `dermis tune` measures at each distance (the finest,
// SssChoice::finest(), is measured as the reference of every loss):
//   gaussians: 2..6 Gaussians x 5, 9, 17 taps
//   separable: 7, 11, 17, 25 samples per direction
//   disk:      8, 16, 32, 64 samples per pixel
const std::vector<SssChoice>& tuneCandidates();
// The list above, one technique a line, for --help.
std::string describeTuneCandidates();

// "1%" or "0.01" -> 0.01; a fraction in (0, 1). Errors name --budget.
Result<double> parseBudget(const std::string& text);

struct TuneMeasurement {
    SssChoice choice;
    double loss = 0.0;   // relative RMSE of the diffuse AOV over SSS pixels against the finest
    double sssMs = 0.0;  // median GPU ms of the SSS passes
    double frameMs = 0.0;
};

// Candidates whose SSS ms are within this fraction of the cheapest count as
// equally cheap: llvmpipe's timings of one render move by more than that from
// run to run, so among them the measured loss, which does not move, decides.
constexpr double kTuneTimingTie = 0.15;

// Of the measurements whose loss is at most `budget`, the one with the lowest
// loss among those within kTuneTimingTie of the cheapest sssMs; the finest
// (loss 0, finestSssMs) when none is within the budget.
QualityRow cheapestWithin(float pixelsPerMm, const std::vector<TuneMeasurement>& measured, double budget,
                          double finestSssMs);

// Sorts the rows by pixels per mm; errors (naming `where`) when two rows have
// the same scale (two distances too close together).
Status sortQualityRows(QualityTable& table, const std::string& where);

// One line per row: scale, choice, loss, SSS ms, the finest's SSS ms, saving;
// and the margin (dermis tune --margin) a candidate qualified within.
std::string qualityTableMarkdown(const QualityTable& table, double margin);

}  // namespace dermis::bench
