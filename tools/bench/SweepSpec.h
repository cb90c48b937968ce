#pragma once
// The quality sweep of `dermis bench`: which settings to vary, and
// the configurations that result. No GL.
//
// A SPEC is axes separated by ';'. An axis is
//     [MODE:]KEYS=VALUE,VALUE,...
// MODE names an SSS mode (kSssModes): the axis applies to that mode's
// configurations only; without it, to every mode. KEYS is one settings path as `--set` takes it
// (`sss.taps`, `ts.max_size`), several joined by '+' that all take each value
// (`ts.min_size+ts.max_size=512` pins the irradiance texture's side), or the
// word `scale`: the frame is rendered at scale x the bench size and its
// diffuse AOV resampled back before it is compared (render resolution as a
// quality knob). The modes swept are those an axis names, or every mode when
// no axis names one. Each mode's configurations are the Cartesian product of
// the axes that apply to it, in SPEC order, the first axis varying slowest.
//
//   ss:sss.taps=5,9,17;ss:scale=0.5,1;ts:ts.taps=3,7
//   -> ss taps=5 scale=0.5, ss taps=5 scale=1, ss taps=9 scale=0.5, ...,
//      ts taps=3, ts taps=7
//
// Values are checked here only for shape (`scale` a number in (0, 4]); the
// settings are checked like a scene file when the bench loads each
// configuration (scene/SceneOverrides.h).

#include "core/Result.h"

#include <string>
#include <vector>

namespace dermis::bench {

constexpr const char* kScaleKey = "scale";
constexpr double kMaxScale = 4.0;
constexpr size_t kMaxConfigurations = 10000;

struct SweepAxis {
    std::string mode;                 // a name from kSssModes, or "" for every mode
    std::vector<std::string> keys;    // settings paths, or {kScaleKey}
    std::vector<std::string> values;  // as written
};

struct SweepConfig {
    std::string mode;                    // a name from kSssModes
    std::vector<std::string> overrides;  // --set strings: "mode=ss" first, then one per swept key
    double scale = 1.0;                  // frame size factor
    std::string label;                   // "taps=5 scale=0.5"; "" for no swept key
};

// "[ss:|ts:]": the optional mode prefix of an axis, for help and errors.
std::string modePrefixSyntax();

// The sweep `dermis bench` runs when no --sweep is given: the knobs.
extern const char* const kDefaultSweepSpec;

// Errors name the axis: Error{"--sweep ss:sss.taps=", "axis has no values"}.
Result<std::vector<SweepAxis>> parseSweepSpec(const std::string& spec);

// The configurations, mode by mode in the order of kSssModes. An error when there would be more
// than kMaxConfigurations.
Result<std::vector<SweepConfig>> expandSweep(const std::vector<SweepAxis>& axes);

}  // namespace dermis::bench
