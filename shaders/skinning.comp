// GPU skinning: morph targets, then linear-blend skinning, of one character's
// vertices into the vertex buffer every pass draws (anim/Rig.h gives the
// maths and deformRig its CPU reference; passes/SkinningPass.cpp runs it once
// per frame per animated character).
//
//   morphed  = source + sum_s w_s delta_s            (glTF 2.0 §3.7.2.2)
//   M        = sum_i weight_i palette[joint_i]        (glTF 2.0 §3.7.3)
//   position = M x morphed;  normal = normalize(inverse(transpose(M3)) n)
//   tangent  = normalize(M3 t), w kept
//
// Buffers (bindings in include/SharedConstants.glsl), one element per vertex
// unless said: the source (DERMIS_SKIN_SOURCE_FLOATS floats: Mesh.h's Vertex
// in the bind pose, then its dP/du and dP/dv), influences (uvec4: xy two
// 16-bit palette indices each; vec4 weights summing to one), morph deltas
// (DERMIS_MORPH_DELTA_FLOATS floats per slot per vertex, slot-major), the
// palette (mat4 per entry), the morph weights (float per slot), the output
// (a Vertex each: the vertex buffer every pass draws) and, when
// uSkinning.writeDerivatives is 1, the deformed dP/du and dP/dv for the
// texture-space stretch map: M3 x the bind pose's, the same first-order
// transform as the tangent's (weights held constant; morphs left out).

#define DERMIS_USE_SKINNING_BLOCK
#include "UniformBlocks.glsl"

#include "SkinBlend.glsl"

layout(local_size_x = DERMIS_SKINNING_GROUP_SIZE) in;


layout(std430, binding = DERMIS_BINDING_SKIN_SOURCE) readonly buffer SkinSource { float sourceFloats[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_MORPHS) readonly buffer SkinMorphs { float morphDeltas[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_MORPH_WEIGHTS) readonly buffer SkinMorphWeights { float morphWeights[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_OUTPUT) writeonly buffer SkinOutput { float outputFloats[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_DERIVATIVES) writeonly buffer SkinDerivatives { float derivativeFloats[]; };

vec3 readVec3(uint at) { return vec3(sourceFloats[at], sourceFloats[at + 1u], sourceFloats[at + 2u]); }
vec3 readDelta(uint at) { return vec3(morphDeltas[at], morphDeltas[at + 1u], morphDeltas[at + 2u]); }
vec3 normalizeOrKeep(vec3 v) { float l = length(v); return l > 0.0 ? v / l : v; }

void main() {
    const uint vertexCount = uint(uSkinning.vertexCount);
    const uint slots = uint(uSkinning.morphSlots);
    const uint v = gl_GlobalInvocationID.x;
    if (v >= vertexCount) return;
    const uint base = v * DERMIS_SKIN_SOURCE_FLOATS;
    const uint outBase = v * DERMIS_VERTEX_FLOATS;
    vec3 position = readVec3(base);
    vec3 normal = readVec3(base + 3u);
    vec4 tangent = vec4(readVec3(base + 6u), sourceFloats[base + 9u]);
    if (slots > 0u) {
        for (uint s = 0u; s < slots; ++s) {
            const float w = morphWeights[s];
            if (w == 0.0) continue;
            const uint at = (s * vertexCount + v) * DERMIS_MORPH_DELTA_FLOATS;
            position += w * readDelta(at);
            normal += w * readDelta(at + 3u);
            tangent.xyz += w * readDelta(at + 6u);
        }
        normal = normalizeOrKeep(normal);
        tangent.xyz = normalizeOrKeep(tangent.xyz);
    }
    const mat4 m = blendedSkinningMatrix(v);
    const mat3 linear = mat3(m);
    position = (m * vec4(position, 1.0)).xyz;
    normal = normalizeOrKeep(transpose(inverse(linear)) * normal);
    tangent.xyz = normalizeOrKeep(linear * tangent.xyz);

    const float vertexOut[DERMIS_VERTEX_FLOATS] = float[DERMIS_VERTEX_FLOATS](
        position.x, position.y, position.z, normal.x, normal.y, normal.z, tangent.x, tangent.y, tangent.z, tangent.w,
        sourceFloats[base + 10u], sourceFloats[base + 11u]);
    for (uint i = 0u; i < DERMIS_VERTEX_FLOATS; ++i) outputFloats[outBase + i] = vertexOut[i];
    if (uSkinning.writeDerivatives == 1) {
        const vec3 dPdu = linear * readVec3(base + 12u);
        const vec3 dPdv = linear * readVec3(base + 15u);
        const uint at = v * DERMIS_SKIN_DERIVATIVE_FLOATS;
        const float derivativeOut[DERMIS_SKIN_DERIVATIVE_FLOATS] =
            float[DERMIS_SKIN_DERIVATIVE_FLOATS](dPdu.x, dPdu.y, dPdu.z, dPdv.x, dPdv.y, dPdv.z);
        for (uint i = 0u; i < DERMIS_SKIN_DERIVATIVE_FLOATS; ++i) derivativeFloats[at + i] = derivativeOut[i];
    }
}
