#include "plan/FramePlan.h"

#include "plan/LevelOfDetail.h"
#include "plan/ScreenFootprint.h"
#include "plan/SssVariant.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

// Of all characters, or of the visible ones; a unit box at the origin when there are none.
Bounds unionBounds(const std::vector<CharacterPlacement>& characters, bool visibleOnly) {
    Bounds out{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const CharacterPlacement& c : characters) {
        if (visibleOnly && !c.visible) continue;
        out.min = glm::min(out.min, c.worldBounds.min);
        out.max = glm::max(out.max, c.worldBounds.max);
    }
    if (out.min.x > out.max.x) return Bounds{glm::vec3(-0.5f), glm::vec3(0.5f)};
    return out;
}

void markVisibleCharacters(const FrameRequest& request, FramePlan& plan) {
    for (CharacterPlacement& c : plan.characters) {
        const ScreenFootprint footprint = screenFootprint(c.worldBounds, plan.view);
        c.visible = request.everyCharacterVisible || footprint.visible;
        c.culledBecause = c.visible ? "" : std::string("off screen: ") + footprint.outside;
        c.footprintPixels = footprint.unclippedPixels;
    }
}

// Each visible character's level of detail (plan/LevelOfDetail.h), by its
// pixels per object unit at its nearest view depth.
void chooseLevelsOfDetail(const Scene& scene, const SceneGeometry& geometry, const FrameRequest& request, FramePlan& plan) {
    const float maxErrorPx = scene.settings.lod.maxErrorPx;
    for (size_t c = 0; c < plan.characters.size(); ++c) {
        CharacterPlacement& placement = plan.characters[c];
        const std::vector<float>& errors = geometry.lodErrorsObject(c);
        if (!placement.visible || errors.empty() || request.everyCharacterVisible) continue;
        const glm::mat4& m = placement.worldFromObject;
        const float metresPerUnit =
            std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
        const float depthM = screenFootprint(placement.worldBounds, plan.view).nearestViewDepthM;
        const float pixelsPerUnit = plan.view.pixelsPerMetreAtUnitDepth() / std::max(depthM, plan.view.nearM) * metresPerUnit;
        const int previous = c < request.previousLods.size() ? request.previousLods[c] : -1;
        placement.lod = chooseLodLevel(errors, pixelsPerUnit, maxErrorPx, previous);
        placement.lodErrorPx = placement.lod > 0 ? errors[size_t(placement.lod - 1)] * pixelsPerUnit : 0.0f;
    }
}

// The frame's lights: the scene's first DERMIS_MAX_LIGHTS, then the lights
// taken out of the environment (plan/EnvironmentPlan.h; there are none
// unless the scene left room for them).
std::vector<Light> frameLights(const Scene& scene, const EnvironmentPlan& environment) {
    std::vector<Light> lights(scene.lights.begin(),
                              scene.lights.begin() + std::min<ptrdiff_t>(ptrdiff_t(scene.lights.size()), DERMIS_MAX_LIGHTS));
    lights.insert(lights.end(), environment.lights.begin(), environment.lights.end());
    return lights;
}

// Each shadowed light's map is fitted to the visible characters (its
// receivers) and holds the casters that can shade them: chosen with the map
// fitted to the receivers alone, which sets its axes and texel size, then
// the map's depth range is stretched to reach them.
std::vector<ShadowCasters> fitShadows(const Scene& scene, const std::vector<Light>& lights, FramePlan& plan) {
    const Bounds receivers = unionBounds(plan.characters, true);
    const LightSetup aroundReceivers = setupLights(lights, receivers, scene.settings.shadow);
    std::vector<Bounds> bounds;
    std::vector<bool> visible;
    for (const CharacterPlacement& c : plan.characters) {
        bounds.push_back(c.worldBounds);
        visible.push_back(c.visible);
    }
    std::vector<ShadowCasters> casters;
    std::vector<Bounds> reach(lights.size(), receivers);
    for (int light : aroundReceivers.shadowedLights) {
        casters.push_back(chooseShadowCasters(aroundReceivers.block.lights[light], bounds, visible));
        if (!casters.back().kept.empty()) reach[static_cast<size_t>(light)] = casters.back().reach;
    }
    plan.lights = setupLights(lights, receivers, scene.settings.shadow, reach);
    return casters;
}

