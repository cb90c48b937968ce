// PreintegratedSkin.glsl: pre-integrated skin shading (Penner & Borshukov
// 2011), the screen-space technique "preintegrated" (sss.technique). It is
// this file's manual.
//
// WHAT IT DOES
//   The lighting pass replaces each light's N.L by D(N.L, curvature), the
//   light a sphere of that curvature scatters to a point whose normal is at
//   that angle from the light: the profile's falloff pre-integrated around
//   the sphere on the CPU (engine/sss/PreintegratedTable.h says how, and why
//   its kernel is the profile's 1-D marginal). Light thus wraps past the
//   terminator and reddens it where the surface is curved. No pass blurs the
//   irradiance: `sss init` passes its slots' irradiance on unchanged
//   (plan/SssPlan.cpp, initial weight 1).
//
// THE TABLE
//   Per profile slot (its profile and width scale) a table of
//   DERMIS_PREINTEGRATED_COSINES x DERMIS_PREINTEGRATED_CURVATURES texels,
//   sampled linearly with clamping: u = (N.L + 1) / 2 and
//   v = sqrt(curvature / DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM) (the square
//   root gives the gently curved cheek, where the falloff changes fastest with
//   curvature, most rows). Texel centres hold the exact values. The slots'
//   tables are stacked in one 2-D texture, slot s in rows s x CURVATURES up
//   (render/PreintegratedTables.h); v is clamped to the slot's texel centres so
//   that no row of its neighbours leaks in. (A 2-D array texture sampled in the
//   lights' loop crashed llvmpipe's shader compiler, LLVM 15.)
//
// CURVATURE
//   Per pixel from the G-buffer's scatter target (z, 1/mm): gbuffer.frag's
//   |dN| / |dP| of the interpolated vertex normal and view position, exact
//   (1/r) on a sphere of radius r. Normal maps do not change it.
//
// WHAT IT LEAVES OUT
//   Shadows multiply the falloff as in the other techniques: a shadow edge
//   is not softened by the profile (Penner & Borshukov 2011's penumbra
//   table is not built). The environment's diffuse light and the ambient
//   are not scattered. Bumps smaller than a triangle scatter nothing.
#ifndef DERMIS_PREINTEGRATED_SKIN_GLSL
#define DERMIS_PREINTEGRATED_SKIN_GLSL

#if DERMIS_PREINTEGRATED_COSINES < 2 || DERMIS_PREINTEGRATED_CURVATURES < 2
#error "the pre-integrated table needs at least 2 x 2 texels"
#endif

// The slot's scattered share of one light: D(N.L, curvature) per channel.
vec3 preintegratedFalloff(sampler2D tables, int slot, float nDotL, float curvaturePerMm) {
    const float rows = float(DERMIS_PREINTEGRATED_CURVATURES);
    float u = 0.5 * clamp(nDotL, -1.0, 1.0) + 0.5;
    float v = sqrt(clamp(curvaturePerMm / float(DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM), 0.0, 1.0));
    float row = clamp(v * rows, 0.5, rows - 0.5) + float(slot) * rows;
    return textureLod(tables, vec2(u, row / (rows * float(DERMIS_MAX_PROFILES + 1))), 0.0).rgb;
}

#endif
