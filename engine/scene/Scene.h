#pragma once
// The scene description that content/scenes/*.json files map onto, one field
// per JSON key (see content/scenes/README.md for the file format). Units are
// metres for world space; each character's mesh is in its own units, scaled by
// metresPerUnit. Angles in the file are degrees.

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

struct Camera {
    glm::vec3 positionM{0.0f, 0.0f, 1.0f};
    glm::vec3 targetM{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDeg = 30.0f;
    float nearM = 0.05f;
    float farM = 50.0f;
};

enum class LightType { Directional, Spot, Point };

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 positionM{0.0f, 0.0f, 1.0f};  // spot and point
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // directional and spot: the way the light travels
    glm::vec3 colour{1.0f};                   // linear RGB
    float intensity = 1.0f;                   // directional: irradiance scale; spot/point: radiant intensity (1/r^2 applies)
    float spotInnerDeg = 20.0f;               // full-intensity half-angle
    float spotOuterDeg = 30.0f;               // zero-intensity half-angle
    bool castsShadow = true;
};

struct Transform {
    glm::vec3 translationM{0.0f};
    glm::vec3 rotationDeg{0.0f};  // XYZ Euler angles, applied X then Y then Z
    float scale = 1.0f;           // uniform; applied to the mesh after metresPerUnit

    glm::mat4 worldFromObject(float metresPerUnit) const;
};

struct MeshSource {
    std::string procedural;  // "head", "plane", "sphere", "wedge"; empty when gltfPath is set
    std::string gltfPath;    // .gltf or .glb, absolute or relative to the scene file
};

struct Material {
    // Maps: a path (relative to the scene file) or empty. An empty albedo or
    // normal map on a procedural mesh means "the procedural one" when
    // `procedural` is true, and "none" otherwise.
    std::string albedoMap;
    std::string normalMap;
    bool flipV = false;  // sample maps at (u, 1 - v): for meshes with OpenGL-convention UVs
    bool procedural = false;
    glm::vec3 albedo{0.8f, 0.6f, 0.5f};  // linear; multiplies the albedo map
    float roughness = 0.3f;              // Beckmann m (seed 000 §2.3)
    float rhoS = 0.18f;                  // specular intensity rho_s
    std::string profile = "skin";        // diffusion profile name, or "none" for an opaque material
};

struct Character {
    std::string name;
    Transform transform;
    MeshSource mesh;
    float metresPerUnit = 1.0f;
    Material material;
};

struct Background {
    glm::vec3 colour{0.05f, 0.05f, 0.06f};  // linear RGB radiance behind everything
};

// Settings of the frame itself; later issues add SSS, SSAO and LEAN knobs here.
struct RenderSettings {
    float exposure = 1.0f;
    glm::vec3 ambient{0.03f};       // uniform ambient irradiance (linear RGB)
    int shadowMapSize = 1024;
    float shadowBiasConstant = 0.0005f;  // in light-space depth units [0,1]
    float shadowBiasSlope = 2.0f;        // multiplies the depth slope (glPolygonOffset factor)
    std::string shadowFilter = "pcf4x4";  // "pcf4x4" (seed 000) or "poisson" (seed 003)
};

struct Scene {
    std::string path;  // the file it came from, for error messages and relative paths
    Camera camera;
    std::vector<Light> lights;
    std::vector<Character> characters;
    Background background;
    RenderSettings settings;
};

}  // namespace dermis
