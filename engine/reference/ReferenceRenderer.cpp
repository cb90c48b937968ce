#include "reference/ReferenceRenderer.h"
#include "reference/ReferenceDefinition.h"

#include "pose/CharacterPose.h"

#include "core/Hash.h"
#include "core/Log.h"
#include "raytrace/ParallelFor.h"
#include "import/ModelLoader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace dermis::reference {
using raytrace::parallelFor;
}  // namespace dermis::reference

namespace dermis::reference {
namespace {

// About 90 bytes each with their samples: 1.8 GB.
constexpr size_t kMaxBaseCells = 20'000'000;

// NaN becomes 0, like the renderer's sanitizeColour (the reference keeps values above fp16's range).
glm::vec3 sanitize(const glm::vec3& c) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = std::isnan(c[i]) ? 0.0f : c[i];
    return out;
}

}  // namespace

Result<ReferenceRenderer> ReferenceRenderer::load(const Scene& scene, const ReferenceOptions& options) {
    std::vector<Model> models;
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        auto model = loadCharacterModel(scene.characters[c]);
        if (!model.ok()) return model.error();
        // Animated characters as the engine's frame at time 0 shows them.
        if (const Status posed = poseModelAt(scene, c, 0.0f, *model); !posed.ok()) return posed.error();
        models.push_back(std::move(*model));
    }
    return create(scene, std::move(models), options);
}