// A shadowed light is a back light when it is behind some visible SSS
// character as the camera sees it (Jimenez et al. 2010); a character off
// screen has no pixel to transmit it.
void markBackLights(const Scene& scene, FramePlan& plan) {
    for (int index : plan.lights.shadowedLights) {
        const Light& light = plan.lights.sources[static_cast<size_t>(index)];
        // Transmittance reads a 2-D map's thickness: a point light's cube atlas gives none.
        if (light.type == LightType::Point) continue;
        bool behind = false;
        for (size_t c = 0; c < plan.characters.size() && !behind; ++c) {
            bool visibleSss = false;
            for (int slot : plan.sss.slotsOfCharacter[c])
                visibleSss = visibleSss || (slot > 0 && plan.sss.slots[static_cast<size_t>(slot - 1)].visible);
            behind = visibleSss && plan.characters[c].visible &&
                     isBackLight(light, plan.characters[c].worldBounds, scene.camera.positionM);
        }
        plan.lights.block.lights[index].backLight = behind ? 1.0f : 0.0f;
        plan.anyBackLight = plan.anyBackLight || behind;
    }
}

std::string shadowPassName(const LightSetup& lights, int lightIndex) {
    const LightType type = lights.sources[static_cast<size_t>(lightIndex)].type;
    return "shadow:light" + std::to_string(lightIndex) +
           (type == LightType::Directional ? "(dir)" : type == LightType::Spot ? "(spot)" : "(point)");
}

// An animated caster's shadow depends on its pose too: its palette and morph
// weights join the cache key after the light and the kept casters' transforms.
void appendPoseKey(const CharacterPlacement& caster, std::vector<float>& key) {
    if (!caster.animated) return;
    for (const glm::mat4& m : caster.pose.palette) key.insert(key.end(), &m[0][0], &m[0][0] + 16);
    key.insert(key.end(), caster.pose.morphWeights.begin(), caster.pose.morphWeights.end());
}

// The character's pose at this frame's time, and its bounds in that pose.
// The clip is looked up by name every frame, so an edited scene (the viewer's
// clip list) plays the new one.
Status poseCharacter(const Scene& scene, const SceneGeometry& geometry, size_t index, float timeS,
                     CharacterPlacement& placement, Bounds& objectBounds) {
    const Rig& rig = geometry.rig(index);
    if (rig.empty()) return success();
    auto resolved = resolveAnimationClip(scene, index, rig);
    if (!resolved.ok()) return resolved.error();
    const int clip = *resolved;
    const Character& character = scene.characters[index];
    const CharacterAnimation& animation = character.animation;
    placement.animated = true;
    placement.clipTimeS = characterClipTime(animation, rig, clip, timeS);
    placement.pose = poseRig(rig, clip, placement.clipTimeS);
    placement.skinPassName = "skin:" + character.name + "#" + std::to_string(index);
    rigPoseBounds(rig, placement.pose, objectBounds.min, objectBounds.max);
    return success();
}

