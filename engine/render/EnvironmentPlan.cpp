#include "render/EnvironmentPlan.h"

#include "core/Log.h"
#include "import/EnvironmentSource.h"

namespace dermis {

Result<std::shared_ptr<const EnvironmentLight>> loadEnvironmentLight(const Environment& environment) {
    auto map = loadEnvironmentSource(environment);
    if (!map.ok()) return map.error();
    auto light = std::make_shared<EnvironmentLight>();
    light->source = environment.source;
    light->mapSh = projectLatLong(*map);
    light->map = std::move(*map);
    log::info("environment '" + environment.source + "': " + std::to_string(light->map.width) + "x" +
              std::to_string(light->map.height));
    return std::shared_ptr<const EnvironmentLight>(std::move(light));
}

Sh9 keepShBands(const Sh9& sh, int bands) {
    Sh9 kept;
    for (int i = 0; i < kShCoefficients && i < bands * bands; ++i) kept.coefficients[size_t(i)] = sh.coefficients[size_t(i)];
    return kept;
}

EnvironmentPlan planEnvironment(const Environment& environment, std::shared_ptr<const EnvironmentLight> light,
                                const std::vector<glm::mat4>& worldFromObject, float timeS, bool drawsColour) {
    EnvironmentPlan plan;
    if (!environment.enabled() || !light) return plan;
    plan.light = std::move(light);
    plan.worldFromMap = environment.worldFromMap(timeS);
    Sh9 world = rotateSh(keepShBands(plan.light->mapSh, environment.shBands), plan.worldFromMap);
    for (glm::vec3& c : world.coefficients) c *= environment.intensity;
    plan.worldSh = world;
    plan.transfer = environment.occlusion == EnvironmentOcclusion::Transfer;
    plan.skybox = environment.background && drawsColour;
    if (!plan.transfer) return plan;  // only the vertices' transfer reads the object-space light
    for (const glm::mat4& m : worldFromObject) {
        // The rotation of a uniformly scaled transform: its columns over their length.
        const glm::mat3 linear(m);
        const glm::mat3 rotation(glm::normalize(linear[0]), glm::normalize(linear[1]), glm::normalize(linear[2]));
        plan.objectSh.push_back(rotateSh(world, glm::transpose(rotation)));
    }
    return plan;
}

}  // namespace dermis
