// Kelemen/Szirmay-Kalos specular (Chappuis 2011 §2.3, listings 2.3-2.5).
//
// Integration: bind the Beckmann table made by brdf/BeckmannTable.cpp to
// `beckmannTable` (R32F, DERMIS_BECKMANN_SIZE texels a side, linear filter,
// clamp to edge) and call ksSpecular() per light. The table stores
// P_H = exp(-tan^2(a)/m^2) / (m^2 cos^4(a)) in float (so the seed's
// 0.5 * pow(x, 0.1) 8-bit encoding is not needed), indexed by
// s = sqrt(1 - N.H) and by m, each with texel centres on the sample points
// (see BeckmannTable.h for why s and not N.H).
#ifndef DERMIS_SPECULAR_GLSL
#define DERMIS_SPECULAR_GLSL

#include "SharedConstants.glsl"

// Fresnel reflectance at normal incidence for skin (Chappuis 2011 §2.3, after d'Eon & Luebke).
const float kSkinF0 = DERMIS_SKIN_F0;

#ifndef DERMIS_BECKMANN_SIZE
#define DERMIS_BECKMANN_SIZE 256
#endif
#if DERMIS_BECKMANN_SIZE < 2
#error "DERMIS_BECKMANN_SIZE must be at least 2"
#endif

float beckmannPH(sampler2D beckmannTable, float nDotH, float m) {
    vec2 st = vec2(sqrt(clamp(1.0 - nDotH, 0.0, 1.0)), clamp(m, 0.0, 1.0));
    return texture(beckmannTable, (st * float(DERMIS_BECKMANN_SIZE - 1) + 0.5) / float(DERMIS_BECKMANN_SIZE)).r;
}

// Schlick's approximation (Chappuis 2011 listing 2.3).
float fresnelSchlick(vec3 H, vec3 V, float f0) {
    float base = 1.0 - clamp(dot(V, H), 0.0, 1.0);
    float exponential = pow(max(base, 0.0), 5.0);
    return exponential + f0 * (1.0 - exponential);
}

// KS BRDF times N.L (Chappuis 2011 listing 2.5): rho_s * P_H * F / |L + V|^2 * N.L.
// Finite for every input: N.H is clamped into the table, |L + V|^2 is bounded
// away from 0 (L = -V gives no highlight), and N.L <= 0 gives 0.
float ksSpecular(sampler2D beckmannTable, vec3 N, vec3 L, vec3 V, float m, float rhoS) {
    float nDotL = dot(N, L);
    if (nDotL <= 0.0) return 0.0;
    vec3 h = L + V;
    float hLengthSquared = dot(h, h);
    if (hLengthSquared < 1e-6) return 0.0;
    vec3 H = h * inversesqrt(hLengthSquared);
    float nDotH = clamp(dot(N, H), 0.0, 1.0);
    float pH = beckmannPH(beckmannTable, nDotH, m);
    float F = fresnelSchlick(H, V, kSkinF0);
    return max(pH * F / hLengthSquared, 0.0) * nDotL * rhoS;
}

#endif
