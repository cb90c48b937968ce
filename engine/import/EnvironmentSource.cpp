#include "import/EnvironmentSource.h"

#include "core/Limits.h"
#include "env/EnvironmentMap.h"

#include <algorithm>
#include <cstdio>

namespace dermis {

Result<Image> loadEnvironmentSource(const Environment& environment) {
    if (!environment.enabled()) return makeError("environment", "no source: the scene has no environment");
    if (isBuiltInEnvironment(environment.source)) return makeBuiltInEnvironment(environment.source);
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
