#pragma once
// Scene lights -> the LightsBlock, including each shadow-casting light's
// projection fitted around the scene's bounds.
//
// Shadow maps store linear depth along the light's axis (metres), measured
// from the light's position. Directional lights get an orthographic box whose
// "position" sits behind the bounds; spot lights a perspective frustum of
// their outer cone; point lights a cube map of the distance to the light, its
// six 90-degree faces in one 3x2 atlas (cubeShadowFaceSize), taking one of the
// DERMIS_MAX_SHADOWED_LIGHTS slots like any other map. GpuLight.area carries
// the light's size for the PCSS filter (docs/shadows.md).

#include "gpu/UniformBlocks.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"

#include <vector>

namespace dermis {

struct LightSetup {
    gpu::LightsBlock block{};
    int lightCount = 0;
    std::vector<int> shadowedLights;  // light index per shadow slot
};

// A point light's cube faces are half the map size, so that its 3x2 atlas holds
// 1.5 maps' texels.
uint32_t cubeShadowFaceSize(int mapSize);

LightSetup setupLights(const std::vector<Light>& lights, const Bounds& sceneBounds, const ShadowSettings& shadows);

}  // namespace dermis
