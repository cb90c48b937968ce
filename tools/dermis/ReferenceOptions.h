#pragma once
// The command-line options of the CPU references that `dermis bench`,
// `compare --errors` and `reference` take (measure/ReferenceImages.h).

#include "Args.h"

#include "measure/ReferenceImages.h"

#include <set>
#include <string>

namespace dermis::cli {

// The options that set measure::ReferenceSettings (all but the size), for the option
// lists and help texts of the commands that take them.
inline const std::set<std::string> kReferenceOptionNames = {"density",      "spp",          "change-spp",
                                                            "irradiance-size", "target-error", "max-passes"};
std::string referenceOptionsHelp();
Result<measure::ReferenceSettings> referenceSettingsFromArgs(const ParsedArgs& args);
// --target-error PCT (default kDefaultTargetRelativeRmse) and --max-passes N.
Result<reference::ProgressiveSettings> progressiveSettingsFromArgs(const ParsedArgs& args);
}  // namespace dermis::cli
