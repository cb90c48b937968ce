#include "plan/EnvironmentPlan.h"

#include "core/Log.h"
#include "env/IrradianceMap.h"
#include "env/RingingFreeSh.h"

#include <cmath>
#include <cstdio>

namespace dermis {
namespace {

// The largest region taken out: the cone of the widest sized light a scene may have.
float maxExtractedSolidAngleSr() {
    return float(2.0 * 3.14159265358979323846 * (1.0 - std::cos(glm::radians(0.5 * kMaxLightAngularDiameterDeg))));
}

std::string describe(const ExtractedLight& light) {
    const glm::vec2 uv = latLongUv(light.towardsLight);
    char text[256];
    std::snprintf(text, sizeof text,
                  "a light of %.3g deg (%d texels, %.3g sr) at u %.3f v %.3f, irradiance %.4g %.4g %.4g, fill %.3g %.3g %.3g",
                  double(light.angularDiameterDeg), light.texels, double(light.solidAngleSr), double(uv.x), double(uv.y),
                  double(light.irradiance.r), double(light.irradiance.g), double(light.irradiance.b), double(light.fill.r),
                  double(light.fill.g), double(light.fill.b));
    return text;
}

}  // namespace

LightExtractionSettings lightExtractionSettings(const Environment& environment, size_t sceneLights) {
    LightExtractionSettings settings;
    settings.thresholdOverMean = environment.extractThreshold;
    settings.maxSolidAngleSr = maxExtractedSolidAngleSr();
    const bool room = sceneLights < size_t(DERMIS_MAX_LIGHTS);
    settings.maxLights = environment.extractLight == EnvironmentLightExtraction::Auto && room ? 1 : 0;
    return settings;
}

bool operator==(const LightExtractionSettings& a, const LightExtractionSettings& b) {
    return a.thresholdOverMean == b.thresholdOverMean && a.maxSolidAngleSr == b.maxSolidAngleSr &&
           a.maxLights == b.maxLights;
}

std::shared_ptr<const EnvironmentLight> splitEnvironmentLight(std::string source, Image map,
                                                              const LightExtractionSettings& extraction) {
    auto light = std::make_shared<EnvironmentLight>();
    light->source = std::move(source);
    light->extraction = extraction;
    if (extraction.maxLights > 0) {
        EnvironmentSplit split = extractDominantLights(map, extraction);
        for (const ExtractedLight& extracted : split.lights) log::info("environment '" + light->source + "': " + describe(extracted));
        if (split.lights.empty()) log::info("environment '" + light->source + "': no light taken out: " + split.why);
        light->extracted = std::move(split.lights);
        if (!light->extracted.empty()) light->remainder = std::move(split.remainder);
    }
    light->map = std::move(map);
    const SplitSh split = projectLatLongSplit(light->lit());
    light->mapSh = split.total();
    light->mapSmoothSh = split.smooth;
    light->irradiancePowers = makeIrradiancePowerMaps(light->lit());
    return light;
}

Light worldLight(const ExtractedLight& extracted, const glm::mat3& worldFromMap, float intensity) {
    Light light;
    light.type = LightType::Directional;
    light.direction = -glm::normalize(worldFromMap * extracted.towardsLight);
    light.colour = extracted.irradiance;
    light.intensity = intensity;
    light.castsShadow = true;
    light.angularDiameterDeg = extracted.angularDiameterDeg;
    return light;
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
    // Map space to world space, times the intensity, with the scene's bands.
    auto toWorld = [&](const Sh9& mapSpace) {
        Sh9 world = rotateSh(keepShBands(mapSpace, environment.shBands), plan.worldFromMap);
        for (glm::vec3& c : world.coefficients) c *= environment.intensity;
        return world;
    };
    plan.worldSh = toWorld(plan.light->mapSh);
    const Sh9 smooth = toWorld(plan.light->mapSmoothSh);
    for (int i = 0; i < kShCoefficients; ++i)
        plan.worldHotSh.coefficients[size_t(i)] = plan.worldSh.coefficients[size_t(i)] - smooth.coefficients[size_t(i)];
    for (const ExtractedLight& extracted : plan.light->extracted)
        plan.lights.push_back(worldLight(extracted, plan.worldFromMap, environment.intensity));
    plan.transfer = environment.occlusion == EnvironmentOcclusion::Transfer;
    plan.skybox = environment.background && drawsColour;
    if (!plan.transfer) return plan;  // only the vertices' transfer reads the object-space light
    for (const glm::mat4& m : worldFromObject) {
        // The rotation of a uniformly scaled transform: its columns over their length.
        const glm::mat3 linear(m);
        const glm::mat3 rotation(glm::normalize(linear[0]), glm::normalize(linear[1]), glm::normalize(linear[2]));
        // The transfer takes the smooth part; the hot part is lit at the normal (worldHotSh).
        plan.objectSh.push_back(rotateSh(smooth, glm::transpose(rotation)));
    }
    return plan;
}

}  // namespace dermis
