// One level of a shadow map's max-depth mip chain (passes/ShadowPass.cpp runs
// it level by level after a back light's map is drawn): each texel holds the largest
// light-space depth (m) of the surfaces its block of the map's texels holds,
// or -DERMIS_SHADOW_NO_SURFACE_M where the block holds none (the map stores
// +DERMIS_SHADOW_NO_SURFACE_M there). Level 0 stays the map; the shadow
// lookups read it with nearest filtering and never see the other levels.
// include/Transmittance.glsl reads the chain to find the points whose back
// surface lies beyond the profile's reach, and skips their rings.
#include "SharedConstants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uMap;  // the map, read at level uFinerLevel
layout(r32f, binding = 1) writeonly uniform image2D uCoarser;
layout(location = 1) uniform int uFinerLevel;

float surfaceDepth(ivec2 texel) {
    float depthM = texelFetch(uMap, texel, uFinerLevel).r;
    return depthM >= 0.5 * DERMIS_SHADOW_NO_SURFACE_M ? -DERMIS_SHADOW_NO_SURFACE_M : depthM;
}

// Finer texels per coarser texel along each axis: 4 from level 0 to level 2
// (level 1 is never read: include/Transmittance.glsl's footprints are at
// least 3 texels wide), then 2.
layout(location = 0) uniform int uFactor;

void main() {
    ivec2 coarseSize = imageSize(uCoarser);
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, coarseSize))) return;
    ivec2 fineSize = textureSize(uMap, uFinerLevel);
    // The last coarse texel of a row or column also takes the finer texels
    // past the block (sizes that do not halve evenly).
    ivec2 first = texel * uFactor;
    ivec2 last = mix(first + uFactor - 1, fineSize - 1, equal(texel, coarseSize - 1));
    last = min(last, fineSize - 1);
    float deepest = -DERMIS_SHADOW_NO_SURFACE_M;
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) deepest = max(deepest, surfaceDepth(ivec2(x, y)));
    }
    imageStore(uCoarser, texel, vec4(deepest));
}
