#pragma once
// Environment maps: latitude-longitude HDR images (env/SphericalHarmonics.h
// gives the layout: +Y up, row 0 at the top, longitude from +Z towards +X),
// read from a file (.hdr, .exr or anything OpenImageIO reads) and checked, or
// made procedurally so that a scene needs no file.

#include "core/Image.h"
#include "core/Result.h"

#include <glm/glm.hpp>

namespace dermis {

// The smallest map accepted: 8 x 4 texels.
constexpr int kMinEnvironmentHeight = 4;

// Loads a lat-long map as linear radiance. Refused, naming the file: an
// unreadable file, a width that is not twice the height, a map smaller than
// 2 kMinEnvironmentHeight x kMinEnvironmentHeight, non-finite or negative
// texels (with their count and the first one's position).
Result<Image> loadEnvironmentMap(const std::string& path);

// The same checks on a map in memory; `name` is used in the errors.
Status checkEnvironmentMap(const Image& map, const std::string& name);

// A built-in sky: a blue zenith fading to a pale horizon, a darker brown
// ground below it, and a sun (a disc of angular radius sunRadiusDeg, radiance
// sunRadiance) towards `sunDirection`. Linear RGB radiance, height x 2 height.
struct ProceduralSky {
    glm::vec3 zenith{0.25f, 0.45f, 0.9f};
    glm::vec3 horizon{0.85f, 0.9f, 1.0f};
    glm::vec3 ground{0.25f, 0.2f, 0.15f};
    glm::vec3 sunDirection{0.4f, 0.6f, 0.7f};  // towards the sun; normalised when used
    glm::vec3 sunRadiance{2000.0f, 1900.0f, 1700.0f};
    float sunRadiusDeg = 0.53f / 2.0f;
};

Image makeProceduralSky(const ProceduralSky& sky, int height);

// A built-in photo studio: dim walls and floor and three soft boxes (key,
// fill, rim), each a spherical cap of `radiance` with a soft edge
// `edgeDeg` wide, so that nine SH coefficients describe it well.
struct SoftBox {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // towards the box; normalised when used
    float radiusDeg = 20.0f;
    glm::vec3 radiance{1.0f};
};

struct ProceduralStudio {
    glm::vec3 walls{0.06f, 0.06f, 0.065f};
    glm::vec3 floor{0.03f, 0.028f, 0.026f};
    SoftBox key{{0.6f, 0.45f, 0.65f}, 22.0f, {5.0f, 4.8f, 4.5f}};
    SoftBox fill{{-0.75f, 0.15f, 0.6f}, 28.0f, {0.9f, 0.95f, 1.1f}};
    SoftBox rim{{-0.2f, 0.55f, -0.8f}, 12.0f, {4.0f, 4.0f, 4.0f}};
    float edgeDeg = 4.0f;
};

Image makeProceduralStudio(const ProceduralStudio& studio, int height);

// The rows of the built-in environments (Scene::kBuiltInEnvironments):
// 512 x 256, texels of 0.7 degrees, finer than any lobe the renderer blurs
// them with (docs/environment.md).
constexpr int kBuiltInEnvironmentHeight = 256;

// The built-in environment of that name ("sky": makeProceduralSky with a sun
// giving about the sky's irradiance; "studio": makeProceduralStudio;
// "uniform": radiance 1 everywhere, the white furnace).
// An unknown name is an error listing the known ones.
Result<Image> makeBuiltInEnvironment(const std::string& name, int height = kBuiltInEnvironmentHeight);

}  // namespace dermis
