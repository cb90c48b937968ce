// Texture-space step 5, the gather (include/TextureSpace.glsl): the
// character's mesh again, in screen space, positioned exactly as in the
// G-buffer pass so that its depth matches the stored one.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 3) in vec2 aUv;
layout(location = 4) in vec3 aDPdu;
layout(location = 5) in vec3 aDPdv;
layout(location = 6) in float aBorderDistance;  // object units (mesh/UvLayout.h)
layout(location = DERMIS_LOCATION_TS_SEAM) in vec4 aSeamContinuation;  // UV across the nearest border, 1 at a seam, its turn (mesh/UvLayout.h)

out vec3 vWorldPositionM;
out vec2 vUv;
out vec3 vDPduM;
out vec3 vDPdvM;
out float vBorderDistanceM;
out vec4 vSeamContinuation;
// The provoking vertex's UV and continuation UV (ts_gather.frag's agreement test).
flat out vec4 vProvokingUvs;

void main() {
    vec4 worldPosition = uObject.worldFromObject * vec4(aPosition, 1.0);
    vWorldPositionM = worldPosition.xyz;
    vUv = aUv;
    vDPduM = mat3(uObject.worldFromObject) * aDPdu;
    vDPdvM = mat3(uObject.worldFromObject) * aDPdv;
    vBorderDistanceM = aBorderDistance * length(uObject.worldFromObject[0].xyz);  // uniform scale
    vSeamContinuation = aSeamContinuation;
    vProvokingUvs = vec4(aUv, aSeamContinuation.xy);
    gl_Position = uFrame.clipFromWorld * worldPosition;
}
