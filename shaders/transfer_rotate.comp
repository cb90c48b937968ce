// Turns an animated character's per-vertex SH transfer with its skinning
// (docs/environment.md, "Animated characters"; passes/SkinningPass.cpp runs
// it after skinning.comp): each vertex's nine coefficients, made on the rest
// pose (engine/env/ShTransfer.h), rotated by the rotation of its blended
// skinning matrix, so that L.T holds for the posed vertex. The occlusion the
// pose itself creates is not in it.
//
// The rotation is the blended matrix's polar factor (Higham 1986: X <- (X +
// X^-T) / 2 until it stops changing), as env/ShTransfer.h's
// skinningRotation. A rotated function is f'(w) = f(R^T w): band 0 is kept,
// band 1 is a vector a (the coefficients in (y, z, x) order over kShBand1)
// with a' = R a, and band 2 a traceless symmetric quadratic form Q,
// f(w) = w^T Q w, with Q' = R Q R^T; the basis is that of
// engine/env/SphericalHarmonics.h.
#define DERMIS_USE_SKINNING_BLOCK
#include "UniformBlocks.glsl"
#include "SkinBlend.glsl"
#include "ShBasis.glsl"

layout(local_size_x = DERMIS_SKINNING_GROUP_SIZE) in;

layout(std430, binding = DERMIS_BINDING_SKIN_SOURCE) readonly buffer RestTransfer { float restTransfer[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_OUTPUT) writeonly buffer PosedTransfer { float posedTransfer[]; };

mat3 polarRotation(mat3 x) {
    if (abs(determinant(x)) <= 0.0) return mat3(1.0);
    for (int iteration = 0; iteration < 20; ++iteration) {
        mat3 next = 0.5 * (x + transpose(inverse(x)));
        float change = max(length(next[0] - x[0]), max(length(next[1] - x[1]), length(next[2] - x[2])));
        x = next;
        if (change < 1e-7) break;
    }
    return x;
}

void main() {
    const uint v = gl_GlobalInvocationID.x;
    if (v >= uint(uSkinning.vertexCount)) return;
    float c[9];
    for (uint i = 0u; i < 9u; ++i) c[i] = restTransfer[v * 9u + i];
    const mat3 R = polarRotation(mat3(blendedSkinningMatrix(v)));

    vec3 a = R * vec3(c[3], c[1], c[2]);  // (x, y, z) components, each over kShBand1
    mat3 Q = mat3(0.0);                    // symmetric; Q[column][row]
    Q[0][1] = Q[1][0] = 0.5 * kShBand2xy * c[4];
    Q[1][2] = Q[2][1] = 0.5 * kShBand2xy * c[5];
    Q[0][2] = Q[2][0] = 0.5 * kShBand2xy * c[7];
    Q[0][0] = -kShBand20 * c[6] + kShBand22 * c[8];
    Q[1][1] = -kShBand20 * c[6] - kShBand22 * c[8];
    Q[2][2] = 2.0 * kShBand20 * c[6];
    const mat3 turned = R * Q * transpose(R);
    const float c6 = turned[2][2] / (2.0 * kShBand20);
    const float out9[9] = float[9](c[0], a.y, a.z, a.x, 2.0 * turned[0][1] / kShBand2xy, 2.0 * turned[1][2] / kShBand2xy, c6,
                                   2.0 * turned[0][2] / kShBand2xy, (turned[0][0] + kShBand20 * c6) / kShBand22);
    for (uint i = 0u; i < 9u; ++i) posedTransfer[v * 9u + i] = out9[i];
}
