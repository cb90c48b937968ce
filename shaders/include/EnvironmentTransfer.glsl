// Per-vertex SH transfer (docs/environment.md, "Per-vertex transfer"; Chappuis
// 2011 §3.3): a vertex's nine coefficients T_lm of V(w) max(N.w, 0), made on
// the CPU (engine/env/ShTransfer.h) in the mesh's object space, reach the
// vertex shader as three vec3 attributes at DERMIS_LOCATION_TRANSFER..+2.
// Its environment irradiance is L.T with L the light in the same space
// (uObject.environmentSh); interpolated across the triangle, like Chappuis's.
// Needs UniformBlocks.glsl first.
#ifndef DERMIS_ENVIRONMENT_TRANSFER_GLSL
#define DERMIS_ENVIRONMENT_TRANSFER_GLSL

#include "ShBasis.glsl"

layout(location = DERMIS_LOCATION_TRANSFER) in vec3 aTransfer0;
layout(location = DERMIS_LOCATION_TRANSFER + 1) in vec3 aTransfer1;
layout(location = DERMIS_LOCATION_TRANSFER + 2) in vec3 aTransfer2;

// a: the share of the sky the vertex sees, T_00 / (pi Y_00), for specular
// occlusion. rgb, by uEnvironment.diffuseMode:
//   sh:  the environment irradiance L.T (>= 0);
//   map: the share of the map's light that occlusion leaves, which
//        include/Environment.glsl multiplies the map's exact irradiance by.
//        The CPU uploads s A_l Y_lm(n) per vertex (visibleShareTransfer,
//        engine/env/ShTransfer.h), so T_00 / (pi Y_00) is s itself: read
//        directly, with no quotient of two SH sums to condition.
// In map mode a is that same s (the map-weighted visible share); in sh mode
// it is the cosine-weighted one.
vec4 transferIrradiance() {
    const float kUnoccludedT00 = 0.886227;  // pi x Y_00: the transfer of a vertex that sees everything
    float visible = clamp(aTransfer0.x / kUnoccludedT00, 0.0, 1.0);
    if (int(uEnvironment.diffuseMode + 0.5) == DERMIS_ENV_DIFFUSE_MAP) return vec4(vec3(visible), visible);
    float t[9] = float[9](aTransfer0.x, aTransfer0.y, aTransfer0.z, aTransfer1.x, aTransfer1.y, aTransfer1.z,
                          aTransfer2.x, aTransfer2.y, aTransfer2.z);
    vec3 irradiance = vec3(0.0);
    for (int i = 0; i < 9; ++i) irradiance += uObject.environmentSh[i].rgb * t[i];
    return vec4(max(irradiance, vec3(0.0)), visible);
}

#endif
