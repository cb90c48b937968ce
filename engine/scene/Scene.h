#pragma once
// The scene description that content/scenes/*.json files map onto, one field
// per JSON key (see content/scenes/README.md for the file format). Units are
// metres for world space; each character's mesh is in its own units, scaled by
// metresPerUnit. Angles in the file are degrees.

#include "core/Limits.h"
#include "core/Result.h"
#include "scene/SceneEnums.h"
#include "scene/QualityTable.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <map>
#include <string>
#include <string_view>
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

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 positionM{0.0f, 0.0f, 1.0f};  // spot and point
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // directional and spot: the way the light travels
    glm::vec3 colour{1.0f};                   // linear RGB
    float intensity = 1.0f;                   // directional: irradiance scale; spot/point: radiant intensity (1/r^2 applies)
    float spotInnerDeg = 20.0f;               // full-intensity half-angle
    float spotOuterDeg = 30.0f;               // zero-intensity half-angle
    bool castsShadow = true;
    // The light's size (docs/shadows.md): 0 is a delta light with a hard shadow.
    float angularDiameterDeg = 0.0f;  // directional: the disc of directions it comes from (the sun: 0.53)
    float radiusM = 0.0f;             // spot and point: the radius of the emitting sphere
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

// Material::profile of an opaque material (no subsurface scattering).
inline constexpr std::string_view kOpaqueProfile = "none";

struct Material {
    // Maps: a path (relative to the scene file) or empty. An empty albedo or
    // normal map on a procedural mesh means "the procedural one" when
    // `procedural` is true, and "none" otherwise.
    std::string albedoMap;
    std::string normalMap;
    bool flipV = false;  // sample maps at (u, 1 - v): for meshes with OpenGL-convention UVs
    // false drops every normal map of the material, the mesh file's and normalMap
    // alike, in the renderer and the CPU reference: the normal map's share of an
    // error (docs/bench.md, "Error by ingredient").
    bool useNormalMap = true;
    bool procedural = false;
    glm::vec3 albedo{0.8f, 0.6f, 0.5f};  // linear; multiplies the albedo map
    float roughness = 0.3f;              // Beckmann m (Chappuis 2011 §2.3)
    float rhoS = 0.18f;                  // specular intensity rho_s
    std::string profile = "skin";        // diffusion profile name (built-in or Scene::profiles), or "none" for an opaque material
    float widthScale = 1.0f;             // multiplies settings.sss.widthScale for this material's scattering
    // Grey images (paths, relative to the scene file) or empty: the roughness
    // map gives Beckmann m itself, the specular map multiplies rhoS.
    std::string roughnessMap;
    std::string specularMap;
    // How much of the material scatters (docs/materials.md, "Skin only where
    // there is skin"): the outgoing diffuse light is (1 - s) x the local
    // light + s x the scattered light, s = scatter x the scatter map's red
    // channel; 0 keeps the surface sharp and stops its transmittance.
    float scatter = 1.0f;
    std::string scatterMap;  // a grey image (path, relative to the scene file) or empty
    // This object gave `profile`, `scatter` or `scatter_map` itself: a
    // `materials` entry then decides its material's scattering over what the
    // file says (import/MaterialScattering.h).
    bool scatteringGiven = false;
};

// Per-character SSAO overrides (Papanikolaou 2013 §3: radius and sample count per object).
struct CharacterSsao {
    float radiusM = 0.0f;  // world-space hemisphere radius; 0 = use settings.ssao.radius_m
    int samples = 0;       // kMinSsaoSamples..kMaxSsaoSamples; 0 = use settings.ssao.samples
};

// Character::animation::clip naming no clip: the rest pose.
inline constexpr std::string_view kRestPoseClip = "none";

// Which clip of the character's glTF plays, and where in it (anim/Rig.h).
// The clip time of a frame rendered at time t (FrameRequest::timeS) is
// timeS + speed x t, wrapped into the clip when looping, clamped otherwise.
struct CharacterAnimation {
    std::string clip;  // a clip name; empty = the file's first clip; "none" = the rest pose
    float timeS = 0.0f;
    float speed = 1.0f;
    bool loop = true;
};

struct Character {
    std::string name;
    Transform transform;
    MeshSource mesh;
    float metresPerUnit = 1.0f;
    Material material;  // every primitive's, unless `materials` names its glTF material
    // Per glTF material name: the material its primitives use instead (each
    // starts as a copy of `material`, then the keys given replace fields).
    std::map<std::string, Material> materials;
    CharacterSsao ssao;
    CharacterAnimation animation;
};

struct Background {
    glm::vec3 colour{0.05f, 0.05f, 0.06f};  // linear RGB radiance behind everything
};

