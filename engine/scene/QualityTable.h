#pragma once
// Quality tables (docs/quality.md): the cheapest screen-space SSS choice
// within an error budget, per on-screen scale, as `dermis tune` measured it.
//
// The error a budget bounds is the LOSS of a choice: the relative RMSE of the
// diffuse AOV over SSS pixels against the finest screen-space setting
// (SssChoice::finest(), min_width_px 0, full resolution) at the same view.
//
// File layout (JSON):
//   {"budget": 0.01, "tuned_on": "content/scenes/default.json", "size": [640, 360],
//    "rows": [{"pixels_per_mm": 1.9, "choice": {"technique": "gaussians", "taps": 5,
//              "gaussians": 3, "separable_samples": 17, "disk_samples": 40},
//              "loss": 0.004, "sss_ms": 1.2, "finest_sss_ms": 4.1}, ...]}
// Rows are sorted by pixels_per_mm, strictly increasing: the on-screen scale
// (pixels per millimetre at the characters' nearest depth) the row was tuned at.
//
// THE RULE (conservative): a character at scale s uses the row tuned at the
// smallest scale >= s, i.e. between two tuned scales the row tuned at the
// LARGER one, below the smallest the first row; above the largest tuned scale
// it uses the finest choice. Why: the same blur spans more pixels at a larger
// scale, so a cheap choice's loss grows with the scale; a row is only known to
// meet the budget at its own scale and, by that growth, below it.

#include "core/Result.h"
#include "scene/SssChoice.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis {

struct QualityRow {
    float pixelsPerMm = 0.0f;  // the scale it was tuned at
    SssChoice choice;
    double loss = 0.0;         // against the finest at that scale
    double sssMs = 0.0;        // median GPU ms of the SSS passes, as measured
    double finestSssMs = 0.0;  // the same for the finest choice
};

struct QualityTable {
    std::string path;   // the file it was read from, for messages
    double budget = 0.0;
    std::string tunedOn;
    int width = 0;
    int height = 0;
    std::vector<QualityRow> rows;  // pixelsPerMm strictly increasing

    bool empty() const { return rows.empty(); }
    // The rule above: the index of the row for scale s, or rows.size() for the finest.
    size_t rowFor(float pixelsPerMm) const;
    // The choice at index `row` of rowFor; rows.size() is the finest.
    SssChoice choiceAt(size_t row) const;
};

// Strict: unknown keys, a missing key, a wrong type, an unknown technique, a
// sample count outside the engine's limits, rows not strictly increasing in
// pixels_per_mm are errors naming `path` and the JSON pointer.
Result<QualityTable> parseQualityTable(const std::string& text, const std::string& path);
Result<QualityTable> loadQualityTable(const std::string& path);
// The file's text, unparsed (dermis merge joins tables as JSON).
Result<std::string> readQualityTableText(const std::string& path);
std::string qualityTableJson(const QualityTable& table);

}  // namespace dermis
