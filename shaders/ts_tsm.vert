// The modified translucent shadow map (Chappuis 2011 §2.5; include/TextureSpace.glsl):
// one character seen from its TSM light.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "TextureSpace.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec2 aUv;

out float vDepthM;
out vec2 vUv;
out vec3 vWorldNormal;

void main() {
    vec3 worldPositionM = (uObject.worldFromObject * vec4(aPosition, 1.0)).xyz;
    vDepthM = tsmDepthM(worldPositionM);
    vUv = aUv;
    vWorldNormal = mat3(uObject.normalWorldFromObject) * aNormal;
    gl_Position = uTs.tsmClipFromWorld * vec4(worldPositionM, 1.0);
}