// Environment light (docs/environment.md): a lat-long radiance map around the
// scene, for diffuse light through nine SH coefficients (Ramamoorthi &
// Hanrahan 2001) and specular light through a prefiltered map. Absent from a
// scene (source empty), the frame has the uniform settings.ambient only.
// The environments the engine makes itself (env/EnvironmentMap.h), so that a
// scene needs no file; any other `source` is a map file.
inline constexpr std::string_view kBuiltInEnvironments[] = {"sky", "studio", "uniform"};
bool isBuiltInEnvironment(const std::string& source);

struct EnvironmentRotation {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};  // normalised by the loader
    float angleDeg = 0.0f;              // at time 0
    float speedDegPerS = 0.0f;          // the angle grows by this per second of scene time
};

struct Environment {
    std::string source;  // empty: none; a built-in (kBuiltInEnvironments) or a map file (resolved path)
    float intensity = 1.0f;  // multiplies the map's radiance
    EnvironmentRotation rotation;  // world(d) = R map(d): the map turned about `axis` by the angle
    bool background = true;        // draw the map behind everything (the skybox pass), else background.colour
    EnvironmentOcclusion occlusion = EnvironmentOcclusion::Transfer;  // what darkens the environment's diffuse light
    EnvironmentSpecular specular = EnvironmentSpecular::Prefiltered;
    EnvironmentDiffuse diffuse = EnvironmentDiffuse::Map;
    int shBands = kMaxShBands;  // SH bands of the diffuse light, 1..3 (1, 4 or 9 coefficients): diffuse "sh", and the transfer
    // The dominant light (env/DominantLight.h): with Auto, the brightest region
    // whose texels reach extractThreshold x the mean luminance, if compact,
    // lights the frame as a directional light of its size (threshold: a multiple of the mean luminance).
    EnvironmentLightExtraction extractLight = EnvironmentLightExtraction::Auto;
    float extractThreshold = 8.0f;

    bool enabled() const { return !source.empty(); }
    // The rotation from map directions to world directions at scene time t.
    glm::mat3 worldFromMap(float timeS) const;
};

// Screen-space SSS (docs/screen-space.md, step 6; Chappuis 2011 §2.2.4, Vila Verde 2015 §3.2.2 and §4.3.2).
struct SssSettings {
    bool enabled = true;
    SssVariant variant = SssVariant::Lbb;  // Vila Verde 2015 §5.1 (kSssVariants; plan/SssVariant.h)
    SssBlur blur = SssBlur::Variant;        // edge handling (kSssBlurs)
    SssTechnique technique = SssTechnique::Gaussians;  // kSssTechniques
    int separableSamples = 17;           // separable: samples per direction, odd, kMinSeparableSamples..kMaxSeparableSamples
    int diskSamples = 40;                // disk: samples per pixel, kMinDiskSamples..kMaxDiskSamples
    int taps = 9;                        // gaussians: taps per direction, odd, kMinBlurTaps..kMaxBlurTaps
    float bilateralDepthMm = 1.0f;       // std dev of the Gaussian in tap-to-centre depth difference (mm)
    float controlDepthScalePerMm = 0.5f;  // control: lerp to centre by min(1, scale * |depth difference| in mm)
    int gaussians = 6;                   // gaussians: use at most this many of each profile's Gaussians (the widest are dropped)
    float widthScale = 1.0f;             // multiplies every profile's widths (1 = physical)
    float minWidthPx = 0.5f;             // skip a Gaussian narrower than this (std dev, pixels) at the nearest SSS pixel
    float mix = 0.5f;                    // pre-/post-scatter albedo mix (Chappuis 2011 §2.2.4): albedo^mix before the blur
    float leanMomentWidthMm = 0.6f;      // lcb/lbb: LEAN moments ride through the Gaussians up to this std dev (0 = all; plan/SssVariant.h)
};

// Light carried through thin regions from the lit surface behind them (shaders/include/Transmittance.glsl).
struct TransmittanceSettings {
    bool enabled = true;
    float shrinkMm = 0.0f;   // the surface point moves this far inwards along -N before its thickness is read
    float strength = 1.0f;   // multiplies the transmitted light
    bool thinEdges = true;   // taps past the outline of a thin part take its hidden side's light (shaders/include/ThinEdges.glsl)
};

// Screen-space ambient occlusion (Papanikolaou 2013 §3): a normal-oriented hemisphere.
struct SsaoSettings {
    bool enabled = true;
    int samples = 16;       // kMinSsaoSamples..kMaxSsaoSamples (per-character override: Character::ssao)
    float radiusM = 0.02f;  // world-space radius (per-character override)
    float strength = 1.0f;  // AO = 1 - strength * occlusion
    bool blur = true;       // bilateral blur of the raw AO
};

