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

// a: the cosine-weighted share of the sky the vertex sees, T_00 / (pi Y_00),
// for specular occlusion. rgb, by uEnvironment.diffuseMode:
//   sh:  the environment irradiance L.T (>= 0);
//   map: the share of the light that occlusion leaves, L.T over the
//        unoccluded L.T_0 (T_0 the clamped cosine about the vertex normal,
//        A_l Y_lm(n)), which include/Environment.glsl multiplies the map's
//        exact irradiance by. Where the vertex faces away from nearly all
//        the light the quotient is ill-conditioned: kShareFloor of the mean
//        irradiance pi L_00 Y_00 is added to both sides (to the numerator at
//        the visible share a), so the share tends to a there. Clamped to
//        [0, 1.5], not 1: the rays' noise about 1 on an open vertex would
//        otherwise only ever darken (docs/environment.md, "Occlusion").
vec4 transferIrradiance(vec3 objectNormal) {
    const float kUnoccludedT00 = 0.886227;  // pi x Y_00: the transfer of a vertex that sees everything
    const float kShareFloor = 0.05;
    float t[9] = float[9](aTransfer0.x, aTransfer0.y, aTransfer0.z, aTransfer1.x, aTransfer1.y, aTransfer1.z,
                          aTransfer2.x, aTransfer2.y, aTransfer2.z);
    vec3 irradiance = vec3(0.0);
    for (int i = 0; i < 9; ++i) irradiance += uObject.environmentSh[i].rgb * t[i];
    irradiance = max(irradiance, vec3(0.0));
    float visible = clamp(t[0] / kUnoccludedT00, 0.0, 1.0);
    if (int(uEnvironment.diffuseMode + 0.5) != DERMIS_ENV_DIFFUSE_MAP) return vec4(irradiance, visible);
    vec3 unoccluded = shIrradiance(uObject.environmentSh, normalize(objectNormal));
    vec3 floorIrradiance = kShareFloor * kUnoccludedT00 * max(uObject.environmentSh[0].rgb, vec3(0.0));
    vec3 share = (irradiance + floorIrradiance * visible) / max(unoccluded + floorIrradiance, vec3(1e-20));
    return vec4(clamp(share, 0.0, 1.5), visible);
}

#endif
