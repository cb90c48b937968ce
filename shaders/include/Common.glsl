// Small helpers every shader may use. All of them are finite for every input
// (docs/stress.md).
#ifndef DERMIS_COMMON_GLSL
#define DERMIS_COMMON_GLSL

#include "UniformBlocks.glsl"
#include "Sanitise.glsl"

const float kPi = 3.14159265358979;
const float kTiny = 1e-8;

// normalize() that returns `fallback` instead of NaN for a zero vector.
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float lengthSquared = dot(v, v);
    return lengthSquared > kTiny ? v * inversesqrt(lengthSquared) : fallback;
}

// albedo^exponent for the pre-/post-scatter split (Chappuis 2011 §2.2.4). GLSL's
// pow(0, 0) is undefined (NaN on many GPUs); here x^0 = 1 and 0^e = 0 for e > 0.
vec3 albedoPower(vec3 albedo, float exponent) {
    if (exponent <= 0.0) return vec3(1.0);
    return pow(max(albedo, vec3(0.0)), vec3(exponent));
}

// Octahedral unit-vector encoding (Cigolle et al. 2014): two components.
vec2 octWrap(vec2 v) { return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
vec2 encodeNormal(vec3 n) {
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), kTiny);
    return n.z >= 0.0 ? n.xy : octWrap(n.xy);
}
vec3 decodeNormal(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = clamp(-n.z, 0.0, 1.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return safeNormalize(n, vec3(0.0, 0.0, 1.0));
}

// View-space position of a pixel from its depth-buffer value in [0,1].
vec3 viewPositionFromDepth(vec2 uv, float depth, mat4 viewFromClip) {
    vec4 clip = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 view = viewFromClip * clip;
    return view.xyz / (abs(view.w) > kTiny ? view.w : kTiny);
}

// View-space position of a pixel from its linear view depth (metres), for
// passes that cannot sample the depth buffer because it is attached for the
// stencil test. Works for any projection with the eye at the origin.
vec3 viewPositionFromViewDepth(vec2 uv, float viewDepthM, mat4 viewFromClip) {
    vec3 farPoint = viewPositionFromDepth(uv, 1.0, viewFromClip);
    return farPoint * (viewDepthM / max(-farPoint.z, kTiny));
}

// G-buffer depth keys (layout in UniformBlocks.glsl).
const uint kKeyDepthMask = (1u << DERMIS_KEY_DEPTH_BITS) - 1u;
uint makeDepthKey(int slot, float viewDepthM) {
    float units = clamp(viewDepthM * DERMIS_KEY_UNITS_PER_M, 0.0, float(kKeyDepthMask));
    return (uint(slot) << DERMIS_KEY_DEPTH_BITS) | uint(units);
}
float viewDepthFromKey(uint key) { return float(key & kKeyDepthMask) / DERMIS_KEY_UNITS_PER_M; }
// The SSS profile slot, 0 for opaque pixels and the background.
int slotFromKey(uint key) {
    int slot = int(key >> DERMIS_KEY_DEPTH_BITS);
    return slot == DERMIS_BACKGROUND_SLOT ? 0 : slot;
}
bool isBackgroundKey(uint key) { return int(key >> DERMIS_KEY_DEPTH_BITS) == DERMIS_BACKGROUND_SLOT; }
// Depth difference in mm between two keys; +infinity-like when they belong to
// different slots (so every depth weight of it is 0).
float keyDistanceMm(uint a, uint b) {
    if ((a >> DERMIS_KEY_DEPTH_BITS) != (b >> DERMIS_KEY_DEPTH_BITS)) return DERMIS_OTHER_PROFILE_DISTANCE_MM;
    int units = int(a & kKeyDepthMask) - int(b & kKeyDepthMask);
    return float(abs(units)) * (1000.0 / DERMIS_KEY_UNITS_PER_M);
}

// Pixel coordinates to a float in [0, 1): xorshift-multiply rounds with the
// constants of Wellons' "lowbias32" integer hash.
float hashToUnit(uvec2 pixel) {
    uint h = pixel.x * 0x9E3779B9u ^ (pixel.y + 0x7F4A7C15u) * 0x85EBCA6Bu;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return float(h >> 8) * (1.0 / 16777216.0);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// The upper tail 1 - Phi(z) of the standard normal for z >= 0, from erf as
// Abramowitz & Stegun 1964 (7.1.26) approximate it (|error| < 1.5e-7 in erf);
// computed directly, so the tail keeps its precision where Phi(z) rounds to 1.
float normalUpperTail(float z) {
    float x = z * 0.70710678;
    float t = 1.0 / (1.0 + 0.3275911 * x);
    float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return 0.5 * poly * exp(-x * x);
}

// The standard normal CDF Phi(z), any z.
float normalCdf(float z) { return z >= 0.0 ? 1.0 - normalUpperTail(z) : normalUpperTail(-z); }

#endif