struct ShadowSettings {
    int mapSize = 1024;              // kMinShadowMapSize..kMaxShadowMapSize
    float biasConstantM = 0.0005f;   // constant depth bias, metres along the light's axis
    float biasSlopeTexels = 2.0f;    // slope-scaled bias: this many shadow texels times tan(angle to the light)
    ShadowFilter filter = ShadowFilter::Pcss;  // kShadowFilters; pcss is pcf4x4 for delta lights
};

// Texture-space SSS (d'Eon & Luebke, Chappuis 2011 §2.2-§2.8; docs/texture-space.md).
struct TextureSpaceSettings {
    int taps = 7;              // taps per 1-D blur pass (Chappuis 2011 §2.2.4 uses seven), odd, kMinBlurTaps..kMaxBlurTaps
    int minSize = 256;         // irradiance texture side in texels, a power of two: the screen coverage
    int maxSize = 2048;        // picks a power of two within [minSize, maxSize]
    bool tsm = false;          // the modified translucent shadow map carries light through thin regions (Chappuis 2011 §2.5)
                               // instead of the transmittance both modes share (include/Transmittance.glsl)
    float tsmStrength = 1.0f;  // multiplies the TSM's global-scattering terms (1 = as the profile predicts)
    float seamBlend = 2.0f;    // a Gaussian gives way to local diffuse where a UV chart border is nearer than
                               // this many of its standard deviations (0 = never)
};

// An error budget for the screen-space SSS (docs/quality.md): each character
// gets the cheapest choice a quality table lists for its on-screen scale.
struct QualitySettings {
    float errorBudget = 0.0f;  // 0: off (every character uses settings.sss); else a fraction, e.g. 0.01
    std::string table;         // resolved path of the quality table (scene/QualityTable.h)
    QualityTable loaded;       // read at scene load when errorBudget > 0; not a field of the file
};

// Levels of detail (mesh/MeshLod.h, plan/LevelOfDetail.h): each visible
// character draws the coarsest level whose error against the full mesh,
// projected on screen, is at most maxErrorPx pixels; 0 (the default) draws
// full meshes. Off by default: a level's shading differs from the full
// mesh's by more than its geometric error suggests (docs/crowds.md).
struct LodSettings {
    float maxErrorPx = 0.0f;
};

// Settings of the frame itself.
struct RenderSettings {
    SssMode mode = SssMode::ScreenSpace;  // kSssModes
    float exposure = 1.0f;
    ToneMap toneMap = ToneMap::Aces;  // of the final image (shaders/tonemap.frag)
    glm::vec3 ambient{0.03f};  // uniform ambient irradiance (linear RGB); SSAO darkens it
    bool energyConservation = true;  // Chappuis 2011 §2.6: diffuse x (1 - rho_s rho_dt) in and out
    // The G-buffer culls the back faces of closed meshes seen from outside
    // (mesh/MeshTopology.h, passes/GBufferPass.cpp): the same image, less work.
    bool cullBackFaces = true;
    ShadowSettings shadow;
    SssSettings sss;
    TransmittanceSettings transmittance;
    SsaoSettings ssao;
    TextureSpaceSettings ts;
    QualitySettings quality;
    LodSettings lod;
};

struct Scene {
    std::string path;  // the file it came from, for error messages and relative paths
    Camera camera;
    std::vector<Light> lights;
    std::vector<Character> characters;
    std::vector<DiffusionProfile> profiles;  // user profiles, by name; never "skin", "marble" or "none"
    Background background;
    Environment environment;
    RenderSettings settings;
};

// The material a character's primitives with this glTF material name use:
// its `materials` entry, else its `material`.
// `cause`, found while loading what the scene file's key `pointer` names (a
// JSON pointer: "/environment/source"), as an error that names the scene
// file and the key first: "SCENE: /environment/source: FILE: problem".
Error atSceneKey(const Scene& scene, const std::string& pointer, const Error& cause);

// Why nothing but the ambient term lights the scene ("no light and no
// environment", ...), or "" when a light or the environment does: such a
// scene renders (nearly) black, which deserves a warning, not an error.
std::string unlitSceneReason(const Scene& scene);

const Material& characterMaterial(const Character& character, const std::string& gltfMaterialName);
// The scene's own entry for the character's glTF material `index` (named
// `gltfMaterialName`): `materials` by that name, else by "#index"; null when
// the scene names neither. characterMaterial() with the index.
const Material* sceneMaterialEntry(const Character& character, const std::string& gltfMaterialName, size_t index);
const Material& characterMaterial(const Character& character, const std::string& gltfMaterialName, size_t index);
// "#3" for material 3: how `materials` names a material by index.
std::string materialIndexKey(size_t index);

// A diffusion profile by name: a built-in one or one of the scene's own; the
// error lists every known name.
Result<const DiffusionProfile*> findSceneProfile(const Scene& scene, const std::string& name);

}  // namespace dermis
