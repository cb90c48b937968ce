#pragma once
// The wrong-image detectors' counts for the stress summary: JSON and one line.
#include "stress/Invariants.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dermis::stress {

// {"coverage": {"checked": n, "violated": m}, ...}
nlohmann::ordered_json countsJson(const InvariantReport& report);
// The violated invariants of one case with their counts and details.
nlohmann::ordered_json violationsJson(const InvariantReport& report);
// "coverage 120/0, energy 300/0, ..." (checked/violated).
std::string countsLine(const InvariantReport& report);

}  // namespace dermis::stress
