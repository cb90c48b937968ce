// Texture-space step 4: one separable pass of one incremental Gaussian step
// (Chappuis 2011 §2.2.4, listing 2.2; include/TextureSpace.glsl is the manual).
// Taps sit at offset_k x sigma along U or V, sigma in mm turned into UV by
// the stretch map (mm per UV unit) at the centre texel. The kernel's weights
// and offsets come from engine/sss/BlurKernel.cpp and sigma is divided by
// the kernel's own spread, so a step blurs by exactly its variance.
// Texels with no stretch (gutters, degenerate triangles) keep their value;
// taps on empty texels (alpha 0) are dropped and the rest renormalised.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 1) uniform sampler2D uStretch;

layout(location = 0) out vec4 oBlurred;

// A tap never reaches further than this many texels per standard deviation.
const float kMaxTexelsPerSigma = 64.0;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(uInput, texel, 0);
    vec2 direction = uTs.blur.xy;
    float stretchMm = dot(texelFetch(uStretch, texel, 0).rg, direction);
    if (centre.a <= 0.0 || !(stretchMm > 0.0)) {
        oBlurred = centre;
        return;
    }
    float texelUv = uTs.size.y;
    float sigmaUv = min(uTs.blur.z / stretchMm, kMaxTexelsPerSigma * texelUv);
    vec2 uv = (vec2(texel) + 0.5) * texelUv;
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    int taps = int(uTs.blur.w);
    for (int k = 0; k < taps; ++k) {
        vec4 value = texture(uInput, uv + direction * (uTs.kernel[k].x * sigmaUv));
        float weight = value.a > 0.0 ? uTs.kernel[k].y : 0.0;
        sum += value * weight;
        weightSum += weight;
    }
    oBlurred = weightSum > 0.0 ? sum / weightSum : centre;
}
