// Shadow-map lookups with percentage-closer filtering.
//
// The shadow pass stores linear depth along the light's axis in metres (R32F),
// so the same map serves shadows and the transmittance thickness. A receiver
// is lit where its own light-space depth minus the bias is no further than the
// stored occluder depth. The bias is slope-scaled: constant + slope * texel
// footprint * tan(angle between N and L) (Papanikolaou 2013 §3).
//
// Two filters (GpuLight.shadowParams.w, DERMIS_SHADOW_FILTER_*):
//   PCF4X4: a 4x4 grid of taps, box-weighted (Chappuis 2011 §2.4);
//   POISSON: 16 Poisson-disc taps rotated per pixel by interleaved gradient noise
//      (Papanikolaou 2013 §3), trading banding for noise.
#ifndef DERMIS_SHADOWS_GLSL
#define DERMIS_SHADOWS_GLSL

const vec2 kPoissonDisc[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

float interleavedGradientNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Light-space linear depth (metres) of a world position.
float lightLinearDepth(GpuLight light, vec3 worldPositionM) {
    return dot(worldPositionM - light.positionType.xyz, light.directionShadow.xyz);
}

// Fraction of the light that reaches worldPositionM, in [0,1].
float shadowVisibility(sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, vec2 pixel) {
    vec4 clip = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
    if (clip.w <= kTiny) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;

    float receiverDepthM = lightLinearDepth(light, worldPositionM);
    vec3 L = -light.directionShadow.xyz;
    if (light.positionType.w != float(DERMIS_LIGHT_DIRECTIONAL)) L = safeNormalize(light.positionType.xyz - worldPositionM, N);
    float cosTheta = clamp(dot(N, L), 0.05, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    // Texel footprint in metres at the receiver: constant for orthographic,
    // growing with distance for perspective maps.
    float texelM = light.shadowParams.z * (light.shadowDepth.z > 0.5 ? 1.0 : max(receiverDepthM, 0.0));
    float biasM = light.shadowParams.x + light.shadowParams.y * texelM * min(tanTheta, 10.0);
    float testDepthM = receiverDepthM - biasM;

    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    float lit = 0.0;
    if (int(light.shadowParams.w + 0.5) == DERMIS_SHADOW_FILTER_PCF4X4) {
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 4; ++x) {
                vec2 offset = (vec2(x, y) - 1.5) * texel;
                lit += testDepthM <= texture(shadowMap, uv + offset).r ? 1.0 : 0.0;
            }
        }
    } else {
        float angle = 6.2831853 * interleavedGradientNoise(pixel);
        mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
        for (int i = 0; i < 16; ++i) {
            vec2 offset = rotation * kPoissonDisc[i] * 2.0 * texel;
            lit += testDepthM <= texture(shadowMap, uv + offset).r ? 1.0 : 0.0;
        }
    }
    return lit / 16.0;
}

#endif
