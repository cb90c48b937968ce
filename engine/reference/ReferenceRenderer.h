#pragma once
// The CPU reference: brute-force evaluation of what both real-time
// SSS modes approximate (docs/reference.md),
//   L_d(x_o) = albedo^(1-mix)(x_o) x (1 - rho_s rho_dt(N.V, m)) x
//              integral over the character of R(|x_o - x_i|) E(x_i) albedo^mix(x_i) dA_i,
// the outgoing energy factor only with settings.energyConservation, exactly as
// the renderer's composite applies it (shaders/include/OutgoingDiffuse.glsl).
// E is ReferenceLighting's (lights, shadow rays, the environment by multiple
// importance sampling with visibility rays, ambient with AO = 1; no
// transmittance). Characters without a profile, and every character when
// settings.sss.enabled is false, are local: L_d = E(x_o) x albedo(x_o) x the
// outgoing factor. R is the character's profile with settings.sss.widthScale
// applied (variances x scale^2); the real-time knobs (taps, Gaussians used,
// blur mode) are approximations and do not change it.
//
// The output is the `diffuse` AOV of `dermis render`: linear RGB, image rows top
// first, through the scene camera (PixelSampling.h; the near and far planes clip).
// Each pixel is the box-filtered mean of its sub-samples (samplesPerPixel, an
// n x n jittered grid; 1 is the pixel centre): alpha is the fraction that hit a
// surface, RGB the mean over all of them with the background counting 0, so it
// compares with the engine where alpha is 1. Maps are read trilinearly at the
// level of detail of one whole pixel's footprint at each sub-sample's hit, as
// the GPU reads them per pixel; the sub-samples average geometry, not texels.
//
// The matched-irradiance mode (docs/reference.md): with the engine's own
// texture-space irradiance of a character, renderScatterChange gives
//   Delta = albedo^(1-mix)(x_o) x outgoing(x_o) x [integral of R(|x_o - x_i|) E~(x_i) dA_i - E~(x_o)],
// E~ the engine's integrand (E x albedo^mix) read from its texture, so that
// "engine diffuse with SSS off + Delta" is the engine's own light scattered
// exactly: its difference from the engine with SSS on is the SSS technique's error.

#include "core/Image.h"
#include "core/Result.h"
#include "raytrace/Bvh.h"
#include "raytrace/EmbreeBvh.h"
#include "reference/CharacterSurface.h"
#include "reference/DiffusionIntegrator.h"
#include "reference/EngineIrradiance.h"
#include "reference/PixelSampling.h"
#include "reference/ReferenceLighting.h"
#include "reference/SampleMemo.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <limits>
#include <memory>
#include <vector>

namespace dermis::reference {
using raytrace::Bvh;
using raytrace::BvhHit;
using raytrace::Ray;
}  // namespace dermis::reference

