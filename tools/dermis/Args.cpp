#include "Args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dermis::cli {

std::string ParsedArgs::get(const std::string& name, const std::string& fallback) const {
    auto it = options.find(name);
    return it == options.end() ? fallback : it->second;
}

std::vector<std::string> ParsedArgs::all(const std::string& name) const {
    auto it = repeated.find(name);
    return it == repeated.end() ? std::vector<std::string>{} : it->second;
}

Result<ParsedArgs> parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valued,
                             const std::set<std::string>& switches) {
    ParsedArgs parsed;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) {
            parsed.positional.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        std::optional<std::string> value;
        if (const size_t eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (switches.count(name)) {
            if (value) return makeError("--" + name, "takes no value");
            parsed.flags.insert(name);
        } else if (valued.count(name)) {
            if (!value) {
                if (i + 1 >= args.size()) return makeError("--" + name, "needs a value");
                value = args[++i];
            }
            parsed.options[name] = *value;
            parsed.repeated[name].push_back(*value);
        } else {
            return makeError(arg, "unknown option (see --help)");
        }
    }
    return parsed;
}

Result<int> parsePositiveInt(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value <= 0 || value > 1000000) {
        return makeError(option, "expected a positive integer, got '" + text + "'");
    }
    return static_cast<int>(value);
}

Result<std::pair<int, int>> parseSize(const std::string& text, int maxDimension) {
    const size_t x = text.find('x');
    auto bad = [&](const std::string& why) { return makeError("--size " + text, why); };
    if (x == std::string::npos) return bad("expected WIDTHxHEIGHT, e.g. 640x360");
    errno = 0;
    char* end = nullptr;
    const long w = std::strtol(text.substr(0, x).c_str(), &end, 10);
    if (*end != '\0' || x == 0) return bad("expected WIDTHxHEIGHT, e.g. 640x360");
    const long h = std::strtol(text.substr(x + 1).c_str(), &end, 10);
    if (*end != '\0' || x + 1 == text.size() || errno != 0) return bad("expected WIDTHxHEIGHT, e.g. 640x360");
    if (w < 1 || h < 1 || w > maxDimension || h > maxDimension) {
        return bad("each side must be 1.." + std::to_string(maxDimension));
    }
    return std::make_pair(static_cast<int>(w), static_cast<int>(h));
}

Result<float> parsePositiveFloat(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value) || !(value > 0.0f) || value > 1e4f) {
        return makeError(option, "expected a number in (0, 10000], got '" + text + "'");
    }
    return value;
}

}  // namespace dermis::cli
