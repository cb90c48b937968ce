#pragma once
// One bench row as JSON, every field and without loss, for the shards of
// `dermis bench` (shards/BenchShards.h): a double is written as the shortest
// decimal that reads back to the same bits, and one that is not finite as the
// string "nan", "inf" or "-inf" (JSON has no such numbers). The Pareto marks
// are not written: they depend on the other rows.

#include "bench/BenchReport.h"
#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dermis::bench {

nlohmann::ordered_json benchRowToJson(const BenchRow& row);

// Errors name `where` and the key (as a JSON pointer below it).
Result<BenchRow> benchRowFromJson(const nlohmann::json& json, const std::string& where);

}  // namespace dermis::bench
