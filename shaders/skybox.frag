// The skybox (passes/SkyboxPass.cpp): the environment map behind everything,
// at the pixels nothing was drawn on (the far-plane triangle's depth test),
// its radiance x the intensity in the linear HDR colour before exposure. Unit
// 0 holds the map as loaded (GpuEnvironment::background), dominant light
// included.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Environment.glsl"

layout(binding = 0) uniform sampler2D uBackground;

in vec2 vUv;
layout(location = 0) out vec4 oColour;

void main() {
    vec4 viewPoint = uFrame.viewFromClip * vec4(vUv * 2.0 - 1.0, 1.0, 1.0);
    vec3 worldDirection = safeNormalize(mat3(uFrame.worldFromView) * (viewPoint.xyz / viewPoint.w), vec3(0.0, 0.0, -1.0));
    vec3 mapDirection = mat3(uEnvironment.mapFromWorld) * worldDirection;
    vec3 radiance = textureLod(uBackground, latLongUv(mapDirection), 0.0).rgb * uEnvironment.intensity;
    oColour = vec4(sanitizeColour(radiance), 1.0);
}
