#pragma once
// The files `dermis bench` and `dermis merge` (of bench shards) write into a
// bench directory: results.csv, passes.csv, summary.json and the plots
// (tools/plot_bench.py) with errors.md.

#include "bench/BenchReport.h"
#include "core/OutputFiles.h"
#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace dermis::cli {

// Stages results.csv, passes.csv, summary.json and, when `plots`, the plots
// and errors.md (drawn in a hidden directory inside outDir).
Status stageBenchTables(const std::filesystem::path& outDir, const std::vector<bench::BenchRow>& rows,
                        const nlohmann::ordered_json& summary, bool plots, OutputFiles& outputs);

// One line per mode: its default configuration's time and error.
void printBenchDefaults(const nlohmann::ordered_json& summary);

}  // namespace dermis::cli