Result<ReferenceRenderer> ReferenceRenderer::create(const Scene& scene, std::vector<Model> models,
                                                    const ReferenceOptions& options) {
    if (models.size() != scene.characters.size()) {
        return makeError("reference", "expected one model per character");
    }
    const QuadratureSettings& quadrature = options.quadrature;
    if (!(quadrature.density > 0.0f) || !std::isfinite(quadrature.density)) {
        return makeError("reference", "the sample density must be a finite number > 0");
    }
    if (!(quadrature.refineCutoffSigmas > 0.0f) || !std::isfinite(quadrature.refineCutoffSigmas)) {
        return makeError("reference", "the refinement cut-off must be a finite number > 0");
    }
    if (strataPerSide(options.samplesPerPixel) == 0) {
        return makeError("reference", "the samples per pixel must be a perfect square from 1 to " +
                                          std::to_string(kMaxSamplesPerPixel) + " (got " +
                                          std::to_string(options.samplesPerPixel) + ")");
    }
    if (!options.engineIrradiance.empty() && options.engineIrradiance.size() != scene.characters.size()) {
        return makeError("reference", "expected one engine irradiance image per character (" +
                                          std::to_string(scene.characters.size()) + "), got " +
                                          std::to_string(options.engineIrradiance.size()));
    }
    ReferenceRenderer renderer;
    renderer.mScene = scene;
    renderer.mOptions = options;
    renderer.mOptions.engineIrradiance.clear();  // kept once, as EngineIrradiance below
    std::vector<glm::vec3> corners;
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const auto firstTriangle = static_cast<uint32_t>(corners.size() / 3);
        auto surface = CharacterSurface::create(scene.characters[c], std::move(models[c]), firstTriangle);
        if (!surface.ok()) return surface.error();
        renderer.mFirstTriangle.push_back(firstTriangle);
        for (size_t t = 0; t < surface->triangleCount(); ++t) {
            for (int i = 0; i < 3; ++i) corners.push_back(surface->corner(t, i));
        }
        renderer.mSurfaces.push_back(std::make_unique<CharacterSurface>(std::move(*surface)));
        renderer.mInteriors.push_back(std::make_unique<SurfaceInterior>(SurfaceInterior::build(*renderer.mSurfaces.back())));
        renderer.mStats.buriedTriangles += renderer.mInteriors.back()->buriedTriangleCount();
        renderer.mStats.straddlingTriangles += renderer.mInteriors.back()->straddlingTriangleCount();
    }
    renderer.mFirstTriangle.push_back(static_cast<uint32_t>(corners.size() / 3));
    if (options.embree) {
        renderer.mBvh = std::make_unique<raytrace::EmbreeBvh>(raytrace::EmbreeBvh::build(corners));
    } else {
        renderer.mBvh = std::make_unique<raytrace::Bvh>(raytrace::Bvh::build(corners));
    }
    auto lighting = ReferenceLighting::create(renderer.mScene, *renderer.mBvh, options.environmentSamples);
    if (!lighting.ok()) return lighting.error();
    renderer.mLighting = std::make_unique<ReferenceLighting>(std::move(*lighting));
    auto integralLighting = ReferenceLighting::create(renderer.mScene, *renderer.mBvh, options.integralEnvironmentSamples);
    if (!integralLighting.ok()) return integralLighting.error();
    renderer.mIntegralLighting = std::make_unique<ReferenceLighting>(std::move(*integralLighting));
    renderer.mStats.triangles = renderer.mBvh->triangleCount();
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        renderer.mExactValues.push_back(
            std::make_unique<ExactLightingValues>(*renderer.mSurfaces[c], *renderer.mIntegralLighting, scene.settings.sss.mix));
        // Only under an environment are a sample's values dear enough to keep: without one, looking a
        // sample up cost more than shading it again (docs/results/reference.md, "Speed").
        renderer.mExactMemos.push_back(options.sampleMemo && scene.environment.enabled()
                                           ? std::make_unique<SampleMemo>(*renderer.mExactValues.back())
                                           : nullptr);
        renderer.mEngineValues.emplace_back();
        if (c >= options.engineIrradiance.size() || options.engineIrradiance[c].empty()) continue;
        auto engine = EngineIrradiance::create(*renderer.mSurfaces[c], options.engineIrradiance[c]);
        if (!engine.ok()) return engine.error();
        renderer.mEngineValues.back() = std::move(*engine);
    }

    const SssSettings& sss = scene.settings.sss;
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const Character& character = scene.characters[c];
        const CharacterSurface& surface = *renderer.mSurfaces[c];
        renderer.mTriangleGroups.emplace_back(surface.triangleCount(), -1);
        // No width: every Gaussian is a delta, the local case.
        if (!sss.enabled || !(sss.widthScale > 0.0f)) continue;
        for (size_t m = 0; m < surface.materialCount(); ++m) {
            const SurfaceScattering& scattering = surface.scattering(m);
            if (scattering.profile == kOpaqueProfile) continue;
            // Materials of one profile and width scale share a group (the first one's).
            size_t first = 0;
            while (first < m && !(surface.scattering(first).profile == scattering.profile &&
                                  surface.scattering(first).widthScale == scattering.widthScale))
                ++first;
            if (first < m) continue;
            std::vector<uint8_t> triangles(surface.triangleCount(), 0);
            bool any = false;
            for (size_t t = 0; t < surface.triangleCount(); ++t) {
                const SurfaceScattering& own = surface.scattering(surface.materialOf(t));
                triangles[t] = own.profile == scattering.profile && own.widthScale == scattering.widthScale;
                any = any || triangles[t];
            }
            if (!any) continue;
            auto profile = findSceneProfile(scene, scattering.profile);
            if (!profile.ok()) return makeError("character '" + character.name + "'", profile.error().what);
            const float widthScale = sss.widthScale * scattering.widthScale;
            std::vector<ProfileGaussian> scaled = (*profile)->gaussians();
            for (ProfileGaussian& g : scaled) g.varianceMm2 *= widthScale * widthScale;
            auto scaledProfile = DiffusionProfile::create((*profile)->name(), std::move(scaled));
            if (!scaledProfile.ok()) return makeError("character '" + character.name + "'", scaledProfile.error().what);
            const size_t cells = countTessellationCells(
                surface, DiffusionIntegrator::baseCellEdgeM(*scaledProfile, quadrature), &triangles);
            if (cells > kMaxBaseCells) {
                return makeError("character '" + character.name + "'",
                                 "the reference would need " + std::to_string(cells) + " base cells (at most " +
                                     std::to_string(kMaxBaseCells) + "): lower the density");
            }
            const auto group = static_cast<int32_t>(renderer.mGroups.size());
            for (size_t t = 0; t < surface.triangleCount(); ++t)
                if (triangles[t]) renderer.mTriangleGroups[c][t] = group;
            renderer.mGroups.push_back(
                {c, std::make_unique<DiffusionIntegrator>(surface, *scaledProfile, options.quadrature, &triangles,
                                                          renderer.mInteriors[c].get())});
            renderer.mStats.baseCells += renderer.mGroups.back().integrator->baseCellCount();
        }
    }
    return renderer;
}

