#pragma once
// The files `dermis tune` and `dermis merge` write for a quality table
// (docs/quality.md): FILE.json, and the same as a Markdown table in FILE.md.

#include "core/OutputFiles.h"
#include "core/Result.h"
#include "scene/QualityTable.h"

#include <string>

namespace dermis::cli {

// FILE.json -> FILE.md
std::string markdownPath(const std::string& jsonPath);

// Stages both files: `json` (the table's file) and the Markdown of `table`
// (the same table); the JSON is read back first as a scene would read it, so
// that a table written here always loads. `margin` is tune's --margin.
Status stageQualityTable(const std::string& json, const QualityTable& table, double margin, const std::string& outPath,
                         OutputFiles& outputs);

}  // namespace dermis::cli
