#pragma once
// The command-line options of the CPU references that `dermis bench`,
// `compare --errors` and `reference` take (measure/ReferenceImages.h).

#include "Args.h"

#include "gl/GlContext.h"
#include "measure/ReferenceImages.h"

#include <filesystem>

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

// What `bench` and `compare` both take: one SCENE, --out DIR, --size WxH (default
// 640x360), --frames N (default 5), --backend NAME and the reference's options
// (their size set to --size).
struct MeasureOptions {
    std::string scenePath;
    std::filesystem::path outDir;
    int width = 0, height = 0, frames = 5;
    gl::Backend backend = gl::Backend::Auto;
    measure::ReferenceSettings reference;
};
Result<MeasureOptions> measureOptionsFromArgs(const ParsedArgs& args, const std::string& command);
}  // namespace dermis::cli
