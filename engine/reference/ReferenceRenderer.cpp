#include "reference/ReferenceRenderer.h"

#include "core/Log.h"
#include "reference/ParallelFor.h"
#include "import/ModelLoader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

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
    for (const Character& character : scene.characters) {
        auto model = loadCharacterModel(character);
        if (!model.ok()) return model.error();
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
    ReferenceRenderer renderer;
    renderer.mScene = scene;
    renderer.mOptions = options;
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
    renderer.mLighting = std::make_unique<ReferenceLighting>(renderer.mScene, *renderer.mBvh);
    renderer.mStats.triangles = renderer.mBvh->triangleCount();

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
        renderer.mIntegrators.back() = std::make_unique<DiffusionIntegrator>(
            *renderer.mSurfaces[c], *renderer.mLighting, *scaledProfile, sss.mix, options.quadrature);
        renderer.mStats.baseCells += renderer.mIntegrators.back()->baseCellCount();
    }
    return renderer;
}

Ray ReferenceRenderer::cameraRay(const Camera& camera, int width, int height, int x, int y) {
    const glm::mat4 worldFromView = glm::inverse(glm::lookAt(camera.positionM, camera.targetM, camera.up));
    const float tanHalfFov = std::tan(0.5f * glm::radians(camera.verticalFovDeg));
    const float aspect = float(width) / float(height);
    const float ndcX = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
    const glm::vec3 viewDirection(ndcX * tanHalfFov * aspect, ndcY * tanHalfFov, -1.0f);
    return Ray{glm::vec3(worldFromView[3]), glm::mat3(worldFromView) * viewDirection};
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

glm::vec4 ReferenceRenderer::shadeHit(const Hit& hit, const Ray& ray,
                                      const std::vector<std::vector<Sample>>* baseSamples) const {
    if (hit.character < 0) return glm::vec4(0.0f);
    const auto c = size_t(hit.character);
    const SurfacePoint point = mSurfaces[c]->pointAt(hit.triangle, hit.b1, hit.b2, hit.backFacing);
    const glm::vec3 towardsViewer = glm::normalize(-ray.direction);
    const float mix = mScene.settings.sss.mix;
    glm::vec3 diffuse;
    if (mIntegrators[c] && baseSamples) {
        diffuse = mIntegrators[c]->integrate(point.positionM, *baseSamples) * albedoPower(point.albedo, 1.0f - mix);
    } else {
        diffuse = mLighting->irradiance(point) * albedoPower(point.albedo, mix) * albedoPower(point.albedo, 1.0f - mix);
    }
    diffuse *= mLighting->outgoingFactor(point, towardsViewer);
    return glm::vec4(sanitize(diffuse), 1.0f);
}

std::vector<glm::vec4> ReferenceRenderer::diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax) {
    return diffuseAlongRays(rays, tMin, tMax, 64);
}

std::vector<glm::vec4> ReferenceRenderer::diffuseAlongRays(const std::vector<Ray>& rays, float tMin, float tMax,
                                                          size_t itemSize) {
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
        if (!mIntegrators[c]) continue;
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
                baseSamples[c][list[i]] = integrator.shadeBaseCell(list[i]);
            }
        }, mOptions.showProgress ? "reference: irradiance (" + mSurfaces[c]->name() + ")" : std::string());
    }

    std::vector<glm::vec4> out(rays.size());
    parallelFor(items, threads, [&](size_t item) {
        forItem(item, [&](size_t r) {
            const Hit& hit = hits[r];
            out[r] = shadeHit(hit, rays[r], hit.character >= 0 ? &baseSamples[size_t(hit.character)] : nullptr);
        });
    }, mOptions.showProgress ? "reference: scattering" : std::string());
    return out;
}

Image ReferenceRenderer::renderDiffuse(int width, int height) {
    std::vector<Ray> rays;
    rays.reserve(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) rays.push_back(cameraRay(mScene.camera, width, height, x, y));
    }
    // One work item per pixel row.
    const std::vector<glm::vec4> values = diffuseAlongRays(rays, mScene.camera.nearM, mScene.camera.farM, size_t(width));
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = ColourSpace::Linear;
    image.texels = values;
    return image;
}

}  // namespace dermis::reference
