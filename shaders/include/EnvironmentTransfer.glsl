// Per-vertex SH transfer (docs/environment.md, "Per-vertex transfer"; Chappuis
// 2011 §3.3): a vertex's nine coefficients T_lm of V(w) max(N.w, 0), made on
// the CPU (engine/env/ShTransfer.h) in the mesh's object space, reach the
// vertex shader as three vec3 attributes at DERMIS_LOCATION_TRANSFER..+2.
// Its environment irradiance is L.T with L the light in the same space
// (uObject.environmentSh); interpolated across the triangle, like Chappuis's.
// Needs UniformBlocks.glsl first.
#ifndef DERMIS_ENVIRONMENT_TRANSFER_GLSL
#define DERMIS_ENVIRONMENT_TRANSFER_GLSL

layout(location = DERMIS_LOCATION_TRANSFER) in vec3 aTransfer0;
layout(location = DERMIS_LOCATION_TRANSFER + 1) in vec3 aTransfer1;
layout(location = DERMIS_LOCATION_TRANSFER + 2) in vec3 aTransfer2;

// rgb: the environment irradiance L.T (>= 0); a: the cosine-weighted share of
// the sky the vertex sees, T_00 / (pi Y_00), for specular occlusion.
vec4 transferIrradiance() {
    const float kUnoccludedT00 = 0.886227;  // pi x Y_00: the transfer of a vertex that sees everything
    float t[9] = float[9](aTransfer0.x, aTransfer0.y, aTransfer0.z, aTransfer1.x, aTransfer1.y, aTransfer1.z,
                          aTransfer2.x, aTransfer2.y, aTransfer2.z);
    vec3 irradiance = vec3(0.0);
    for (int i = 0; i < 9; ++i) irradiance += uObject.environmentSh[i].rgb * t[i];
    return vec4(max(irradiance, vec3(0.0)), clamp(t[0] / kUnoccludedT00, 0.0, 1.0));
}

#endif