Ray ReferenceRenderer::cameraRay(const Camera& camera, int width, int height, int x, int y) {
    return CameraRays(camera, width, height).through(float(x) + 0.5f, float(y) + 0.5f);
}

ReferenceRenderer::Hit ReferenceRenderer::trace(const Ray& ray, float tMin, float tMax) const {
    Hit hit;
    BvhHit bvhHit;
    if (!mBvh->closestHit(ray, tMin, tMax, &bvhHit)) return hit;
    const auto owner = std::upper_bound(mFirstTriangle.begin(), mFirstTriangle.end(), bvhHit.triangle) - 1;
    hit.character = static_cast<int>(owner - mFirstTriangle.begin());
    hit.triangle = bvhHit.triangle - *owner;
    hit.b1 = bvhHit.u;
    hit.b2 = bvhHit.v;
    const CharacterSurface& surface = *mSurfaces[size_t(hit.character)];
    const glm::vec3 faceNormal = glm::cross(surface.corner(hit.triangle, 1) - surface.corner(hit.triangle, 0),
                                            surface.corner(hit.triangle, 2) - surface.corner(hit.triangle, 0));
    hit.backFacing = glm::dot(faceNormal, ray.direction) > 0.0f;  // gl_FrontFacing: counter-clockwise faces the viewer
    return hit;
}

MapFootprint ReferenceRenderer::pixelFootprint(const Hit& hit, const Ray& ray, const CameraRays& camera) const {
    const CharacterSurface& surface = *mSurfaces[size_t(hit.character)];
    const glm::vec3 p = surface.positionAt(hit.triangle, hit.b1, hit.b2);
    const glm::vec3 normal = glm::cross(surface.corner(hit.triangle, 1) - surface.corner(hit.triangle, 0),
                                        surface.corner(hit.triangle, 2) - surface.corner(hit.triangle, 0));
    const glm::vec2 uv = surface.mapUvAt(hit.triangle, hit.b1, hit.b2);
    // A step whose ray misses the plane (grazing views) reads the coarsest level, as an
    // unbounded derivative would on the GPU.
    auto step = [&](const glm::vec3& directionStep) {
        glm::vec3 q;
        if (!offsetRayOnPlane(ray, directionStep, p, normal, &q)) return glm::vec2(std::numeric_limits<float>::infinity());
        return surface.mapUvAtPlanePoint(hit.triangle, q) - uv;
    };
    return MapFootprint{step(camera.directionPerPixelX()), step(camera.directionPerPixelY())};
}

const SampleValues* ReferenceRenderer::valuesFor(Quantity quantity, size_t character) const {
    if (quantity == Quantity::Diffuse) {
        if (mExactMemos[character]) return mExactMemos[character].get();
        return mExactValues[character].get();
    }
    return mEngineValues[character].get();
}