void planShadows(const Scene& scene, const ShadowCache& cache, std::vector<ShadowCasters> casters, FramePlan& plan) {
    const auto mapSize = static_cast<uint32_t>(scene.settings.shadow.mapSize);
    for (size_t slot = 0; slot < plan.lights.shadowedLights.size(); ++slot) {
        ShadowSlotPlan s;
        s.light = plan.lights.shadowedLights[slot];
        s.passName = shadowPassName(plan.lights, s.light);
        s.desc = {mapSize, mapSize, graph::TextureFormat::R32F};
        if (plan.lights.sources[static_cast<size_t>(s.light)].type == LightType::Point) {
            const uint32_t face = cubeShadowFaceSize(scene.settings.shadow.mapSize);
            s.desc = {3 * face, 2 * face, graph::TextureFormat::R32F};  // the cube atlas (plan/LightSetup.h)
        }
        s.casters = std::move(casters[slot]);
        std::vector<glm::mat4> transforms;
        for (int c : s.casters.kept) transforms.push_back(plan.characters[static_cast<size_t>(c)].worldFromObject);
        s.key = ShadowCache::makeKey(plan.lights.block.lights[s.light], s.casters.kept, transforms);
        for (int c : s.casters.kept) s.castersDrawLevels |= plan.characters[static_cast<size_t>(c)].animated;
        for (int c : s.casters.kept) {
            appendPoseKey(plan.characters[static_cast<size_t>(c)], s.key);
            // the triangles it casts with
            s.key.push_back(s.castersDrawLevels ? float(plan.characters[static_cast<size_t>(c)].lod) : 0.0f);
        }
        s.current = cache.isCurrent(static_cast<int>(slot), s.desc, s.key);
        plan.shadows.push_back(std::move(s));
    }
}

// The texture-space planner's inputs: bounds and the UV layout's stretch in
// world millimetres (d'Eon & Luebke 2007 §16.3.2).
std::vector<TsCharacterInput> textureSpaceInputs(SceneGeometry& geometry, const FramePlan& plan) {
    std::vector<TsCharacterInput> inputs;
    for (size_t c = 0; c < plan.characters.size(); ++c) {
        TsCharacterInput input;
        input.worldBounds = plan.characters[c].worldBounds;
        input.submeshMaterials = geometry.submeshMaterials(c);
        if (plan.sss.hasSss(c)) {
            const UvLayout& layout = geometry.uvLayout(c, plan.characters[c].metresPerUnit());
            const float mmPerUnit = plan.characters[c].metresPerUnit() * 1000.0f;
            input.mmPerUv = layout.medianStretch * mmPerUnit;
            input.denseMmPerUv = layout.denseStretch * mmPerUnit;
            input.uvlessSurfaceFraction = layout.uvlessSurfaceFraction;
            input.uvOverlapFraction = layout.uvOverlapFraction;
            input.uvCoverageFraction = layout.uvCoverageFraction;
        }
        inputs.push_back(input);
    }
    return inputs;
}

Status planKernel(int taps, const char* setting, BlurKernel& kernel) {
    auto made = makeGaussianKernel(taps);
    if (!made.ok()) return makeError(setting, made.error().what);
    kernel = std::move(*made);
    return success();
}

}  // namespace

bool aovReadsSss(Aov aov, bool lean) {
    return aov == Aov::Final || aov == Aov::Radiance || aov == Aov::Diffuse || (aov == Aov::Specular && lean);
}

