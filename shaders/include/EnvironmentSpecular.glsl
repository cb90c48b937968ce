// Environment specular by the split sum (Karis 2013, "Real Shading in Unreal
// Engine 4") for the Kelemen/Szirmay-Kalos lobe:
//   L_spec(V) ~= rho_s rho_dt(N.V, m) prefilteredRadiance(map, R, m) x specular occlusion,
// R = reflect(-V, N) in the map's space, rho_dt from the energy table
// (include/EnergyConservation.glsl). The map holds, per direction r,
//   sum L(l) D(h) (n.l) dw / sum D(h) (n.l) dw,  n = v = r,  h = normalize(l + r),
// the environment averaged over the Beckmann lobe of roughness m about r,
// weighted as Karis weights his importance samples (see
// engine/env/PrefilteredEnvironment.h; the lobe's Fresnel and 1 / |L + V|^2
// are left to rho_dt).
//
// Binding: upload PrefilteredEnvironment::levels() (env/PrefilteredEnvironment.h)
// as one 2D texture: glTexStorage2D(GL_TEXTURE_2D, DERMIS_PREFILTERED_LEVELS,
// GL_RGBA16F or GL_RGBA32F, 2 DERMIS_PREFILTERED_BASE_HEIGHT,
// DERMIS_PREFILTERED_BASE_HEIGHT), level k from levels()[k], row 0 (the map's
// top, +Y) first; GL_TEXTURE_WRAP_S = GL_REPEAT (longitude wraps),
// GL_TEXTURE_WRAP_T = GL_CLAMP_TO_EDGE (the poles),
// GL_TEXTURE_MIN_FILTER = GL_LINEAR_MIPMAP_LINEAR, GL_TEXTURE_MAG_FILTER =
// GL_LINEAR. The chain stops at 16 x 8, so the immutable storage must have
// exactly DERMIS_PREFILTERED_LEVELS levels (or set GL_TEXTURE_MAX_LEVEL to
// DERMIS_PREFILTERED_LEVELS - 1). Directions are in the map's space: apply
// the environment's rotation to R before the call.
//
// Levels: level 0 is the map (a mirror), level k >= 1 the lobe of roughness
// DERMIS_PREFILTERED_ROUGHNESS_OF_LEVEL(k) (SharedConstants.glsl: m doubles
// per level up to m = 1 at the last); rougher lobes read the last level.
#ifndef DERMIS_ENVIRONMENT_SPECULAR_GLSL
#define DERMIS_ENVIRONMENT_SPECULAR_GLSL

#include "Common.glsl"
#include "SharedConstants.glsl"

// The lat-long texture coordinates of a unit direction, the inverse of
// engine/env/SphericalHarmonics.h's latLongDirection: u = phi / (2 pi) with
// phi the longitude about +Y from +Z towards +X, v = theta / pi with theta the
// colatitude from +Y. u runs over (-0.5, 0.5]; GL_REPEAT makes that [0, 1).
// atan(0, 0) is undefined in GLSL, so the poles read u = 0.
vec2 latLongUv(vec3 direction) {
    float phi = (direction.x == 0.0 && direction.z == 0.0) ? 0.0 : atan(direction.x, direction.z);
    float theta = acos(clamp(direction.y, -1.0, 1.0));
    return vec2(phi / (2.0 * kPi), theta / kPi);
}

// The fractional mip level holding roughness m (Beckmann), clamped to the chain.
float prefilteredLevel(float m) {
    return DERMIS_PREFILTERED_LEVEL_OF_ROUGHNESS(m);
}

// The prefiltered radiance about `directionInMapSpace` (unit) for roughness m:
// bilinear within a level, linear between the two levels around m.
vec3 prefilteredRadiance(sampler2D map, vec3 directionInMapSpace, float m) {
    return textureLod(map, latLongUv(directionInMapSpace), prefilteredLevel(m)).rgb;
}

#endif
