#pragma once
// The environment light of a frame (scene/Scene.h Environment,
// docs/environment.md), planned on the CPU: the map's nine SH coefficients
// turned into world space at the frame's time and scaled by the intensity,
// the same light in each character's object space (for the per-vertex
// transfer, which is in object space), and which passes need what.

#include "core/Image.h"
#include "core/Result.h"
#include "env/SphericalHarmonics.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace dermis {

// What a scene's environment source gives, loaded once per source
// (SceneGeometry::environment): the radiance map in map space and its SH.
struct EnvironmentLight {
    std::string source;
    Image map;
    Sh9 mapSh;  // projectLatLong(map), unscaled
};

Result<std::shared_ptr<const EnvironmentLight>> loadEnvironmentLight(const Environment& environment);

struct EnvironmentPlan {
    std::shared_ptr<const EnvironmentLight> light;  // null: the frame has no environment
    glm::mat3 worldFromMap{1.0f};
    Sh9 worldSh;                 // radiance x intensity, world space, 0 past the scene's sh_bands
    std::vector<Sh9> objectSh;   // per character: worldSh in its object space; empty unless `transfer`
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
