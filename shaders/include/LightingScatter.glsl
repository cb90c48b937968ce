// LightingScatter.glsl: what the lighting pass gives an SSS technique that
// scatters there instead of blurring (engine/render/LightingScatter.h; the
// pre-integrated technique is one). The generated "LightingTechniques.glsl"
// includes this file, then each such technique's file, then the dispatch
// (lightingScatterFalloff, lightingScatterShadowShows, lightingScatterShadow).
#ifndef DERMIS_LIGHTING_SCATTER_GLSL
#define DERMIS_LIGHTING_SCATTER_GLSL

#include "UniformBlocks.glsl"

#ifndef DERMIS_LIGHTING_TABLE_SLOT_ROWS
#error "include LightingTechniques.glsl (generated from the technique registry), not this file"
#endif

// Bound where some visible slot scatters in the lighting pass (uProfiles.anyScattersInLighting = 1):
layout(binding = 10) uniform sampler2D uScatter;  // the G-buffer's: z curvature (1/mm), w profile slot
layout(binding = DERMIS_UNIT_FIRST_PASS_EXTRA) uniform sampler2D uLightingTables;  // the slots' tables, stacked

// One pixel as such a technique sees it.
struct LightingScatterSurface {
    int technique;         // ProfileParams.lightingTechnique: 0 where the pixel's slot does not scatter here
    int slot;              // its profile slot
    float parameter;       // ProfileParams.lightingParameter
    float curvaturePerMm;  // the G-buffer's (gbuffer.frag)
};

LightingScatterSurface lightingScatterSurface(ivec2 pixel) {
    LightingScatterSurface s = LightingScatterSurface(0, 0, 0.0, 0.0);
    if (uProfiles.anyScattersInLighting == 0) return s;
    vec4 scatter = texelFetch(uScatter, pixel, 0);
    int slot = int(scatter.w + 0.5);
    if (slot <= 0 || slot > DERMIS_MAX_PROFILES || uProfiles.profiles[slot].lightingTechnique == 0) return s;
    return LightingScatterSurface(uProfiles.profiles[slot].lightingTechnique, slot, uProfiles.profiles[slot].lightingParameter,
                                  scatter.z);
}

// The table texture's (u, v) for texel coordinates (x, row) of the slot's table.
vec2 lightingTableUv(int slot, float x, float row) {
    return vec2(x / float(DERMIS_LIGHTING_TABLE_COLUMNS),
                (row + float(slot * DERMIS_LIGHTING_TABLE_SLOT_ROWS)) / float(DERMIS_LIGHTING_TABLE_SLOT_ROWS * (DERMIS_MAX_PROFILES + 1)));
}

#endif