namespace dermis::reference {

// The default sub-samples per pixel (docs/reference.md: the convergence table).
constexpr int kDefaultSamplesPerPixel = 4;

struct ReferenceOptions {
    QuadratureSettings quadrature;  // density: samples per s^2 for every Gaussian of standard deviation s (> 0)
    int samplesPerPixel = kDefaultSamplesPerPixel;  // a perfect square n^2, 1 to kMaxSamplesPerPixel
    // rays per shading point for the environment's light (ReferenceLighting.h), kMinEnvironmentSamples
    // to kMaxEnvironmentSamples; unused without an environment
    int environmentSamples = kEnvironmentSamples;
    // the same for each sample x_i of the subsurface integral (ReferenceLighting.h); same range
    int integralEnvironmentSamples = kIntegralEnvironmentSamples;
    // per character (scene order); an empty Image = this character uses the exact lighting
    std::vector<Image> engineIrradiance;   // empty: none at all (EngineIrradiance.h for the layout)
    // The fast path (Embree, each sample's value computed once) and the slow one it
    // replaced (the in-house BVH, every value computed where it is needed), kept to check it.
    bool embree = true;
    bool sampleMemo = true;
    int threads = 0;            // 0: one per hardware thread
    bool showProgress = false;  // progress bars on stderr
};

// The progressive mode's default goal: the estimated relative RMSE of the
// image's sampling noise over its covered pixels (docs/reference.md).
constexpr double kDefaultTargetRelativeRmse = 0.002;
constexpr int kMaxProgressivePasses = 64;
constexpr int kDefaultProgressivePasses = 8;

struct ProgressiveSettings {
    double targetRelativeRmse = kDefaultTargetRelativeRmse;  // > 0
    int maxPasses = kDefaultProgressivePasses;                // 1 to kMaxProgressivePasses
};

struct ReferenceStats {
    size_t triangles = 0;      // in the ray-tracing BVH (all characters)
    size_t baseCells = 0;      // base tessellation cells, all SSS characters
    size_t buriedTriangles = 0;      // inside the body, all characters (SurfaceInterior.h)
    size_t straddlingTriangles = 0;  // across the body's boundary
    size_t shadedBaseCells = 0;  // those the last call needed
    size_t sssHits = 0;        // rays (sub-samples) of the last call that landed on an SSS character
    size_t emptyIrradianceReads = 0;  // engine irradiance reads with no covered texel in reach, all calls
    size_t sampleLookups = 0;  // exact-lighting values the integral asked for, all calls
    size_t sampleMemoHits = 0;  // those already computed (SampleMemo.h)
    // Wall seconds of the last call's stages: the rays' nearest hits, the base
    // cells' samples, the rest (the integral per sub-sample, its finer cells).
    double traceSeconds = 0.0;
    double baseCellSeconds = 0.0;
    double scatterSeconds = 0.0;
    // The last progressive render: full passes taken and the estimated relative
    // RMSE of its noise (0 without an environment: one pass).
    int passes = 0;
    double estimatedRelativeRmse = 0.0;
};

// renderThicknessMm where the ray through the part leaves without meeting the character again.
constexpr float kNoExitThicknessMm = std::numeric_limits<float>::infinity();

class ReferenceRenderer {
public:
    // `models` in the order of scene.characters (object units, as loadCharacterModel gives them).
    static Result<ReferenceRenderer> create(const Scene& scene, std::vector<Model> models, const ReferenceOptions& options);
    // Loads every character's model with loadCharacterModel.
    static Result<ReferenceRenderer> load(const Scene& scene, const ReferenceOptions& options);

    // L_d (rgb) and coverage (a) for each ray's nearest hit with tMin < t < tMax;
    // maps at level 0 (a bare ray has no pixel footprint).
    std::vector<glm::vec4> diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax);
    // Delta (rgb, 0 where it does not apply) and coverage (a), likewise.
    std::vector<glm::vec4> scatterChangeAlongRays(const std::vector<Ray>& rays, float tMin, float tMax);
    // The scene camera's view at width x height, samplesPerPixel sub-samples each.
    Image renderDiffuse(int width, int height);
    // The rows [firstRow, firstRow + rowCount) of renderDiffuse's image, bit for
    // bit (every pixel is computed on its own); the other rows 0.
    Image renderDiffuseRows(int width, int height, int firstRow, int rowCount);
    // renderDiffuse (pass 0), then passes with independent environment rays until
    // the estimated relative RMSE of the mean's noise, from the spread of the
    // passes over the covered pixels, is at most the target (or maxPasses); the
    // image is the passes' mean and each estimate is logged. A second pass over
    // a few hundred pixels first estimates pass 0's noise, which is often within
    // the target already. Without an environment nothing is random: one pass. The
    // sub-samples' positions are part of the pixel's definition (the same every
    // pass) and the quadrature's error (the density) is not noise: docs/reference.md
    // gives both.
    Image renderDiffuseProgressive(int width, int height, const ProgressiveSettings& settings);
    // Delta at the same sub-samples as renderDiffuse, averaged over those that meet
    // the character at the pixel's centre (the surface the engine's pixel shows; the
    // centre itself where none does): 0 on characters without SSS or without an
    // engine texture, and everywhere when SSS is off.
    Image renderScatterChange(int width, int height);
    // At each pixel centre's hit: the distance in mm along minus the geometric normal
    // (turned to the viewer's side) to the next surface of the same character,
    // kNoExitThicknessMm where there is none; alpha 1 there, 0 (RGB 0) on the background.
    Image renderThicknessMm(int width, int height);

