#pragma once
// Scene lights -> the LightsBlock, including each shadow-casting light's
// projection fitted around the receivers' bounds (the visible characters;
// plan/ShadowCasters.h), its depth range reaching the casters kept for it.
//
// Shadow maps store linear depth along the light's axis (metres), measured
// from the light's position. Directional lights get an orthographic box whose
// "position" sits behind the bounds; spot lights a perspective frustum of
// their outer cone; point lights a cube map of the distance to the light, its
// six 90-degree faces in one 3x2 atlas (cubeShadowFaceSize), taking one of the
// DERMIS_MAX_SHADOWED_LIGHTS slots like any other map. GpuLight.size carries
// the light's size for the PCSS filter (docs/shadows.md).

#include "gpu/UniformBlocks.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"

#include <vector>

namespace dermis {

// Which shadow filters the programs that read the frame's shadow maps compile
// (DERMIS_SHADOW_CODE, shaders/include/Shadows.glsl): the least that covers
// every shadowed light, since a CPU driver runs the code of filters no light
// uses as well (docs/shadows.md, "Only the filters a frame uses").
enum class ShadowCode {
    HardEdges = DERMIS_SHADOW_CODE_HARD_EDGES,      // delta lights with 2-D maps under the PCSS filter
    SoftEdges = DERMIS_SHADOW_CODE_SOFT_EDGES,      // those, and lights with a size under the PCSS filter
    EveryFilter = DERMIS_SHADOW_CODE_EVERY_FILTER,  // PCF 4x4, Poisson, delta point lights
};

struct LightSetup {
    gpu::LightsBlock block{};
    int lightCount = 0;
    std::vector<Light> sources;  // the lights set up, one per block entry (the frame's lights, plan/FramePlan.h)
    std::vector<int> shadowedLights;  // light index per shadow slot
    ShadowCode shadowCode = ShadowCode::HardEdges;
};

// A point light's cube faces are half the map size, so that its 3x2 atlas holds
// 1.5 maps' texels.
uint32_t cubeShadowFaceSize(int mapSize);

// `receivers` sets each map's extent: the orthographic box and the far plane
// enclose its bounding sphere. `casterReach`, per light index (missing: the
// receivers), is the box of the casters kept for that light: the near plane
// (and a directional light's origin) moves towards the light until it holds
// them; casters inside the receivers' sphere change nothing.
LightSetup setupLights(const std::vector<Light>& lights, const Bounds& receivers, const ShadowSettings& shadows,
                       const std::vector<Bounds>& casterReach = {});

}  // namespace dermis