glm::vec4 ReferenceRenderer::shadeHit(Quantity quantity, const Hit& hit, const Ray& ray, const CameraRays* camera,
                                      const std::vector<std::vector<std::vector<Sample>>>* baseSamples) const {
    if (hit.character < 0) return glm::vec4(0.0f);
    const auto c = size_t(hit.character);
    const SampleValues* values = valuesFor(quantity, c);
    const int32_t group = mTriangleGroups[c][hit.triangle];
    const DiffusionIntegrator* integrator = group >= 0 ? mGroups[size_t(group)].integrator.get() : nullptr;
    const std::vector<std::vector<Sample>>* samples = group >= 0 ? &(*baseSamples)[size_t(group)] : nullptr;
    if (quantity == Quantity::ScatterChange && !(integrator && values)) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    MapFootprint footprint;
    if (camera) footprint = pixelFootprint(hit, ray, *camera);
    const SurfacePoint point =
        mSurfaces[c]->pointAt(hit.triangle, hit.b1, hit.b2, hit.backFacing, camera ? &footprint : nullptr);
    const glm::vec3 towardsViewer = glm::normalize(-ray.direction);
    const float mix = mScene.settings.sss.mix;
    glm::vec3 diffuse;
    // A share s of the light scatters, the rest leaves where it arrived (docs/materials.md).
    const float s = integrator ? point.scatter : 0.0f;
    auto local = [&] { return mLighting->irradiance(point, nullptr, mPass) * albedoPower(point.albedo, mix); };
    if (quantity == Quantity::ScatterChange) {
        const glm::vec3 here = values->valueAt(hit.triangle, glm::vec2(hit.b1, hit.b2), nullptr);
        diffuse = s * (integrator->integrate(point.positionM, *samples, *values) - here) *
                  albedoPower(point.albedo, 1.0f - mix);
    } else if (s >= 1.0f) {
        diffuse = integrator->integrate(point.positionM, *samples, *values) * albedoPower(point.albedo, 1.0f - mix);
    } else if (s > 0.0f) {
        diffuse = (s * integrator->integrate(point.positionM, *samples, *values) + (1.0f - s) * local()) *
                  albedoPower(point.albedo, 1.0f - mix);
    } else {
        diffuse = local() * albedoPower(point.albedo, 1.0f - mix);
    }
    diffuse *= mLighting->outgoingFactor(point, towardsViewer);
    return glm::vec4(sanitize(diffuse), 1.0f);
}

std::vector<glm::vec4> ReferenceRenderer::diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax) {
    return evaluate(Quantity::Diffuse, rays, tMin, tMax, nullptr, 64);
}

std::vector<glm::vec4> ReferenceRenderer::scatterChangeAlongRays(const std::vector<Ray>& rays, float tMin, float tMax) {
    return evaluate(Quantity::ScatterChange, rays, tMin, tMax, nullptr, 64);
}

std::vector<glm::vec4> ReferenceRenderer::evaluate(Quantity quantity, const std::vector<Ray>& rays, float tMin,
                                                   float tMax, const CameraRays* camera, size_t itemSize,
                                                   std::vector<int>* hitCharacters) {
    const int threads = mOptions.threads;
    const size_t items = (rays.size() + itemSize - 1) / itemSize;
    auto forItem = [&](size_t item, auto&& perRay) {
        for (size_t r = item * itemSize; r < std::min(rays.size(), (item + 1) * itemSize); ++r) perRay(r);
    };

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::vector<Hit> hits(rays.size());
    parallelFor(items, threads, [&](size_t item) { forItem(item, [&](size_t r) { hits[r] = trace(rays[r], tMin, tMax); }); });
    const auto traced = Clock::now();
    if (hitCharacters) {
        hitCharacters->resize(rays.size());
        for (size_t r = 0; r < rays.size(); ++r) (*hitCharacters)[r] = hits[r].character;
    }

    // Shade the base cells that some SSS hit reads, once each.
    std::vector<std::vector<std::vector<Sample>>> baseSamples(mGroups.size());
    mStats.shadedBaseCells = 0;
    mStats.sssHits = 0;
    for (size_t g = 0; g < mGroups.size(); ++g) {
        const size_t c = mGroups[g].character;
        const SampleValues* values = valuesFor(quantity, c);
        if (!values) continue;
        const DiffusionIntegrator& integrator = *mGroups[g].integrator;
        std::vector<uint8_t> needed(integrator.baseCellCount(), 0);
        for (size_t r = 0; r < rays.size(); ++r) {
            if (hits[r].character != int(c) || mTriangleGroups[c][hits[r].triangle] != int32_t(g)) continue;
            ++mStats.sssHits;
            integrator.markNeeded(mSurfaces[c]->positionAt(hits[r].triangle, hits[r].b1, hits[r].b2), needed);
        }
        std::vector<uint32_t> list;
        for (size_t i = 0; i < needed.size(); ++i) {
            if (needed[i]) list.push_back(static_cast<uint32_t>(i));
        }
        mStats.shadedBaseCells += list.size();
        baseSamples[g].resize(integrator.baseCellCount());
        constexpr size_t kCellsPerItem = 256;
        parallelFor((list.size() + kCellsPerItem - 1) / kCellsPerItem, threads, [&](size_t item) {
            for (size_t i = item * kCellsPerItem; i < std::min(list.size(), (item + 1) * kCellsPerItem); ++i) {
                baseSamples[g][list[i]] = integrator.shadeBaseCell(list[i], *values);
            }
        }, mOptions.showProgress ? "reference: irradiance (" + mSurfaces[c]->name() + ")" : std::string());
    }

    const auto shadedBase = Clock::now();
    std::vector<glm::vec4> out(rays.size());
    parallelFor(items, threads, [&](size_t item) {
        forItem(item, [&](size_t r) {
            const Hit& hit = hits[r];
            out[r] = shadeHit(quantity, hit, rays[r], camera, &baseSamples);
        });
    }, mOptions.showProgress ? "reference: scattering" : std::string());
    const auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
    mStats.traceSeconds = seconds(start, traced);
    mStats.baseCellSeconds = seconds(traced, shadedBase);
    mStats.scatterSeconds = seconds(shadedBase, Clock::now());
    mStats.emptyIrradianceReads = 0;
    for (const auto& engine : mEngineValues) {
        if (engine) mStats.emptyIrradianceReads += engine->emptyReads();
    }
    mStats.sampleLookups = 0;
    mStats.sampleMemoHits = 0;
    for (const auto& memo : mExactMemos) {
        if (!memo) continue;
        mStats.sampleLookups += memo->lookups();
        mStats.sampleMemoHits += memo->hits();
    }
    return out;
}

