#pragma once
// A small strict option parser: `--name value` and `--name=value` options,
// `--flag` switches, and positional arguments. Unknown options are errors.

#include "core/EnumTable.h"
#include "core/Result.h"
#include "gl/GlContext.h"
#include "scene/JsonReader.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace dermis::cli {

struct ParsedArgs {
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;  // without the leading "--"; the last value given
    std::map<std::string, std::vector<std::string>> repeated;  // every value, in order
    std::set<std::string> flags;

    bool has(const std::string& name) const { return options.count(name) > 0; }
    std::string get(const std::string& name, const std::string& fallback) const;
    std::vector<std::string> all(const std::string& name) const;
};

// `valued` lists options that take a value, `switches` those that do not.
Result<ParsedArgs> parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valued,
                             const std::set<std::string>& switches);

// "c, lcb or lbb": the names a closed-set option takes, for its error.
template <typename E, size_t N>
std::string expectedNames(const EnumTable<E, N>& table) {
    return listForMessage(table.names(), "or");
}

// The largest count an option takes (--frames, --cases, --spp, ...): a million.
inline constexpr long kMaxCountOption = 1000000;

Result<int> parsePositiveInt(const std::string& option, const std::string& text);
Result<int> parseNonNegativeInt(const std::string& option, const std::string& text);
// A finite number in (0, 10000].
Result<float> parsePositiveFloat(const std::string& option, const std::string& text);
// A finite number in [low, high].
Result<float> parseFloatIn(const std::string& option, const std::string& text, double low, double high);
// "START:END:FPS": frame times START, START + 1/FPS, ... up to END (inclusive);
// END >= START, FPS in (0, 10000], at most maxFrames frames.
Result<std::vector<float>> parseSequence(const std::string& option, const std::string& text, size_t maxFrames);
// "WxH" -> {W, H}; both in 1..maxDimension.
Result<std::pair<int, int>> parseSize(const std::string& text, int maxDimension);

// --backend NAME: auto, egl or osmesa.
Result<gl::Backend> parseBackend(const std::string& name);

// The exit statuses, after the one error line.
int failure(const Error& error);     // 1: the input or the run failed; 2 when the error names a --set override
int usageError(const Error& error);  // 2: the command line is wrong

}  // namespace dermis::cli
