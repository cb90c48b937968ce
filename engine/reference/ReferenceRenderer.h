#pragma once
// The CPU reference: brute-force evaluation of what both real-time
// SSS modes approximate (docs/reference.md),
//   L_d(x_o) = albedo^(1-mix)(x_o) x (1 - rho_s rho_dt(N.V, m)) x
//              integral over the character of R(|x_o - x_i|) E(x_i) albedo^mix(x_i) dA_i,
// the outgoing energy factor only with settings.energyConservation, exactly as
// the renderer's composite applies it (shaders/include/OutgoingDiffuse.glsl).
// E is ReferenceLighting's (lights, shadow rays, ambient with AO = 1; no
// transmittance). Characters without a profile, and every character when
// settings.sss.enabled is false, are local: L_d = E(x_o) x albedo(x_o) x the
// outgoing factor. R is the character's profile with settings.sss.widthScale
// applied (variances x scale^2); the real-time knobs (taps, Gaussians used,
// blur mode) are approximations and do not change it.
//
// The output is the `diffuse` AOV of `dermis render`: linear RGB, alpha 1 where
// a surface is hit and 0 (with RGB 0) on the background, one ray per pixel
// centre through the scene camera (glm::lookAt + glm::perspective, OpenGL
// conventions, the near and far planes clip), image rows top first.

#include "core/Image.h"
#include "core/Result.h"
#include "reference/Bvh.h"
#include "reference/CharacterSurface.h"
#include "reference/DiffusionIntegrator.h"
#include "reference/ReferenceLighting.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace dermis::reference {

struct ReferenceOptions {
    QuadratureSettings quadrature;  // density: samples per s^2 for every Gaussian of standard deviation s (> 0)
    int threads = 0;            // 0: one per hardware thread
    bool showProgress = false;  // progress bars on stderr
};

struct ReferenceStats {
    size_t triangles = 0;      // in the ray-tracing BVH (all characters)
    size_t baseCells = 0;      // base tessellation cells, all SSS characters
    size_t shadedBaseCells = 0;  // those the last call needed
    size_t sssHits = 0;        // rays of the last call that landed on an SSS character
};

class ReferenceRenderer {
public:
    // `models` in the order of scene.characters (object units, as loadCharacterModel gives them).
    static Result<ReferenceRenderer> create(const Scene& scene, std::vector<Model> models, const ReferenceOptions& options);
    // Loads every character's model with loadCharacterModel.
    static Result<ReferenceRenderer> load(const Scene& scene, const ReferenceOptions& options);

    // L_d (rgb) and coverage (a) for each ray's nearest hit with tMin < t < tMax.
    std::vector<glm::vec4> diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax);
    // The scene camera's view at width x height.
    Image renderDiffuse(int width, int height);

    // Ray through the centre of pixel (x, y), y = 0 the top row; its direction has
    // view-space z = -1, so t is the view depth in metres.
    static Ray cameraRay(const Camera& camera, int width, int height, int x, int y);

    const ReferenceStats& stats() const { return mStats; }

private:
    struct Hit {
        int character = -1;
        uint32_t triangle = 0;
        float b1 = 0.0f, b2 = 0.0f;
        bool backFacing = false;
    };
    Hit trace(const Ray& ray, float tMin, float tMax) const;
    glm::vec4 shadeHit(const Hit& hit, const Ray& ray, const std::vector<std::vector<Sample>>* baseSamples) const;
    std::vector<glm::vec4> diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax, size_t itemSize);

    Scene mScene;
    ReferenceOptions mOptions;
    std::vector<std::unique_ptr<CharacterSurface>> mSurfaces;
    std::vector<uint32_t> mFirstTriangle;  // per character, into the BVH's triangle order; plus the total
    std::unique_ptr<Bvh> mBvh;
    std::unique_ptr<ReferenceLighting> mLighting;
    std::vector<std::unique_ptr<DiffusionIntegrator>> mIntegrators;  // per character, width-scaled profile (null: local)
    ReferenceStats mStats;
};

}  // namespace dermis::reference