Image ReferenceRenderer::renderPixels(Quantity quantity, int width, int height, const std::vector<uint32_t>* only) {
    const CameraRays camera(mScene.camera, width, height);
    const int spp = mOptions.samplesPerPixel;
    const float tMin = mScene.camera.nearM, tMax = mScene.camera.farM;
    std::vector<uint32_t> pixels;
    if (only) {
        pixels = *only;
    } else {
        pixels.resize(size_t(width) * size_t(height));
        for (size_t p = 0; p < pixels.size(); ++p) pixels[p] = uint32_t(p);
    }
    const auto rayThrough = [&camera, width](uint32_t pixel, const glm::vec2& offset) {
        return camera.through(float(pixel % uint32_t(width)) + offset.x, float(pixel / uint32_t(width)) + offset.y);
    };
    std::vector<Ray> rays;
    rays.reserve(pixels.size() * size_t(spp));
    for (const uint32_t p : pixels) {
        for (const glm::vec2& offset : subSampleOffsets(int(p % uint32_t(width)), int(p / uint32_t(width)), spp)) {
            rays.push_back(rayThrough(p, offset));
        }
    }
    // The scattering change box-filters the surface that the engine's pixel
    // shows, the one at the pixel's centre: it averages the sub-samples that
    // meet the centre's character. Averaging every one, the background's 0
    // scaled an outline pixel's change by its coverage. Where none meets it,
    // the centre's own change stands.
    const bool centreSurfaceOnly = quantity == Quantity::ScatterChange && strataPerSide(spp) > 1;
    std::vector<int> centreCharacter;
    if (centreSurfaceOnly) {
        centreCharacter.resize(pixels.size());
        parallelFor(pixels.size(), mOptions.threads, [&](size_t i) {
            centreCharacter[i] = trace(rayThrough(pixels[i], glm::vec2(0.5f)), tMin, tMax).character;
        });
    }
    // One work item per pixel row's worth of sub-samples; a scattered subset in items of
    // kSubsetItemPixels, or its few items would leave threads idle at the end.
    constexpr size_t kSubsetItemPixels = 32;
    const size_t itemPixels = only ? kSubsetItemPixels : size_t(width);
    std::vector<int> hitCharacters;
    const std::vector<glm::vec4> values = evaluate(quantity, rays, tMin, tMax, &camera, itemPixels * size_t(spp),
                                                   centreSurfaceOnly ? &hitCharacters : nullptr);
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = ColourSpace::Linear;
    image.texels.assign(size_t(width) * size_t(height), glm::vec4(0.0f));
    std::vector<Ray> centreRays;
    std::vector<uint32_t> centrePixels;
    for (size_t i = 0; i < pixels.size(); ++i) {
        glm::dvec4 sum(0.0);
        int count = 0;
        for (size_t r = i * size_t(spp); r < (i + 1) * size_t(spp); ++r) {
            if (centreSurfaceOnly && hitCharacters[r] != centreCharacter[i]) continue;
            sum += glm::dvec4(values[r]);
            ++count;
        }
        if (count > 0) {
            image.texels[pixels[i]] = glm::vec4(sum / double(count));
        } else {
            centreRays.push_back(rayThrough(pixels[i], glm::vec2(0.5f)));
            centrePixels.push_back(pixels[i]);
        }
    }
    if (!centreRays.empty()) {
        const ReferenceStats first = mStats;
        const std::vector<glm::vec4> centres = evaluate(quantity, centreRays, tMin, tMax, &camera, kSubsetItemPixels);
        for (size_t i = 0; i < centres.size(); ++i) image.texels[centrePixels[i]] = centres[i];
        mStats.traceSeconds += first.traceSeconds;
        mStats.baseCellSeconds += first.baseCellSeconds;
        mStats.scatterSeconds += first.scatterSeconds;
        mStats.shadedBaseCells = std::max(mStats.shadedBaseCells, first.shadedBaseCells);  // the cells overlap
        mStats.sssHits += first.sssHits;
    }
    image.attributes = {{kDefinitionAttribute, definitionRecord(mScene)},  // what it is a reference of
                        {kSamplesPerPixelAttribute, std::to_string(mOptions.samplesPerPixel)}};
    return image;
}

