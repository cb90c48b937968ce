#pragma once
// The irradiance E at a surface point as the renderer's lighting pass defines it
// (shaders/lighting.frag, include/Lights.glsl, include/EnergyConservation.glsl),
// with exact visibility from shadow rays instead of shadow maps:
//   E = ambient + sum over lights of radiance x max(N.L, 0) x visibility x (1 - rho_s rho_dt(N.L, m))
// - directional: radiance = colour x intensity; spot and point: / r^2, spots
//   fade by smoothstep(cos outer, cos inner, cos angle);
// - the last factor only with settings.energyConservation (Chappuis 2011 §2.6);
// - the ambient is uniform and unoccluded: the renderer darkens it by SSAO, the
//   reference takes AO = 1;
// - the lights the renderer shadows are exactly the ones that cast shadow rays
//   here (engine/plan/LightSetup.cpp: shadow on, the first
//   DERMIS_MAX_SHADOWED_LIGHTS of them, point lights included: a cube map takes
//   one slot); only the first DERMIS_MAX_LIGHTS lights count;
// - a light with a size (Light::angularDiameterDeg, Light::radiusM) is an area
//   light for the visibility only: the visibility is the fraction of
//   kAreaLightSamples shadow rays spread uniformly over its disc of directions
//   (a cone for a directional light, the visible disc of the sphere for spot and
//   point lights) that nothing blocks; radiance, N.L and the spot fade stay those
//   of the light's centre, as in the renderer. A delta light casts one ray.
// - the environment (Scene::environment, when it has a source) adds
//     E_env = intensity x integral over the sphere of L_map(R^T omega) V(omega) max(N.omega, 0)
//             x (1 - rho_s rho_dt(N.omega, m)) d omega,
//   R = worldFromMap(0), V exact visibility through the occluders, the last
//   factor only with settings.energyConservation: the true quantity the
//   renderer's SH irradiance with transfer approximates. It is estimated by
//   multiple importance sampling (Veach 1997 §9.2, the balance heuristic) of the
//   map's luminance (EnvironmentSampling.h) and the cosine-weighted hemisphere,
//   environmentSamples rays per point, with a stratified set that a hash of the
//   point's position shifts (deterministic, independent of threads). The
//   renderer's environment occlusion, specular and SH band settings do not
//   change it: they are its approximations.
// Transmittance (back-lit light through thin parts) is not part of E.

#include "core/Image.h"
#include "core/Result.h"
#include "raytrace/Bvh.h"
#include "reference/CharacterSurface.h"
#include "reference/EnvironmentSampling.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::reference {
using raytrace::Bvh;
using raytrace::BvhHit;
using raytrace::Ray;
}  // namespace dermis::reference

namespace dermis::reference {

// Shadow rays per sized light: 1/64 steps of visibility across a penumbra.
constexpr int kAreaLightSamples = 64;

// Environment rays per shading point by default (half from the map's
// distribution, half cosine-weighted): docs/reference.md gives the noise and
// cost. 16, not more: every sample of the diffusion integral casts them (a
// 160x90 default head took 165 s with 16), and the integral averages the
// independent noise of its many samples per pixel.
constexpr int kEnvironmentSamples = 16;
// The same at the subsurface integral's samples x_i, which each x_o averages by
// thousands: fewer rays each make a pass cheaper but noisier (docs/reference.md,
// "Progressive mode", measures the trade; 16 reaches 0.2 % in the fewest passes).
constexpr int kIntegralEnvironmentSamples = 16;
constexpr int kMinEnvironmentSamples = 2;  // one per technique
constexpr int kMaxEnvironmentSamples = 65536;

// Which lights a sample tested with shadow rays, which of those it saw whole
// (every ray unblocked) and which not at all (every ray blocked). Two samples
// that tested the same light and differ in either lie on either side of a
// shadow edge or inside a penumbra whose visibility changes: the integrator
// refines there.
struct LightVisibility {
    uint64_t tested = 0;
    uint64_t visible = 0;
    uint64_t blocked = 0;

