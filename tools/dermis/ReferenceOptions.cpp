#include "ReferenceOptions.h"

#include "frame/IrradianceCapture.h"
#include "reference/PixelSampling.h"

#include <cstdio>

namespace dermis::cli {
namespace {

using measure::ReferenceSettings;

// 8.0 -> "8", 0.2 -> "0.2".
std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// 0.002 -> "0.2".
std::string percentText(double fraction) { return shortNumber(100.0 * fraction); }

}  // namespace

std::string referenceOptionsHelp() {
    const ReferenceSettings defaults;
    return "  --density N        the references' quadrature density when they are computed (default " +
           shortNumber(defaults.density) +
           ")\n"
           "  --spp N            the references' samples per pixel, a square (default " +
           std::to_string(defaults.samplesPerPixel) +
           ": the pixel centre,\n"
           "                     where the engine shades)\n"
           "  --change-spp N     the same for the matched reference's scattering change (default " +
           std::to_string(defaults.changeSamplesPerPixel) + ")\n"
           "  --irradiance-size N  texels per side of the engine's irradiance for the matched reference,\n"
           "                     a power of two from " + std::to_string(kMinIrradianceCaptureTexels) + " to " +
           std::to_string(kMaxIrradianceCaptureTexels) + " (default " + std::to_string(defaults.irradianceSizeTexels) + ")\n"
           "  --target-error PCT the full and SSS-off references repeat with independent environment\n"
           "                     rays until the estimated relative RMSE of their noise is at most PCT\n"
           "                     percent (default " +
           percentText(reference::kDefaultTargetRelativeRmse) +
           ")\n"
           "  --max-passes N     at most N passes of each, up to " + std::to_string(reference::kMaxProgressivePasses) +
           " (default " + std::to_string(reference::kDefaultProgressivePasses) + ")\n";
}

Result<reference::ProgressiveSettings> progressiveSettingsFromArgs(const ParsedArgs& args) {
    reference::ProgressiveSettings settings;
    if (args.has("target-error")) {
        auto percent = parsePositiveFloat("--target-error", args.get("target-error", ""));
        if (!percent.ok()) return percent.error();
        settings.targetRelativeRmse = double(*percent) / 100.0;
    }
    if (args.has("max-passes")) {
        auto passes = parsePositiveInt("--max-passes", args.get("max-passes", ""));
        if (!passes.ok()) return passes.error();
        if (*passes > reference::kMaxProgressivePasses) {
            return makeError("--max-passes", "at most " + std::to_string(reference::kMaxProgressivePasses));
        }
        settings.maxPasses = *passes;
    }
    return settings;
}

Result<ReferenceSettings> referenceSettingsFromArgs(const ParsedArgs& args) {
    ReferenceSettings settings;  // its defaults stand where an option is absent (and in the help)
    if (args.has("density")) {
        auto density = parsePositiveFloat("--density", args.get("density", ""));
        if (!density.ok()) return density.error();
        settings.density = *density;
    }
    // Each checked here, before any reference is computed and written.
    enum class Rule { SquareSamples, CaptureSize };
    const struct {
        const char* name;
        int* target;
        Rule rule;
    } integers[] = {{"spp", &settings.samplesPerPixel, Rule::SquareSamples},
                    {"change-spp", &settings.changeSamplesPerPixel, Rule::SquareSamples},
                    {"irradiance-size", &settings.irradianceSizeTexels, Rule::CaptureSize}};
    for (const auto& integer : integers) {
        if (!args.has(integer.name)) continue;
        const std::string option = std::string("--") + integer.name;
        auto value = parsePositiveInt(option, args.get(integer.name, ""));
        if (!value.ok()) return value.error();
        if (integer.rule == Rule::SquareSamples && reference::strataPerSide(*value) == 0) {
            return makeError(option, "must be a perfect square from 1 to " +
                                         std::to_string(reference::kMaxSamplesPerPixel) + ", got " +
                                         std::to_string(*value));
        }
        if (integer.rule == Rule::CaptureSize &&
            (*value < kMinIrradianceCaptureTexels || *value > kMaxIrradianceCaptureTexels || (*value & (*value - 1)) != 0)) {
            return makeError(option, "must be a power of two from " + std::to_string(kMinIrradianceCaptureTexels) + " to " +
                                         std::to_string(kMaxIrradianceCaptureTexels) + ", got " + std::to_string(*value));
        }
        *integer.target = *value;
    }
    auto progressive = progressiveSettingsFromArgs(args);
    if (!progressive.ok()) return progressive.error();
    settings.progressive = *progressive;
    return settings;
}

Result<MeasureOptions> measureOptionsFromArgs(const ParsedArgs& args, const std::string& command) {
    if (args.positional.size() != 1) return makeError(command, "expected exactly one SCENE file");
    if (!args.has("out")) return makeError(command, "--out DIR is required");
    MeasureOptions options;
    options.scenePath = args.positional[0];
    options.outDir = args.get("out", "");
    auto size = parseSize(args.get("size", "640x360"), kMaxFrameDimension);
    if (!size.ok()) return size.error();
    auto frames = parsePositiveInt("--frames", args.get("frames", "5"));
    if (!frames.ok()) return frames.error();
    auto backend = parseBackend(args.get("backend", "auto"));
    if (!backend.ok()) return backend.error();
    auto reference = referenceSettingsFromArgs(args);
    if (!reference.ok()) return reference.error();
    options.width = size->first;
    options.height = size->second;
    options.frames = *frames;
    options.backend = *backend;
    options.reference = *reference;
    options.reference.width = size->first;
    options.reference.height = size->second;
    return options;
}

}  // namespace dermis::cli