Image ReferenceRenderer::renderDiffuse(int width, int height) { return renderPixels(Quantity::Diffuse, width, height); }

Image ReferenceRenderer::renderDiffuseRows(int width, int height, int firstRow, int rowCount) {
    const int begin = std::clamp(firstRow, 0, height), end = std::clamp(firstRow + rowCount, begin, height);
    std::vector<uint32_t> pixels;
    pixels.reserve(size_t(end - begin) * size_t(width));
    for (uint32_t p = uint32_t(begin) * uint32_t(width); p < uint32_t(end) * uint32_t(width); ++p) pixels.push_back(p);
    return renderPixels(Quantity::Diffuse, width, height, &pixels);
}

void ReferenceRenderer::usePass(uint32_t pass) {
    if (pass == mPass) return;
    mPass = pass;
    // Without an environment every pass's samples have the same values: the memo stays.
    if (!mLighting->hasEnvironment()) return;
    for (size_t c = 0; c < mSurfaces.size(); ++c) {
        mExactMemos[c].reset();
        mExactValues[c] =
            std::make_unique<ExactLightingValues>(*mSurfaces[c], *mIntegralLighting, mScene.settings.sss.mix, pass);
        if (mOptions.sampleMemo) mExactMemos[c] = std::make_unique<SampleMemo>(*mExactValues[c]);
    }
}

