#include "import/EnvironmentSource.h"

#include "env/EnvironmentMap.h"

namespace dermis {

Result<Image> loadEnvironmentSource(const Environment& environment) {
    if (!environment.enabled()) return makeError("environment", "no source: the scene has no environment");
    if (isBuiltInEnvironment(environment.source)) return makeBuiltInEnvironment(environment.source);
    return loadEnvironmentMap(environment.source);
}

}  // namespace dermis
