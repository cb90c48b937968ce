#include "Common.glsl"
#include "UniformBlocks.glsl"

// GBUFFER_VERTEX_COLOUR 1 (the default): the albedo is multiplied by the
// vertex colour (COLOR_0); 0 for meshes whose colours are all white
// (render/Programs.h GBufferPrograms): one varying fewer.
#ifndef GBUFFER_VERTEX_COLOUR
#define GBUFFER_VERTEX_COLOUR 1
#endif

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUv;
layout(location = 7) in vec4 aColour;  // COLOR_0, white without one (render/GpuScene.h kColourLocation)

out vec3 vViewNormal;
out vec4 vViewTangent;  // xyz tangent, w bitangent sign
out vec2 vUv;
out vec3 vViewPositionM;
#if GBUFFER_VERTEX_COLOUR
out vec3 vColour;
#endif
#ifdef GBUFFER_TRANSFER
#include "EnvironmentTransfer.glsl"
out vec4 vEnvironment;
#endif

void main() {
    vec4 worldPosition = uObject.worldFromObject * vec4(aPosition, 1.0);
    mat3 viewFromWorld3 = mat3(uFrame.viewFromWorld);
    vViewNormal = viewFromWorld3 * (mat3(uObject.normalWorldFromObject) * aNormal);
    vViewTangent = vec4(viewFromWorld3 * (mat3(uObject.worldFromObject) * aTangent.xyz), aTangent.w);
    vUv = uObject.flipV > 0.5 ? vec2(aUv.x, 1.0 - aUv.y) : aUv;
    vViewPositionM = (uFrame.viewFromWorld * worldPosition).xyz;
#if GBUFFER_VERTEX_COLOUR
    vColour = aColour.rgb;
#endif
#ifdef GBUFFER_TRANSFER
    vEnvironment = transferIrradiance();
#endif
    gl_Position = uFrame.clipFromWorld * worldPosition;
}
