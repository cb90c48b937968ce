// Uniform blocks shared by C++ and GLSL: the one definition of each block.
//
// C++ includes this file through engine/render/UniformBlocks.h, which maps
// the GLSL types onto glm and static_asserts every size; GLSL includes it
// with `#include "UniformBlocks.glsl"`. Layout is std140, so:
//   - only vec4, ivec4 and mat4 members (scalars are packed into vec4s by
//     hand, and the comment says which component is what);
//   - arrays only of vec4 or of structs made of them.
// Matrix names read destination-from-source: clipFromWorld maps world-space
// positions to clip space.

#ifndef DERMIS_UNIFORM_BLOCKS_GLSL
#define DERMIS_UNIFORM_BLOCKS_GLSL

#ifdef __cplusplus
#define DERMIS_BLOCK(Name, Binding) struct Name
#define DERMIS_BLOCK_END(instance) ;
#else
#define DERMIS_BLOCK(Name, Binding) layout(std140, binding = Binding) uniform Name
#define DERMIS_BLOCK_END(instance) instance;
#endif

#define DERMIS_MAX_LIGHTS 64
#define DERMIS_MAX_SHADOWED_LIGHTS 4

#define DERMIS_BINDING_FRAME 0
#define DERMIS_BINDING_LIGHTS 1
#define DERMIS_BINDING_OBJECT 2

#define DERMIS_LIGHT_DIRECTIONAL 0
#define DERMIS_LIGHT_SPOT 1
#define DERMIS_LIGHT_POINT 2

DERMIS_BLOCK(FrameBlock, DERMIS_BINDING_FRAME) {
    mat4 clipFromWorld;
    mat4 viewFromWorld;
    mat4 worldFromView;
    mat4 clipFromView;
    mat4 viewFromClip;
    vec4 cameraPositionM;   // xyz: camera position in world space (metres)
    vec4 viewport;          // x: width, y: height (pixels), z: 1/width, w: 1/height
    vec4 depthRangeM;       // x: near, y: far (metres)
    vec4 ambient;           // rgb: uniform ambient irradiance
    vec4 background;        // rgb: background radiance
    vec4 shading;           // x: exposure, y: pre-scatter mix ratio, z: light count, w: output AOV id
} DERMIS_BLOCK_END(uFrame)

struct GpuLight {
    mat4 shadowClipFromWorld;  // light's clip space, for shadow-map lookups
    vec4 positionType;         // xyz: position (metres), w: DERMIS_LIGHT_* type
    vec4 directionShadow;      // xyz: unit direction the light travels, w: shadow-map slot or -1
    vec4 radiance;             // rgb: colour * intensity
    vec4 spot;                 // x: cos(inner), y: cos(outer)
    vec4 shadowParams;         // x: constant bias (m), y: slope bias (texels), z: texel size (m at 1 m / ortho), w: filter (0 grid, 1 poisson)
    vec4 shadowDepth;          // x: near (m), y: far (m), z: orthographic (1) or perspective (0)
};

DERMIS_BLOCK(LightsBlock, DERMIS_BINDING_LIGHTS) {
    GpuLight lights[DERMIS_MAX_LIGHTS];
} DERMIS_BLOCK_END(uLights)

DERMIS_BLOCK(ObjectBlock, DERMIS_BINDING_OBJECT) {
    mat4 worldFromObject;
    mat4 normalWorldFromObject;  // inverse transpose of worldFromObject
    vec4 albedoRoughness;        // rgb: albedo tint (linear), w: Beckmann roughness m
    vec4 material;               // x: rho_s, y: profile id (0 = none), z: has albedo map, w: has normal map
    vec4 mapping;                // x: flip v (1 = sample at 1 - v), y: light index (shadow pass)
} DERMIS_BLOCK_END(uObject)

#endif
