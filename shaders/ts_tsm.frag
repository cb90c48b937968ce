// The modified translucent shadow map: per texel the surface nearest the
// light (the depth test keeps it). RGBA32F: x depth (m, as tsmDepthM), yz its
// UV in the character's layout, w its normal packed (0 = empty).
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "TextureSpace.glsl"

in float vDepthM;
in vec2 vUv;
in vec3 vWorldNormal;

layout(location = 0) out vec4 oTsm;

void main() {
    oTsm = debugPlant(vec4(vDepthM, vUv, packTsmNormal(safeNormalize(vWorldNormal, -uTs.tsmAxis))));
}
