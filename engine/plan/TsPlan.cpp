#include "plan/TsPlan.h"

#include "core/Luminance.h"
#include "plan/ScreenFootprint.h"
#include "plan/SubmeshScattering.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace dermis {
namespace {

glm::vec3 anyUp(const glm::vec3& direction) {
    return std::fabs(direction.y) < 0.95f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// The brightest shadow-casting light behind the character, or -1.
int chooseTsmLight(const Scene& scene, const LightSetup& lights, const Bounds& bounds) {
    int best = -1;
    float bestLuminance = 0.0f;
    const glm::vec3 centre = bounds.centre();
    for (int index : lights.shadowedLights) {
        const Light& light = lights.sources[static_cast<size_t>(index)];
        if (!isBackLight(light, bounds, scene.camera.positionM)) continue;
        float value = relativeLuminance(light.colour) * light.intensity;
        if (light.type != LightType::Directional) {
            const glm::vec3 toLight = light.positionM - centre;
            value /= std::max(glm::dot(toLight, toLight), 1e-6f);
        }
        if (value > bestLuminance) {
            bestLuminance = value;
            best = index;
        }
    }
    return best;
}

// A projection that frames the character's bounding sphere as the light sees it.
void fitTsm(const gpu::GpuLight& light, const Bounds& bounds, TsCharacterPlan& plan) {
    const glm::vec3 centre = bounds.centre();
    const float radiusM = std::max(0.5f * glm::length(bounds.size()), 1e-3f);
    const glm::vec3 direction = light.direction;
    if (int(light.type) == DERMIS_LIGHT_DIRECTIONAL) {
        const glm::vec3 eye = centre - direction * (2.0f * radiusM);
        plan.tsmClipFromWorld = glm::ortho(-radiusM, radiusM, -radiusM, radiusM, 0.5f * radiusM, 3.5f * radiusM) *
                                glm::lookAt(eye, centre, anyUp(direction));
        plan.tsmOriginM = eye;
        plan.tsmAxis = direction;
        plan.tsmAlongAxis = true;
        return;
    }
    const glm::vec3 position = light.positionM;
    const float distanceM = glm::length(centre - position);
    plan.tsmOriginM = position;
    plan.tsmAlongAxis = false;
    if (distanceM > 1.05f * radiusM) {
        const glm::vec3 axis = (centre - position) / distanceM;
        const float halfAngle = std::asin(std::min(radiusM / distanceM, 0.999f));
        plan.tsmAxis = axis;
        plan.tsmClipFromWorld = glm::perspective(2.0f * halfAngle, 1.0f, std::max(distanceM - radiusM, 1e-3f),
                                                 distanceM + radiusM) *
                                glm::lookAt(position, centre, anyUp(axis));
        return;
    }
    // The light is inside the bounds: its own cone.
    const float halfAngle = std::acos(std::clamp(light.spotCosOuter, 0.02f, 0.999f));
    plan.tsmAxis = direction;
    plan.tsmClipFromWorld = glm::perspective(2.0f * halfAngle, 1.0f, 1e-3f, distanceM + radiusM) *
                            glm::lookAt(position, position + direction, anyUp(direction));
}

void planGaussians(TsCharacterPlan& plan, const SssSettings& sss, float denseMmPerUv) {
    const auto& gaussians = plan.profile->gaussians();
    const int used = std::clamp(sss.gaussians, 1, static_cast<int>(gaussians.size()));
    const float widthScale2 = plan.widthScale * plan.widthScale;
    plan.gaussians.clear();
    for (int i = 0; i < used; ++i) {
        const ProfileGaussian& g = gaussians[static_cast<size_t>(i)];
        plan.gaussians.push_back(glm::vec4(g.weight, g.varianceMm2 * widthScale2));
    }
    for (size_t i = static_cast<size_t>(used); i < gaussians.size(); ++i) {
        plan.gaussians.back() += glm::vec4(gaussians[i].weight, 0.0f);
    }
    const float texelsPerMm = denseMmPerUv > 0.0f ? float(plan.size) / denseMmPerUv : 0.0f;
    plan.steps.clear();
    for (int i = 0; i < used; ++i) {
        TsStep step;
        step.gaussian = i;
        const float previous = i == 0 ? 0.0f : plan.gaussians[static_cast<size_t>(i - 1)].a;
        step.stepVarianceMm2 = plan.gaussians[static_cast<size_t>(i)].a - previous;
        step.widthTexels = std::sqrt(plan.gaussians[static_cast<size_t>(i)].a) * texelsPerMm;
        step.skipped = !plan.runs() || step.stepVarianceMm2 <= 0.0f || step.widthTexels < kMinStepTexels;
        plan.steps.push_back(step);
    }
}

}  // namespace

std::string TsCharacterPlan::skipReason() const {
    if (sssDisabled) return "SSS disabled";
    if (!visible) return "character off screen";
    if (!fallback.empty()) return "falls back to screen space: " + fallback;
    return "";
}

bool TsPlan::anyRuns() const {
    return std::any_of(characters.begin(), characters.end(), [](const TsCharacterPlan& c) { return c.runs(); });
}

bool TsPlan::anyVisibleFallback() const {
    return std::any_of(characters.begin(), characters.end(),
                       [](const TsCharacterPlan& c) { return c.visible && !c.fallback.empty(); });
}

int tsTextureSize(float texels, int minSize, int maxSize) {
    int size = minSize;
    if (std::isfinite(texels) && texels > 0.0f) {
        const float exponent = std::round(std::log2(texels));
        size = exponent >= 30.0f ? maxSize : 1 << std::max(0, static_cast<int>(exponent));
    }
    return std::clamp(size, minSize, maxSize);
}

Result<TsPlan> planTextureSpace(const Scene& scene, const std::vector<TsCharacterInput>& inputs, const ViewParams& view,
                                const LightSetup& lights) {
    TsPlan plan;
    const RenderSettings& settings = scene.settings;
    std::map<std::string, int> labelUses;
    for (const Character& character : scene.characters) labelUses[character.name]++;
    for (size_t c = 0; c < scene.characters.size() && c < inputs.size(); ++c) {
        const Character& character = scene.characters[c];
        auto submeshes = submeshScattering(scene, c, inputs[c].submeshMaterials);
        if (!submeshes.ok()) return submeshes.error();
        std::vector<TsCharacterPlan> surfaces;
        for (size_t s = 0; s < submeshes->size(); ++s) {
            const SubmeshScattering& submesh = (*submeshes)[s];
            if (submesh.profile == nullptr) continue;
            auto same = std::find_if(surfaces.begin(), surfaces.end(), [&](const TsCharacterPlan& p) {
                return submesh.sameAs({p.profile, p.widthScale});
            });
            if (same == surfaces.end()) {
                surfaces.emplace_back();
                surfaces.back().profile = submesh.profile;
                surfaces.back().widthScale = submesh.widthScale;
                same = surfaces.end() - 1;
            }
            same->submeshes.push_back(s);
        }
        for (TsCharacterPlan& surface : surfaces) {
            TsCharacterPlan p = std::move(surface);
            p.character = static_cast<int>(c);
            p.label = character.name.empty() ? "character " + std::to_string(c) : character.name;
            if (labelUses[character.name] > 1) p.label += " #" + std::to_string(c);
            if (surfaces.size() > 1) p.label += " " + p.profile->name() + " " + std::to_string(p.submeshes.front());
            const TsCharacterInput& input = inputs[c];
            const ScreenFootprint footprint = screenFootprint(input.worldBounds, view);
            p.sssDisabled = !settings.sss.enabled;
            p.visible = !p.sssDisabled && footprint.visible;
            p.nearestViewDepthM = footprint.nearestViewDepthM;
            if (!(input.uvlessSurfaceFraction <= kMaxUvlessSurfaceFraction)) {
                char why[128];
                std::snprintf(why, sizeof why, "%.0f%% of its surface has no UV area (limit %.0f%%%s)",
                              100.0 * input.uvlessSurfaceFraction, 100.0 * kMaxUvlessSurfaceFraction,
                              input.uvlessSurfaceFraction >= 1.0f ? "; the mesh has no TEXCOORD_0, or all UVs equal" : "");
                p.fallback = why;
            } else if (!(input.uvOverlapFraction <= kMaxUvOverlapFraction)) {
                char why[128];
                std::snprintf(why, sizeof why,
                              "%.1f%% of its UV texels are covered by more than one triangle (limit %.0f%%): overlapping or "
                              "mirrored UVs",
                              100.0 * input.uvOverlapFraction, 100.0 * kMaxUvOverlapFraction);
                p.fallback = why;
            }
            const float pixelsPerMm =
                p.visible ? view.pixelsPerMetreAtUnitDepth() * 1e-3f / footprint.nearestViewDepthM : 0.0f;
            const float densitySide = input.mmPerUv * pixelsPerMm;
            // The whole character's rectangle, clipping left out: the texture holds
            // all of it, and a close-up's density is the first criterion's.
            const float coverageSide = std::sqrt(kTexelsPerCoveredPixel * footprint.unclippedPixels /
                                                 std::max(input.uvCoverageFraction, 1e-4f));
            p.size = std::min(tsTextureSize(densitySide, settings.ts.minSize, settings.ts.maxSize),
                              tsTextureSize(coverageSide, settings.ts.minSize, settings.ts.maxSize));
            planGaussians(p, settings.sss, input.denseMmPerUv);

            // transmittance.enabled means "light through thin regions" in both modes.
            if (settings.ts.tsm && settings.transmittance.enabled) p.tsmLight = chooseTsmLight(scene, lights, input.worldBounds);
            if (p.tsmLight >= 0) {
                p.tsmSize = std::clamp(p.size, kMinTsmSize, kMaxTsmSize);
                fitTsm(lights.block.lights[p.tsmLight], input.worldBounds, p);
            }
            plan.characters.push_back(std::move(p));
        }
    }
    return plan;
}

}  // namespace dermis
