// Texture-space passes that rasterise a character into its own UV layout
// (stretch and irradiance, include/TextureSpace.glsl): each vertex lands at
// its UV, with what the fragment shaders need in world space.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUv;
layout(location = 4) in vec3 aDPdu;  // object units per UV unit (mesh/UvLayout.h)
layout(location = 5) in vec3 aDPdv;
layout(location = 7) in vec4 aColour;  // COLOR_0 (render/GpuScene.h kColourLocation)
layout(location = DERMIS_LOCATION_TS_BURIED) in float aBuried;  // 1 inside the body (mesh/UvLayout.h)

out vec3 vWorldPositionM;
out vec3 vWorldNormal;
out vec4 vWorldTangent;  // xyz tangent, w bitangent sign
out vec2 vMapUv;         // where the material's maps are sampled (flip_v applied)
out vec3 vDPduM;         // metres per UV unit
out vec3 vDPdvM;
out vec3 vColour;
out float vBuried;
#include "EnvironmentTransfer.glsl"
out vec4 vEnvironment;  // L.T and the visible share (occlusion "transfer"; 0 when the mesh has no transfer)

void main() {
    vWorldPositionM = (uObject.worldFromObject * vec4(aPosition, 1.0)).xyz;
    vWorldNormal = mat3(uObject.normalWorldFromObject) * aNormal;
    vWorldTangent = vec4(mat3(uObject.worldFromObject) * aTangent.xyz, aTangent.w);
    vMapUv = uObject.flipV > 0.5 ? vec2(aUv.x, 1.0 - aUv.y) : aUv;
    vDPduM = mat3(uObject.worldFromObject) * aDPdu;
    vDPdvM = mat3(uObject.worldFromObject) * aDPdv;
    vColour = aColour.rgb;
    vBuried = aBuried;
    vEnvironment = transferIrradiance();
    // Texel (x, y) of an N x N target holds uv = ((x, y) + 0.5) / N, so that
    // texture(map, uv) reads back what was written here.
    gl_Position = vec4(aUv * 2.0 - 1.0, 0.0, 1.0);
}
