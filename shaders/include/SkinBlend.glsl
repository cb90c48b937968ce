// The blended skinning matrix of one vertex: its (up to) four palette
// entries weighted (linear-blend skinning; glTF 2.0 §3.7.3). Shared by
// skinning.comp and transfer_rotate.comp; the includer binds the influences
// and the palette at DERMIS_BINDING_SKIN_INFLUENCES and _PALETTE.
#ifndef DERMIS_SKIN_BLEND_GLSL
#define DERMIS_SKIN_BLEND_GLSL

struct Influence {
    uvec4 joints;  // xy: two 16-bit palette indices each
    vec4 weights;
};

layout(std430, binding = DERMIS_BINDING_SKIN_INFLUENCES) readonly buffer SkinInfluences { Influence influences[]; };
layout(std430, binding = DERMIS_BINDING_SKIN_PALETTE) readonly buffer SkinPalette { mat4 palette[]; };

mat4 blendedSkinningMatrix(uint v) {
    const uvec2 packedJoints = influences[v].joints.xy;
    const uint joint[4] = uint[4](packedJoints.x & 0xFFFFu, packedJoints.x >> 16, packedJoints.y & 0xFFFFu, packedJoints.y >> 16);
    const vec4 weight = influences[v].weights;
    mat4 m = mat4(0.0);
    for (int i = 0; i < 4; ++i)
        if (weight[i] != 0.0) m += weight[i] * palette[joint[i]];
    return m;
}

#endif