    // Ray through the centre of pixel (x, y), y = 0 the top row; its direction has
    // view-space z = -1, so t is the view depth in metres.
    static Ray cameraRay(const Camera& camera, int width, int height, int x, int y);

    const ReferenceStats& stats() const { return mStats; }
    // A hash of what it read from files (every character's surface and maps, the
    // environment map): with the scene's own values and the program, the key of
    // the reference images' disk cache (measure/ReferenceImages.h).
    uint64_t contentHash() const;

private:
    struct Hit {
        int character = -1;
        uint32_t triangle = 0;
        float b1 = 0.0f, b2 = 0.0f;
        bool backFacing = false;
    };
    enum class Quantity { Diffuse, ScatterChange };

    Hit trace(const Ray& ray, float tMin, float tMax) const;
    // The footprint of one pixel of `camera` at the hit, in map UV.
    MapFootprint pixelFootprint(const Hit& hit, const Ray& ray, const CameraRays& camera) const;
    glm::vec4 shadeHit(Quantity quantity, const Hit& hit, const Ray& ray, const CameraRays* camera,
                       const std::vector<std::vector<std::vector<Sample>>>* baseSamples) const;
    const SampleValues* valuesFor(Quantity quantity, size_t character) const;
    // The quantity along each ray; with a camera, maps are read at its pixel footprint.
    // hitCharacters (optional): each ray's character, -1 for the background.
    std::vector<glm::vec4> evaluate(Quantity quantity, const std::vector<Ray>& rays, float tMin, float tMax,
                                    const CameraRays* camera, size_t itemSize,
                                    std::vector<int>* hitCharacters = nullptr);
    // Every pixel, or only those listed (the others 0).
    Image renderPixels(Quantity quantity, int width, int height, const std::vector<uint32_t>* only = nullptr);
    // Selects pass `pass`'s sub-samples and environment rays (0: the default ones).
    void usePass(uint32_t pass);

    Scene mScene;
    ReferenceOptions mOptions;
    std::vector<std::unique_ptr<CharacterSurface>> mSurfaces;
    std::vector<std::unique_ptr<SurfaceInterior>> mInteriors;  // per character
    std::vector<uint32_t> mFirstTriangle;  // per character, into the BVH's triangle order; plus the total
    std::unique_ptr<raytrace::TriangleScene> mBvh;
    std::unique_ptr<ReferenceLighting> mLighting;          // at the points the camera sees
    std::unique_ptr<ReferenceLighting> mIntegralLighting;  // at the integral's samples
    // A diffusion group: the triangles of one character whose materials share a
    // profile and width scale, which scatter light only among themselves (as
    // the engine's blurs stay within a profile slot).
    struct DiffusionGroup {
        size_t character = 0;
        std::unique_ptr<DiffusionIntegrator> integrator;  // width-scaled profile
    };
    std::vector<DiffusionGroup> mGroups;
    std::vector<std::vector<int32_t>> mTriangleGroups;  // per character, per triangle: into mGroups, -1 local
    std::vector<std::unique_ptr<ExactLightingValues>> mExactValues;    // per character
    std::vector<std::unique_ptr<SampleMemo>> mExactMemos;              // per character, over mExactValues (or null)
    std::vector<std::unique_ptr<EngineIrradiance>> mEngineValues;      // per character (null: no texture)
    ReferenceStats mStats;
    uint32_t mPass = 0;
};

}  // namespace dermis::reference
