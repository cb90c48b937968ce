// Texture-space step 4: one separable pass of one incremental Gaussian step
// (Chappuis 2011 §2.2.4, listing 2.2; include/TextureSpace.glsl is the manual).
// sigma (mm) is turned into texels by the stretch map (mm per UV unit) at the
// centre texel. Texels with no stretch (gutters, degenerate triangles) keep
// their value; taps on empty texels (alpha 0) are dropped and the rest
// renormalised.
//
// Two ways to blur, by the width in texels:
//  - up to kMaxExactRadiusTexels texels within 3 sigma: every texel, weighted
//    by the Gaussian integrated over it (its cell; the outer cells take the
//    tails). On a texture seen as constant per texel this is the exact
//    convolution at the texel centres. A few wide taps would step: Chappuis
//    2011's 7 taps spaced 1 sigma apart turn a sharp edge (the irradiance is
//    sharp where no narrower Gaussian smoothed it) into a staircase, 5.8% of
//    the step off on the analytic edge (docs/texture-space.md).
//  - wider: the kernel's taps (engine/sss/BlurKernel.cpp) at offset_k x sigma,
//    bilinear, sigma divided by the kernel's own spread so that a step blurs
//    by exactly its variance. There the input is already blurred by the
//    narrower steps, smoother than the taps' spacing.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 1) uniform sampler2D uStretch;

layout(location = 0) out vec4 oBlurred;

// A tap never reaches further than this many texels per standard deviation.
const float kMaxTexelsPerSigma = 64.0;
// The widest exact blur: 3 sigma within this many texels (33 fetches).
const int kMaxExactRadiusTexels = 16;

vec4 exactBlur(ivec2 texel, ivec2 step, float sigmaTexels, int radius, vec4 centre) {
    ivec2 size = textureSize(uInput, 0);
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    float lower = 0.0;  // the CDF at the cell's lower edge; the outer cells reach to infinity
    for (int k = -radius; k <= radius; ++k) {
        float upper = k == radius ? 1.0 : normalCdf((float(k) + 0.5) / sigmaTexels);
        float weight = upper - lower;
        lower = upper;
        ivec2 p = texel + step * k;
        if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) continue;
        vec4 value = texelFetch(uInput, p, 0);
        if (value.a <= 0.0) continue;
        sum += value * weight;
        weightSum += weight;
    }
    return weightSum > 0.0 ? sum / weightSum : centre;
}

void shade() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(uInput, texel, 0);
    vec2 direction = uTs.blurDirection;
    float stretchMm = dot(texelFetch(uStretch, texel, 0).rg, direction);
    if (centre.a <= 0.0 || !(stretchMm > 0.0)) {
        oBlurred = centre;
        return;
    }
    float sigmaTexels = min(uTs.stepSigmaMm / stretchMm * uTs.sideTexels, kMaxTexelsPerSigma);
    // Less what the gather's bilinear reads add (params.w, passes/TsUvPasses.cpp).
    sigmaTexels = sqrt(max(sigmaTexels * sigmaTexels - uTs.omittedVarianceTexels2, 0.0));
    int radius = int(ceil(3.0 * sigmaTexels));
    if (radius <= kMaxExactRadiusTexels) {
        oBlurred = exactBlur(texel, ivec2(direction), max(sigmaTexels, 1e-3), max(radius, 1), centre);
        return;
    }
    float texelUv = uTs.texelUv;
    float sigmaUv = min(uTs.blurSigmaMm / stretchMm, kMaxTexelsPerSigma * texelUv);
    vec2 uv = (vec2(texel) + 0.5) * texelUv;
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    int taps = int(uTs.blurTaps);
    for (int k = 0; k < taps; ++k) {
        vec4 value = texture(uInput, uv + direction * (uTs.kernel[k].x * sigmaUv));
        float weight = value.a > 0.0 ? uTs.kernel[k].y : 0.0;
        sum += value * weight;
        weightSum += weight;
    }
    oBlurred = weightSum > 0.0 ? sum / weightSum : centre;
}

// The pass's output goes through the planted NaN of docs/stress.md.
void main() {
    shade();
    oBlurred = debugPlant(oBlurred);
}
