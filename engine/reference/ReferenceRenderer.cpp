#include "reference/ReferenceRenderer.h"

#include "import/CharacterPose.h"

#include "core/Log.h"
#include "raytrace/ParallelFor.h"
#include "import/ModelLoader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
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
        auto surface = CharacterSurface::create(scene.characters[c], std::move(models[c]));
        if (!surface.ok()) return surface.error();
        renderer.mFirstTriangle.push_back(static_cast<uint32_t>(corners.size() / 3));
        for (size_t t = 0; t < surface->triangleCount(); ++t) {
            for (int i = 0; i < 3; ++i) corners.push_back(surface->corner(t, i));
        }
        renderer.mSurfaces.push_back(std::make_unique<CharacterSurface>(std::move(*surface)));
    }
    renderer.mFirstTriangle.push_back(static_cast<uint32_t>(corners.size() / 3));
    renderer.mBvh = std::make_unique<Bvh>(Bvh::build(corners));
    auto lighting = ReferenceLighting::create(renderer.mScene, *renderer.mBvh, options.environmentSamples);
    if (!lighting.ok()) return lighting.error();
    renderer.mLighting = std::make_unique<ReferenceLighting>(std::move(*lighting));
    renderer.mStats.triangles = renderer.mBvh->triangleCount();
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        renderer.mExactValues.push_back(
            std::make_unique<ExactLightingValues>(*renderer.mSurfaces[c], *renderer.mLighting, scene.settings.sss.mix));
        renderer.mEngineValues.emplace_back();
        if (c >= options.engineIrradiance.size() || options.engineIrradiance[c].empty()) continue;
        auto engine = EngineIrradiance::create(*renderer.mSurfaces[c], options.engineIrradiance[c]);
        if (!engine.ok()) return engine.error();
        renderer.mEngineValues.back() = std::move(*engine);
    }

    const SssSettings& sss = scene.settings.sss;
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const Character& character = scene.characters[c];
        renderer.mIntegrators.emplace_back();
        if (!sss.enabled || character.material.profile == kOpaqueProfile) continue;
        auto profile = findProfile(character.material.profile);
        if (!profile.ok()) return makeError("character '" + character.name + "'", profile.error().what);
        if (!(sss.widthScale > 0.0f)) continue;  // no width: every Gaussian is a delta, the local case
        std::vector<ProfileGaussian> scaled = (*profile)->gaussians();
        for (ProfileGaussian& g : scaled) g.varianceMm2 *= sss.widthScale * sss.widthScale;
        auto scaledProfile = DiffusionProfile::create((*profile)->name(), std::move(scaled));
        if (!scaledProfile.ok()) return makeError("character '" + character.name + "'", scaledProfile.error().what);
        const size_t cells = countTessellationCells(
            *renderer.mSurfaces[c], DiffusionIntegrator::baseCellEdgeM(*scaledProfile, quadrature));
        if (cells > kMaxBaseCells) {
            return makeError("character '" + character.name + "'",
                             "the reference would need " + std::to_string(cells) + " base cells (at most " +
                                 std::to_string(kMaxBaseCells) + "): lower the density");
        }
        renderer.mIntegrators.back() =
            std::make_unique<DiffusionIntegrator>(*renderer.mSurfaces[c], *scaledProfile, options.quadrature);
        renderer.mStats.baseCells += renderer.mIntegrators.back()->baseCellCount();
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
    if (quantity == Quantity::Diffuse) return mExactValues[character].get();
    return mEngineValues[character].get();
}

