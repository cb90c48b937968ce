#pragma once
// The environment light of a frame (scene/Scene.h Environment,
// docs/environment.md), planned on the CPU: the map's nine SH coefficients
// turned into world space at the frame's time and scaled by the intensity,
// the same light in each character's object space (for the per-vertex
// transfer, which is in object space), the dominant light taken out of the
// map (env/DominantLight.h) as a scene light in world space, and which
// passes need what.

#include "core/Image.h"
#include "core/Result.h"
#include "env/DominantLight.h"
#include "env/SphericalHarmonics.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace dermis {

// What a scene's environment source gives, loaded once per source and
// split once per extraction setting (render/SceneLoading.h), in map
// space and unscaled: the radiance map, the lights taken out of it, and the
// SH of what is left.
struct EnvironmentLight {
    std::string source;
    Image map;  // as loaded: the skybox shows it
    LightExtractionSettings extraction;       // what the split was made with
    std::vector<ExtractedLight> extracted;    // empty: nothing was taken out
    Image remainder;                          // the map without them; empty when nothing was taken out
    Sh9 mapSh;                                // projectLatLongWithoutRinging(lit()): smooth + hot
    Sh9 mapSmoothSh;                          // its smooth part alone (env/RingingFreeSh.h)
    std::vector<Image> irradiancePowers;      // makeIrradiancePowerMaps(lit()): [0] the exact diffuse light per normal

    // What the diffuse and specular environment light is made from.
    const Image& lit() const { return extracted.empty() ? map : remainder; }
};

// The extraction a scene asks for: none when `extract_light` is off or the
// frame's light list (the scene's first DERMIS_MAX_LIGHTS lights) is full.
LightExtractionSettings lightExtractionSettings(const Environment& environment, size_t sceneLights);
bool operator==(const LightExtractionSettings& a, const LightExtractionSettings& b);

// Splits a loaded map (logs what was taken out, or why nothing was).
std::shared_ptr<const EnvironmentLight> splitEnvironmentLight(std::string source, Image map,
                                                              const LightExtractionSettings& extraction);

// The world-space directional light of an extracted one at the frame: turned
// with the map, scaled by the intensity, casting a shadow.
Light worldLight(const ExtractedLight& extracted, const glm::mat3& worldFromMap, float intensity);

struct EnvironmentPlan {
    std::shared_ptr<const EnvironmentLight> light;  // null: the frame has no environment
    glm::mat3 worldFromMap{1.0f};
    Sh9 worldSh;                 // radiance x intensity, world space, 0 past the scene's sh_bands
    Sh9 worldHotSh;              // worldSh's hot part (env/RingingFreeSh.h), lit at the normal under `transfer`
    std::vector<Sh9> objectSh;   // per character: the smooth part (worldSh - worldHotSh) in its object space; empty unless `transfer`
    std::vector<Light> lights;   // the extracted lights in world space, appended to the frame's lights
    bool transfer = false;       // occlusion "transfer": the vertices carry SH transfer, the G-buffer its L.T
    bool skybox = false;         // the skybox pass draws the map behind everything

    bool enabled() const { return light != nullptr; }
};

// worldFromObject per character (CharacterPlacement::worldFromObject); `drawsColour`:
// the frame's output shows the final or radiance image (the skybox can show).
EnvironmentPlan planEnvironment(const Environment& environment, std::shared_ptr<const EnvironmentLight> light,
                                const std::vector<glm::mat4>& worldFromObject, float timeS, bool drawsColour);

// The coefficients of bands below `bands` kept, the others zeroed.
Sh9 keepShBands(const Sh9& sh, int bands);

}  // namespace dermis