Image ReferenceRenderer::renderDiffuseProgressive(int width, int height, const ProgressiveSettings& settings) {
    const size_t pixels = size_t(width) * size_t(height);
    usePass(0);
    const Image first = renderPixels(Quantity::Diffuse, width, height);
    std::vector<glm::dvec3> sum(pixels), sumSquares(pixels);
    std::vector<uint8_t> covered(pixels);  // alpha 1: the pixels the estimate is over
    for (size_t p = 0; p < pixels; ++p) {
        sum[p] = glm::dvec3(first.texels[p]);
        sumSquares[p] = sum[p] * sum[p];
        covered[p] = first.texels[p].a == 1.0f;
    }
    mStats.passes = 1;
    mStats.estimatedRelativeRmse = 0.0;
    if (!mLighting->hasEnvironment()) return first;  // nothing random: the image is exact for its settings

    auto report = [&](const char* what) {
        log::info("reference: " + std::to_string(mStats.passes) + " pass(es), " + what + " relative RMSE of the noise " +
                  std::to_string(100.0 * mStats.estimatedRelativeRmse) + " % (target " +
                  std::to_string(100.0 * settings.targetRelativeRmse) + " %)");
    };
    // The relative RMSE of the mean of n passes over `subset` (empty: every covered pixel):
    // the passes' sample variance / n per pixel and channel, against the mean's RMS.
    auto estimate = [&](const std::vector<glm::dvec3>& s, const std::vector<glm::dvec3>& s2, double n,
                        const std::vector<uint32_t>& subset, double passesInImage) {
        double noise = 0.0, signal = 0.0;
        auto add = [&](size_t p) {
            if (!covered[p]) return;
            const glm::dvec3 mean = s[p] / n;
            const glm::dvec3 variance = glm::max((s2[p] - n * mean * mean) / (n - 1.0), glm::dvec3(0.0));
            noise += (variance.r + variance.g + variance.b) / passesInImage;
            signal += glm::dot(mean, mean);
        };
        if (subset.empty()) {
            for (size_t p = 0; p < pixels; ++p) add(p);
        } else {
            for (const uint32_t p : subset) add(p);
        }
        return signal > 0.0 ? std::sqrt(noise / signal) : 0.0;
    };

    // A second pass over about kProbePixels covered pixels (a hash picks one in probeStride)
    // tells the first pass's noise at a small share of the cost: often it is already within
    // the target. Each probed pixel costs what it costs in a full pass, or more (neighbours
    // there share part of the integral's samples; 3x3 blocks of pixels here shared too few to
    // help), so a fixed count, not a share of the image: under a sun map at 320x180 one pixel
    // in 8 cost a fifth of a pass. 256 pixels, three channels each, put the estimate's own
    // error near sqrt(2 / 768) = 5 % where pixels' noise is alike (more where a few dominate);
    // the decision against the target needs no more.
    constexpr size_t kProbePixels = 256;
    constexpr size_t kMinProbeStride = 8;
    size_t coveredCount = 0;
    for (size_t p = 0; p < pixels; ++p) coveredCount += covered[p];
    const uint32_t probeStride = uint32_t(std::max(kMinProbeStride, coveredCount / kProbePixels));
    std::vector<uint32_t> probe;
    for (size_t p = 0; p < pixels; ++p) {
        if (covered[p] && lowbias32(uint32_t(p)) % probeStride == 0) probe.push_back(uint32_t(p));
    }
    if (probe.empty()) return first;
    usePass(1);
    const Image probed = renderPixels(Quantity::Diffuse, width, height, &probe);
    {
        std::vector<glm::dvec3> s = sum, s2 = sumSquares;
        for (const uint32_t p : probe) {
            const glm::dvec3 v(probed.texels[p]);
            s[p] += v;
            s2[p] += v * v;
        }
        mStats.estimatedRelativeRmse = estimate(s, s2, 2.0, probe, 1.0);
    }
    report(("probed over " + std::to_string(probe.size()) + " pixels,").c_str());
    if (mStats.estimatedRelativeRmse <= settings.targetRelativeRmse || settings.maxPasses <= 1) {
        usePass(0);
        return first;
    }
    std::vector<double> alphaSum(pixels);
    for (size_t p = 0; p < pixels; ++p) alphaSum[p] = first.texels[p].a;
    for (int pass = 1; pass < settings.maxPasses; ++pass) {
        usePass(uint32_t(pass));
        const Image image = renderPixels(Quantity::Diffuse, width, height);
        for (size_t p = 0; p < pixels; ++p) {
            const glm::dvec3 v(image.texels[p]);
            sum[p] += v;
            sumSquares[p] += v * v;
            alphaSum[p] += image.texels[p].a;
        }
        ++mStats.passes;
        const double n = mStats.passes;
        mStats.estimatedRelativeRmse = estimate(sum, sumSquares, n, {}, n);
        report("estimated");
        if (mStats.estimatedRelativeRmse <= settings.targetRelativeRmse) break;
    }
    usePass(0);
    Image image = first;
    for (size_t p = 0; p < pixels; ++p) {
        image.texels[p] = glm::vec4(glm::vec3(sum[p] / double(mStats.passes)), float(alphaSum[p] / mStats.passes));
    }
    return image;
}

Image ReferenceRenderer::renderScatterChange(int width, int height) {
    return renderPixels(Quantity::ScatterChange, width, height);
}

uint64_t ReferenceRenderer::contentHash() const {
    ContentHash hash;
    hash.number(mSurfaces.size());
    for (const auto& surface : mSurfaces) surface->hashContent(hash);
    mLighting->hashContent(hash);
    return hash.value();
}

}  // namespace dermis::reference
