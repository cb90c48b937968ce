#include "import/EnvironmentSource.h"

#include "core/Limits.h"
#include "core/Suggest.h"
#include "env/EnvironmentMap.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace dermis {

Result<Image> loadEnvironmentSource(const Environment& environment) {
    if (!environment.enabled()) return makeError("environment", "no source: the scene has no environment");
    if (isBuiltInEnvironment(environment.source)) return makeBuiltInEnvironment(environment.source);
    std::error_code error;
    if (!std::filesystem::exists(environment.source, error)) {
        // Most likely a misspelt built-in: the loader resolved it as a file.
        const std::vector<std::string> builtIn(std::begin(kBuiltInEnvironments), std::end(kBuiltInEnvironments));
        const std::string given = std::filesystem::path(environment.source).filename().string();
        return makeError(environment.source, "no such file, and \"" + given + "\" is not a built-in environment (" +
                                                 "sky, studio or uniform)" + didYouMean(given, builtIn));
    }
    auto map = loadEnvironmentMap(environment.source);
    if (!map) return map;
    // The light a map gives is summed over its texels in float32 (its SH, the
    // lighting): radiance x intensity past a light's limit would overflow to
    // infinity and leave the character black. Refused, as a light would be.
    float brightest = 0.0f;
    for (const glm::vec4& t : map->texels) brightest = std::max({brightest, t.r, t.g, t.b});
    if (double(brightest) * double(environment.intensity) > kMaxLightRadiance) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "radiance up to %.3g x intensity %.3g is above %.0e, the most Dermis sums without overflow "
                      "(scale the map down or lower environment.intensity)",
                      double(brightest), double(environment.intensity), kMaxLightRadiance);
        return makeError(environment.source, line);
    }
    return map;
}

}  // namespace dermis
