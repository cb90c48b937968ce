#pragma once
// Scene lights -> the LightsBlock, including each shadow-casting light's
// projection fitted around the scene's bounds.
//
// Shadow maps store linear depth along the light's axis (metres), measured
// from the light's position. Directional lights get an orthographic box whose
// "position" sits behind the bounds; spot lights a perspective frustum of
// their outer cone. Point lights are lit but cast no shadow (a cube-map
// shadow is future work; the loader warns).

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

LightSetup setupLights(const std::vector<Light>& lights, const Bounds& sceneBounds, const ShadowSettings& shadows);

}  // namespace dermis
