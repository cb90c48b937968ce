#include "Args.h"

#include "core/Log.h"

#include "core/Limits.h"
#include "core/Suggest.h"

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
        if (arg == "-h" && switches.count("help")) {  // as `dermis -h` takes it
            parsed.flags.insert("help");
            continue;
        }
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
            std::vector<std::string> known;
            for (const std::string& option : valued) known.push_back("--" + option);
            for (const std::string& option : switches) known.push_back("--" + option);
            return makeError(arg, "unknown option" + didYouMean("--" + name, known) + " (see --help)");
        }
    }
    return parsed;
}

namespace {

Result<int> parseCount(const std::string& option, const std::string& text, long least, const char* expected) {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || (errno != 0 && errno != ERANGE) || value < least) {
        return makeError(option, std::string("expected ") + expected + ", got '" + text + "'");
    }
    if (errno == ERANGE || value > kMaxCountOption) {
        return makeError(option, "at most " + std::to_string(kMaxCountOption) + ", got '" + text + "'");
    }
    return static_cast<int>(value);
}

}  // namespace

Result<int> parsePositiveInt(const std::string& option, const std::string& text) {
    return parseCount(option, text, 1, "a positive integer");
}

Result<int> parseNonNegativeInt(const std::string& option, const std::string& text) {
    return parseCount(option, text, 0, "a non-negative integer");
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

Result<float> parseFloatIn(const std::string& option, const std::string& text, double low, double high) {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value) || value < low || value > high) {
        return makeError(option, "expected a number in [" + formatNumberForMessage(low) + ", " + formatNumberForMessage(high) +
                                     "], got '" + text + "'");
    }
    return static_cast<float>(value);
}

Result<std::vector<float>> parseSequence(const std::string& option, const std::string& text, size_t maxFrames) {
    const size_t first = text.find(':'), second = first == std::string::npos ? first : text.find(':', first + 1);
    if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
        return makeError(option, "expected START:END:FPS (seconds, seconds, frames per second), got '" + text + "'");
    auto start = parseFloatIn(option + " START", text.substr(0, first), -kMaxAnimationTimeS, kMaxAnimationTimeS);
    if (!start.ok()) return start.error();
    auto end = parseFloatIn(option + " END", text.substr(first + 1, second - first - 1), -kMaxAnimationTimeS, kMaxAnimationTimeS);
    if (!end.ok()) return end.error();
    auto fps = parsePositiveFloat(option + " FPS", text.substr(second + 1));
    if (!fps.ok()) return fps.error();
    if (*end < *start) return makeError(option, "END " + text.substr(first + 1, second - first - 1) + " is before START");
    // Half a frame of slack so that 0:1:30 ends on 1 s despite rounding.
    const double count = std::floor((double(*end) - double(*start)) * double(*fps) + 0.5) + 1.0;
    if (count > double(maxFrames))
        return makeError(option, "gives " + formatNumberForMessage(count) + " frames; at most " + std::to_string(maxFrames));
    std::vector<float> times;
    for (size_t i = 0; i < static_cast<size_t>(count); ++i) times.push_back(static_cast<float>(double(*start) + double(i) / double(*fps)));
    return times;
}

Result<gl::Backend> parseBackend(const std::string& name) {
    if (name == "auto") return gl::Backend::Auto;
    if (name == "egl") return gl::Backend::Egl;
    if (name == "osmesa") return gl::Backend::OsMesa;
    return makeError("--backend " + name, "expected egl or osmesa");
}

int failure(const Error& error) {
    log::error(error.message());
    // A value given on the command line that the scene refuses (--set PATH=VALUE) is a usage error.
    const bool override = error.where.rfind("--set ", 0) == 0 || error.where.rfind("--set-b ", 0) == 0;
    return override ? 2 : 1;
}

int usageError(const Error& error) {
    log::error(error.message());
    return 2;
}

}  // namespace dermis::cli