glm::vec4 ReferenceRenderer::shadeHit(Quantity quantity, const Hit& hit, const Ray& ray, const CameraRays* camera,
                                      const std::vector<std::vector<Sample>>* baseSamples) const {
    if (hit.character < 0) return glm::vec4(0.0f);
    const auto c = size_t(hit.character);
    const SampleValues* values = valuesFor(quantity, c);
    if (quantity == Quantity::ScatterChange && !(mIntegrators[c] && values)) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    MapFootprint footprint;
    if (camera) footprint = pixelFootprint(hit, ray, *camera);
    const SurfacePoint point =
        mSurfaces[c]->pointAt(hit.triangle, hit.b1, hit.b2, hit.backFacing, camera ? &footprint : nullptr);
    const glm::vec3 towardsViewer = glm::normalize(-ray.direction);
    const float mix = mScene.settings.sss.mix;
    glm::vec3 diffuse;
    if (quantity == Quantity::ScatterChange) {
        const glm::vec3 here = values->valueAt(hit.triangle, glm::vec2(hit.b1, hit.b2), nullptr);
        diffuse = (mIntegrators[c]->integrate(point.positionM, *baseSamples, *values) - here) *
                  albedoPower(point.albedo, 1.0f - mix);
    } else if (mIntegrators[c]) {
        diffuse = mIntegrators[c]->integrate(point.positionM, *baseSamples, *values) * albedoPower(point.albedo, 1.0f - mix);
    } else {
        diffuse = mLighting->irradiance(point) * albedoPower(point.albedo, mix) * albedoPower(point.albedo, 1.0f - mix);
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
                                                   float tMax, const CameraRays* camera, size_t itemSize) {
    const int threads = mOptions.threads;
    const size_t items = (rays.size() + itemSize - 1) / itemSize;
    auto forItem = [&](size_t item, auto&& perRay) {
        for (size_t r = item * itemSize; r < std::min(rays.size(), (item + 1) * itemSize); ++r) perRay(r);
    };

    std::vector<Hit> hits(rays.size());
    parallelFor(items, threads, [&](size_t item) { forItem(item, [&](size_t r) { hits[r] = trace(rays[r], tMin, tMax); }); });

    // Shade the base cells that some SSS hit reads, once each.
    std::vector<std::vector<std::vector<Sample>>> baseSamples(mSurfaces.size());
    mStats.shadedBaseCells = 0;
    mStats.sssHits = 0;
    for (size_t c = 0; c < mSurfaces.size(); ++c) {
        const SampleValues* values = valuesFor(quantity, c);
        if (!mIntegrators[c] || !values) continue;
        const DiffusionIntegrator& integrator = *mIntegrators[c];
        std::vector<uint8_t> needed(integrator.baseCellCount(), 0);
        for (size_t r = 0; r < rays.size(); ++r) {
            if (hits[r].character != int(c)) continue;
            ++mStats.sssHits;
            integrator.markNeeded(mSurfaces[c]->positionAt(hits[r].triangle, hits[r].b1, hits[r].b2), needed);
        }
        std::vector<uint32_t> list;
        for (size_t i = 0; i < needed.size(); ++i) {
            if (needed[i]) list.push_back(static_cast<uint32_t>(i));
        }
        mStats.shadedBaseCells += list.size();
        baseSamples[c].resize(integrator.baseCellCount());
        constexpr size_t kCellsPerItem = 256;
        parallelFor((list.size() + kCellsPerItem - 1) / kCellsPerItem, threads, [&](size_t item) {
            for (size_t i = item * kCellsPerItem; i < std::min(list.size(), (item + 1) * kCellsPerItem); ++i) {
                baseSamples[c][list[i]] = integrator.shadeBaseCell(list[i], *values);
            }
        }, mOptions.showProgress ? "reference: irradiance (" + mSurfaces[c]->name() + ")" : std::string());
    }

    std::vector<glm::vec4> out(rays.size());
    parallelFor(items, threads, [&](size_t item) {
        forItem(item, [&](size_t r) {
            const Hit& hit = hits[r];
            out[r] = shadeHit(quantity, hit, rays[r], camera,
                              hit.character >= 0 ? &baseSamples[size_t(hit.character)] : nullptr);
        });
    }, mOptions.showProgress ? "reference: scattering" : std::string());
    mStats.emptyIrradianceReads = 0;
    for (const auto& engine : mEngineValues) {
        if (engine) mStats.emptyIrradianceReads += engine->emptyReads();
    }
    return out;
}

Image ReferenceRenderer::renderPixels(Quantity quantity, int width, int height) {
    const CameraRays camera(mScene.camera, width, height);
    const int spp = mOptions.samplesPerPixel;
    std::vector<Ray> rays;
    rays.reserve(size_t(width) * size_t(height) * size_t(spp));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (const glm::vec2& offset : subSampleOffsets(x, y, spp)) {
                rays.push_back(camera.through(float(x) + offset.x, float(y) + offset.y));
            }
        }
    }
    // One work item per pixel row.
    const std::vector<glm::vec4> values =
        evaluate(quantity, rays, mScene.camera.nearM, mScene.camera.farM, &camera, size_t(width) * size_t(spp));
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = ColourSpace::Linear;
    image.texels.resize(size_t(width) * size_t(height));
    for (size_t p = 0; p < image.texels.size(); ++p) {
        glm::dvec4 sum(0.0);
        for (size_t s = 0; s < size_t(spp); ++s) sum += glm::dvec4(values[p * size_t(spp) + s]);
        image.texels[p] = glm::vec4(sum / double(spp));
    }
    return image;
}

Image ReferenceRenderer::renderDiffuse(int width, int height) { return renderPixels(Quantity::Diffuse, width, height); }

Image ReferenceRenderer::renderScatterChange(int width, int height) {
    return renderPixels(Quantity::ScatterChange, width, height);
}

}  // namespace dermis::reference