Result<FramePlan> planFrame(const Scene& scene, SceneGeometry& geometry, const FrameRequest& request,
                            const ShadowCache& shadows) {
    if (request.width <= 0 || request.height <= 0 || request.width > kMaxFrameDimension ||
        request.height > kMaxFrameDimension) {
        return makeError("frame size", std::to_string(request.width) + "x" + std::to_string(request.height) +
                                           " is outside 1x1 .. " + std::to_string(kMaxFrameDimension) + "x" +
                                           std::to_string(kMaxFrameDimension));
    }
    if (!std::isfinite(request.timeS) || std::abs(request.timeS) > kMaxAnimationTimeS) {
        return makeError("frame time", std::to_string(request.timeS) + " s is outside +-" +
                                           std::to_string(static_cast<long long>(kMaxAnimationTimeS)) + " s");
    }
    FramePlan plan;
    plan.scene = &scene;
    plan.width = request.width;
    plan.height = request.height;
    plan.aov = request.aov;
    plan.materialMipBias = request.materialMipBias;
    plan.transmittanceSkipSigmas = request.transmittanceSkipSigmas;
    plan.view = makeViewParams(scene.camera, request.width, request.height);
    plan.lean = frameUsesLean(scene.settings);

    const size_t count = std::min(scene.characters.size(), geometry.size());
    std::vector<Bounds> bounds;
    std::vector<std::vector<SubmeshMaterial>> submeshMaterials;
    for (size_t c = 0; c < count; ++c) {
        submeshMaterials.push_back(geometry.submeshMaterials(c));
        const Character& character = scene.characters[c];
        CharacterPlacement placement;
        placement.worldFromObject = character.transform.worldFromObject(character.metresPerUnit);
        Bounds objectBounds = geometry.objectBounds(c);
        if (const Status posed = poseCharacter(scene, geometry, c, request.timeS, placement, objectBounds); !posed.ok()) {
            return posed.error();
        }
        placement.worldBounds = transformBounds(objectBounds, placement.worldFromObject);
        plan.characters.push_back(placement);
        bounds.push_back(placement.worldBounds);
    }
    plan.worldBounds = unionBounds(plan.characters, false);
    markVisibleCharacters(request, plan);
    chooseLevelsOfDetail(scene, geometry, request, plan);
    auto environment = geometry.environment(scene.environment, scene.lights.size());
    if (!environment.ok()) return environment.error();
    std::vector<glm::mat4> worldFromObject;
    for (const CharacterPlacement& placement : plan.characters) worldFromObject.push_back(placement.worldFromObject);
    plan.environment = planEnvironment(scene.environment, std::move(*environment), worldFromObject, request.timeS,
                                       request.aov == Aov::Final || request.aov == Aov::Radiance);

    auto sss = planSss(scene, bounds, plan.view, submeshMaterials);
    if (!sss.ok()) return sss.error();
    plan.sss = std::move(*sss);
    std::vector<ShadowCasters> casters = fitShadows(scene, frameLights(scene, plan.environment), plan);
    markBackLights(scene, plan);
    planShadows(scene, shadows, std::move(casters), plan);

    const bool textureSpaceMode = scene.settings.mode == SssMode::TextureSpace;
    plan.textureSpace = aovIsUvLayout(request.aov) || (textureSpaceMode && aovReadsSss(request.aov, plan.lean));
    if (plan.textureSpace) {
        auto ts = planTextureSpace(scene, textureSpaceInputs(geometry, plan), plan.view, plan.lights);
        if (!ts.ok()) return ts.error();
        plan.ts = std::move(*ts);
        if (const Status kernel = planKernel(scene.settings.ts.taps, "ts.taps", plan.tsKernel); !kernel.ok()) {
            return kernel.error();
        }
    }
    // The screen-space chain's: its own mode's, or for the characters that
    // fall back to it in texture-space mode (plan/TsPlan.h).
    if (!textureSpaceMode || plan.ts.anyVisibleFallback()) {
        if (const Status kernel = planKernel(scene.settings.sss.taps, "sss.taps", plan.sssKernel); !kernel.ok()) {
            return kernel.error();
        }
    }
    return plan;
}

void recordShadowMaps(const FramePlan& plan, const graph::RenderGraph& graph, ShadowCache& shadows) {
    for (size_t slot = 0; slot < plan.shadows.size(); ++slot) {
        const ShadowSlotPlan& s = plan.shadows[slot];
        if (graph.wasExecuted(s.passName)) shadows.record(static_cast<int>(slot), s.desc, s.key);
    }
}

bool textureSpaceDraws(const FramePlan& plan, size_t character) {
    if (!plan.textureSpace) return false;
    for (const TsCharacterPlan& ts : plan.ts.characters)
        if (static_cast<size_t>(ts.character) == character) return ts.runs();
    return false;
}

graph::TextureDesc frameOutputDesc(const FramePlan& plan) {
    return {static_cast<uint32_t>(plan.width), static_cast<uint32_t>(plan.height),
            plan.aov == Aov::Final ? graph::TextureFormat::Rgba8 : graph::TextureFormat::Rgba32F};
}

}  // namespace dermis
