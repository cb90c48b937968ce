#include "bench/SweepSpec.h"

#include "scene/JsonReader.h"
#include "scene/SceneEnums.h"
#include "scene/SceneOverrides.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dermis::bench {

const char* const kDefaultSweepSpec =
    "ss:sss.taps=5,9,17;ss:sss.gaussians=3,4,6;ss:sss.blur=bilateral,control;ss:scale=0.5,1;"
    "ss:transmittance.enabled=true,false;"
    "ts:ts.min_size+ts.max_size=256,512,1024;ts:ts.taps=3,7,13;ts:ts.tsm=true,false";

std::string modePrefixSyntax() { return "[" + kSssModes.list(":|") + ":]"; }

namespace {

// "ss: or ts:" and "[ss:|ts:]": the axis prefixes, from the table of modes.
std::string modePrefixes() {
    std::vector<std::string> prefixes = kSssModes.names();
    for (std::string& prefix : prefixes) prefix += ':';
    return listForMessage(prefixes, "or");
}

std::string axisSyntax() { return modePrefixSyntax() + "KEY=VALUE,VALUE,..."; }

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    size_t start = 0;
    while (true) {
        const size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) return parts;
        start = end + 1;
    }
}

std::string trim(const std::string& text) {
    const size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

Result<double> parseScale(const std::string& where, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value) || !(value > 0.0) || value > kMaxScale) {
        return makeError(where, "scale must be a number in (0, " + std::to_string(int(kMaxScale)) + "], got '" + text + "'");
    }
    return value;
}

Status checkKey(const std::string& where, const std::string& key) {
    if (key == kScaleKey) return success();
    if (key == "mode" || key == "settings.mode")
        return makeError(where, "the mode is not a key: prefix an axis with " + modePrefixes() + " instead");
    auto change = parseSceneOverride(key + "=0");
    if (!change.ok()) return makeError(where, "'" + key + "' is not a settings path");
    // The environment's approximations are quality knobs too; its source,
    // intensity and rotation change the picture, which the one reference fixes.
    const std::vector<std::string>& path = change->path;
    const bool environmentKnob = path.size() == 2 && path[0] == "environment" &&
                                 (path[1] == "occlusion" || path[1] == "specular" || path[1] == "sh_bands");
    if (!environmentKnob && (path.empty() || path.front() != "settings"))
        return makeError(where, "'" + key +
                                    "' is not under settings: the bench sweeps settings only, and the environment's "
                                    "occlusion, specular and sh_bands");
    return success();
}

Result<SweepAxis> parseAxis(const std::string& text) {
    const std::string where = "--sweep " + text;
    SweepAxis axis;
    std::string body = text;
    const size_t colon = body.find(':');
    const size_t equals = body.find('=');
    if (colon != std::string::npos && (equals == std::string::npos || colon < equals)) {
        axis.mode = trim(body.substr(0, colon));
        if (!kSssModes.parse(axis.mode)) return makeError(where, "the mode prefix must be " + modePrefixes());
        body = body.substr(colon + 1);
    }
    const size_t eq = body.find('=');
    if (eq == std::string::npos) return makeError(where, "expected " + axisSyntax());
    for (const std::string& key : split(body.substr(0, eq), '+')) {
        const std::string k = trim(key);
        if (k.empty()) return makeError(where, "empty key");
        if (Status ok = checkKey(where, k); !ok.ok()) return ok.error();
        axis.keys.push_back(k);
    }
    const bool isScale = axis.keys.size() == 1 && axis.keys[0] == kScaleKey;
    for (const std::string& key : axis.keys) {
        if (key == kScaleKey && !isScale) return makeError(where, "scale cannot be joined with other keys");
    }
    for (const std::string& value : split(body.substr(eq + 1), ',')) {
        const std::string v = trim(value);
        if (v.empty()) return makeError(where, "axis has an empty value");
        if (isScale) {
            if (auto scale = parseScale(where, v); !scale.ok()) return scale.error();
        }
        axis.values.push_back(v);
    }
    return axis;
}

// "sss.taps" -> "taps"; a switch keeps its group: "transmittance.enabled".
std::string shortName(const std::string& key) {
    const std::string path = key.rfind("settings.", 0) == 0 ? key.substr(9) : key;
    const size_t dot = path.rfind('.');
    if (dot == std::string::npos) return path;
    const std::string last = path.substr(dot + 1);
    return last == "enabled" ? path : last;
}

std::string axisLabel(const SweepAxis& axis) {
    std::string label;
    for (const std::string& key : axis.keys) label += (label.empty() ? "" : "+") + shortName(key);
    return label;
}

}  // namespace

Result<std::vector<SweepAxis>> parseSweepSpec(const std::string& spec) {
    std::vector<SweepAxis> axes;
    for (const std::string& part : split(spec, ';')) {
        if (trim(part).empty()) continue;
        auto axis = parseAxis(trim(part));
        if (!axis.ok()) return axis.error();
        axes.push_back(std::move(*axis));
    }
    if (axes.empty()) return makeError("--sweep", "the sweep has no axes (expected " + axisSyntax() + " separated by ';')");
    return axes;
}

Result<std::vector<SweepConfig>> expandSweep(const std::vector<SweepAxis>& axes) {
    bool named = false;
    for (const SweepAxis& axis : axes) named = named || !axis.mode.empty();
    std::vector<SweepConfig> configs;
    for (const EnumEntry<SssMode>& entry : kSssModes) {
        const std::string mode(entry.name);
        std::vector<const SweepAxis*> applying;
        bool modeNamed = false;
        for (const SweepAxis& axis : axes) {
            if (axis.mode.empty() || axis.mode == mode) applying.push_back(&axis);
            modeNamed = modeNamed || axis.mode == mode;
        }
        if (named && !modeNamed) continue;
        size_t count = 1;
        for (const SweepAxis* axis : applying) {
            count *= axis->values.size();
            if (configs.size() + count > kMaxConfigurations)
                return makeError("--sweep", "more than " + std::to_string(kMaxConfigurations) + " configurations");
        }
        // Mixed-radix counting; the last axis varies fastest.
        std::vector<size_t> digit(applying.size(), 0);
        for (size_t n = 0; n < count; ++n) {
            SweepConfig config;
            config.mode = mode;
            config.overrides.push_back("mode=" + mode);
            for (size_t a = 0; a < applying.size(); ++a) {
                const SweepAxis& axis = *applying[a];
                const std::string& value = axis.values[digit[a]];
                if (axis.keys[0] == kScaleKey) {
                    config.scale = std::strtod(value.c_str(), nullptr);
                } else {
                    for (const std::string& key : axis.keys) config.overrides.push_back(key + "=" + value);
                }
                config.label += (config.label.empty() ? "" : " ") + axisLabel(axis) + "=" + value;
            }
            configs.push_back(std::move(config));
            for (size_t a = applying.size(); a-- > 0;) {
                if (++digit[a] < applying[a]->values.size()) break;
                digit[a] = 0;
            }
        }
    }
    return configs;
}

}  // namespace dermis::bench