    bool disagreesWith(const LightVisibility& other) const {
        return (((visible ^ other.visible) | (blocked ^ other.blocked)) & tested & other.tested) != 0;
    }
};

class ReferenceLighting {
public:
    // Loads the scene's environment map (loadEnvironmentSource) when it has one:
    // its errors, and an environmentSamples outside [kMinEnvironmentSamples,
    // kMaxEnvironmentSamples], are returned.
    static Result<ReferenceLighting> create(const Scene& scene, const raytrace::TriangleScene& occluders,
                                            int environmentSamples = kEnvironmentSamples);
    // `occluders` must outlive this object. `environmentMap`: the radiance map of
    // scene.environment in map space (the scene's source is not read here), empty
    // for none; the environment's intensity and rotation apply to it.
    // `environmentSamples` is clamped to [kMinEnvironmentSamples, kMaxEnvironmentSamples].
    ReferenceLighting(const Scene& scene, const raytrace::TriangleScene& occluders, Image environmentMap = Image{},
                      int environmentSamples = kEnvironmentSamples);

    // E at the point (energy conservation on the way in included). `sampleSet`
    // picks an independent set of environment rays (0: the default set).
    glm::vec3 irradiance(const SurfacePoint& point, LightVisibility* visibility = nullptr, uint32_t sampleSet = 0) const;
    // E_env alone (0 without an environment).
    glm::vec3 environmentIrradiance(const SurfacePoint& point, uint32_t sampleSet = 0) const;
    bool hasEnvironment() const { return !mEnvironment.empty() && mEnvironmentIntensity > 0.0f; }
    // What it read from files (the environment map), into `hash`; the rest follows
    // from the scene's own values.
    void hashContent(ContentHash& hash) const { mEnvironment.hashContent(hash); }
    // The fraction of light `index` that reaches the point (1 for an unshadowed
    // light), with the light's centre towards `l`; sets its bits in `visibility`.
    float lightVisibility(size_t index, const SurfacePoint& point, const glm::vec3& l, float distanceM,
                          LightVisibility* visibility) const;
    // 1 - rho_s rho_dt(N.V, m) when energy conservation is on, else 1.
    float outgoingFactor(const SurfacePoint& point, const glm::vec3& towardsViewer) const;
    // 1 - rho_s rho_dt(cos, m), bilinear in the renderer's table like the shader.
    float energyLeftForDiffuse(float cosTheta, float roughness, float rhoS) const;

private:
    // Whether something blocks the ray from the point towards the unit `direction`
    // before lengthM (infinity: none); the point's own facets near the terminator
    // do not (ReferenceLighting.cpp).
    bool occluded(const SurfacePoint& point, const glm::vec3& direction, float lengthM) const;

    struct PreparedLight {
        int type = 0;  // DERMIS_LIGHT_*
        glm::vec3 positionM{0.0f};
        glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way the light travels
        glm::vec3 radiance{0.0f};
        float cosInner = 1.0f;
        float cosOuter = 1.0f;
        bool shadowed = false;
        float sinAngularRadius = 0.0f;  // directional: sin of half the angular diameter; 0 = delta
        float radiusM = 0.0f;           // spot and point: the sphere's radius; 0 = delta
    };

    const raytrace::TriangleScene* mOccluders;
    std::vector<PreparedLight> mLights;
    std::vector<glm::vec2> mDiscSamples;  // kAreaLightSamples points, uniform over the unit disc
    glm::vec3 mAmbient{0.0f};
    bool mEnergyConservation = true;
    std::vector<float> mEnergyTable;  // row-major, row = m (engine/brdf/EnergyTable.h)
    EnvironmentDistribution mEnvironment;  // empty: no environment light
    float mEnvironmentIntensity = 0.0f;
    glm::mat3 mWorldFromMap{1.0f};
    std::vector<glm::vec2> mMapSquareSamples;     // unit-square points for the map's technique
    std::vector<glm::vec2> mCosineSquareSamples;  // and for the cosine-weighted one
};

}  // namespace dermis::reference
