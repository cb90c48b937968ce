// Sanitising with counts, and the planted NaN of `dermis stress --plant-nan`
// (docs/stress.md, "Counting and reading every target").
//
// Every sanitiser replaces NaN, clamps +-Inf and out-of-range values, and adds
// one to the matching counter of SanitiseBlock for each value it replaced, so
// a NaN is reported by the pass that made it even though the pass erases it.
// The graph backend zeroes the counters before each pass and reads them after
// it when counting is on (engine/gl/SanitiseCounters.h). A value in range
// costs only the compares; with counting off (every frame outside `dermis
// stress`) a replaced one costs a uniform test, not an atomic: a saturated
// light clamps every lit pixel, and one counter for all of them would
// serialise the pass. C++ includes this file through gpu/UniformBlocks.h.
#ifndef DERMIS_SANITISE_GLSL
#define DERMIS_SANITISE_GLSL

#include "SharedConstants.glsl"

#ifdef __cplusplus
struct SanitiseBlock {
#else
layout(std430, binding = DERMIS_BINDING_SANITISE_COUNTERS) buffer SanitiseBlock {
#endif
    uint nanCount;       // NaN replaced
    uint infCount;       // +-Inf clamped to the range
    uint overflowCount;  // finite values above the range clamped (fp16 max for colours, 1 for AO)
    uint negativeCount;  // finite values below the range clamped (0 for colours and AO)
    uint plantNan;       // 1: debugPlant returns NaN in this pass
    uint counting;       // 1: the counters above are read after this pass
    uint padding1;
    uint padding2;
}
#ifndef __cplusplus
uSanitise
#endif
;

#ifndef __cplusplus

const float kHalfMax = 65504.0;  // largest finite fp16

// x with NaN replaced by nanValue and clamped to [low, high]; counts a replaced value.
float sanitiseValue(float x, float low, float high, float nanValue) {
    if (x >= low && x <= high) return x;  // false for NaN
    if (uSanitise.counting == 0u) return isnan(x) ? nanValue : clamp(x, low, high);
    if (isnan(x)) {
        atomicAdd(uSanitise.nanCount, 1u);
        return nanValue;
    }
    if (isinf(x)) {
        atomicAdd(uSanitise.infCount, 1u);
    } else if (x > high) {
        atomicAdd(uSanitise.overflowCount, 1u);
    } else {
        atomicAdd(uSanitise.negativeCount, 1u);
    }
    return clamp(x, low, high);
}

// A pass's output, or NaN when this pass is the planted one.
float debugPlant(float x) { return uSanitise.plantNan != 0u ? uintBitsToFloat(0x7fc00000u) : x; }
vec2 debugPlant(vec2 x) { return vec2(debugPlant(x.x), x.y); }
vec3 debugPlant(vec3 x) { return vec3(debugPlant(x.x), x.yz); }
vec4 debugPlant(vec4 x) { return vec4(debugPlant(x.x), x.yzw); }

// Every sanitiser plants first, so a planted NaN meets the pass's own counter.
float sanitiseRange(float x, float low, float high, float nanValue) {
    return sanitiseValue(debugPlant(x), low, high, nanValue);
}
vec2 sanitiseRange(vec2 v, float low, float high) {
    v = debugPlant(v);
    return vec2(sanitiseValue(v.x, low, high, 0.0), sanitiseValue(v.y, low, high, 0.0));
}
vec4 sanitiseRange(vec4 v, float low, float high) {
    v = debugPlant(v);
    return vec4(sanitiseValue(v.x, low, high, 0.0), sanitiseValue(v.y, low, high, 0.0),
                sanitiseValue(v.z, low, high, 0.0), sanitiseValue(v.w, low, high, 0.0));
}

// Keeps colours storable in fp16 targets and free of NaN/Inf.
vec3 sanitizeColour(vec3 c) {
    c = debugPlant(c);
    return vec3(sanitiseValue(c.r, 0.0, kHalfMax, 0.0), sanitiseValue(c.g, 0.0, kHalfMax, 0.0),
                sanitiseValue(c.b, 0.0, kHalfMax, 0.0));
}

#endif
#endif
