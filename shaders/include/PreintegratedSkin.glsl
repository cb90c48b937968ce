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
//   curvature, most rows). Texel centres hold the exact values. Each slot's
//   falloff and shadow tables (DERMIS_PREINTEGRATED_SLOT_ROWS rows) are its
//   table in the lighting pass's stacked texture (include/LightingScatter.glsl,
//   engine/render/LightingScatter.h); x and the row are clamped to the texel
//   centres of the table read so that no row of a neighbour leaks in.
//
// CURVATURE
//   Per pixel from the G-buffer's scatter target (z, 1/mm): gbuffer.frag's
//   |dN| / |dP| of the interpolated vertex normal and view position, exact
//   (1/r) on a sphere of radius r. Normal maps do not change it.
//
// SHADOWS
//   A shadowed light's visibility is replaced by the light the profile
//   scatters across its shadow edge (Penner & Borshukov 2011's pre-integrated
//   shadows; sss/PreintegratedShadow.h has the model and its table): the
//   shadow map's coverage of a disc of radius k sigma sqrt(1 + q^2) around the
//   receiver, in its tangent plane (k = DERMIS_PREINTEGRATED_SHADOW_STDDEVS,
//   sigma = ProfileParams.lightingParameter, q = h / (2 sigma), h the light's
//   penumbra half-width from PCSS's blocker search, at least one map texel,
//   stretched onto the surface by 1 / cos(N, L)) and q look up the scattered
//   shadow (rgb), which multiplies the falloff, and the light's own
//   visibility (alpha), which the specular keeps. Where the surface rises
//   above the tangent plane by less than a tap's distance, the tap counts
//   as lit (include/Shadows.glsl, surfaceDiscPcf).
//
// WHAT IT LEAVES OUT
//   The environment's diffuse light and the ambient are not scattered. Bumps
//   smaller than a triangle scatter nothing. A shadow edge that is not
//   straight across the disc (a corner, a thin shadow, a concave receiver
//   that rises above its tangent plane) is read as if it were.
#ifndef DERMIS_PREINTEGRATED_SKIN_GLSL
#define DERMIS_PREINTEGRATED_SKIN_GLSL

#include "PreintegratedConstants.glsl"
#include "LightingScatter.glsl"
#include "Shadows.glsl"

#if DERMIS_PREINTEGRATED_COSINES < 2 || DERMIS_PREINTEGRATED_CURVATURES < 2
#error "the pre-integrated table needs at least 2 x 2 texels"
#endif
#if DERMIS_PREINTEGRATED_SHADOW_ROWS < 1
#error "the pre-integrated shadow table needs at least one row"
#endif
#if DERMIS_LIGHTING_TABLE_COLUMNS < DERMIS_PREINTEGRATED_COSINES || DERMIS_LIGHTING_TABLE_SLOT_ROWS < DERMIS_PREINTEGRATED_SLOT_ROWS
#error "the lighting tables' texture is smaller than the pre-integrated table (engine/scene/SssTechniquePreintegrated.cpp)"
#endif

// The slot's scattered share of one light: D(N.L, curvature) per channel.
vec3 preintegratedFalloff(LightingScatterSurface s, float nDotL) {
    const float rows = float(DERMIS_PREINTEGRATED_CURVATURES);
    const float columns = float(DERMIS_PREINTEGRATED_COSINES);
    float x = clamp((0.5 * clamp(nDotL, -1.0, 1.0) + 0.5) * columns, 0.5, columns - 0.5);
    float y = sqrt(clamp(s.curvaturePerMm / float(DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM), 0.0, 1.0));
    return textureLod(uLightingTables, lightingTableUv(s.slot, x, clamp(y * rows, 0.5, rows - 0.5)), 0.0).rgb;
}

// Whether the scattered shadow can show at this pixel: the slot's sigma
// (s.parameter, mm) covers DERMIS_PREINTEGRATED_SHADOW_MIN_SIGMA_PX on screen.
// Further away the plain shadow lookup is used: it costs less (it skips most
// taps where PCSS's blocker search finds nothing), and the scattering is under
// a pixel.
bool preintegratedShadowShows(LightingScatterSurface s, float viewDepthM) {
    return s.parameter * 1e-3 * uFrame.pixelsPerMetreAtUnitDepth / max(viewDepthM, 1e-4) >= float(DERMIS_PREINTEGRATED_SHADOW_MIN_SIGMA_PX);
}

// One shadowed light seen by the slot's skin (nDotL: N.L of the light's
// direction): rgb the light it scatters across the shadow edge, alpha the
// light's own visibility (SHADOWS above).
vec4 preintegratedShadow(LightingScatterSurface s, sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, float nDotL) {
    vec2 uv;
    ShadowFrame f;
    if (!shadowReceiver(light, worldPositionM, N, uv, f)) return vec4(1.0);
    float sigmaM = s.parameter * 1e-3;
    // One map texel: the sharpest edge the map resolves (a delta light's).
    float halfWidthM = f.metresPerTexel;
    if (light.size > 0.0 && int(light.shadowFilter + 0.5) == DERMIS_SHADOW_FILTER_PCSS) {
        halfWidthM = max(pcssPenumbraHalfWidthM(shadowMap, light, f, light.shadowNearM), halfWidthM);
    }
    // The skin scatters along its surface, so the disc lies in the receiver's
    // tangent plane, not across the light as PCSS's does; a penumbra across
    // the light lands on the surface stretched by 1 / cos(N, L) across an
    // edge that runs perpendicular to the tilt (taken as the usual case: a
    // terminator's own shadow, a nose's on the cheek).
    halfWidthM /= clamp(nDotL, 0.2, 1.0);
    float q = halfWidthM / (2.0 * sigmaM);
    float coverage = surfaceDiscPcf(shadowMap, light, f, float(DERMIS_PREINTEGRATED_SHADOW_STDDEVS) * sigmaM * sqrt(1.0 + q * q));
    const float rows = float(DERMIS_PREINTEGRATED_SHADOW_ROWS);
    float x = coverage * float(DERMIS_PREINTEGRATED_COSINES - 1) + 0.5;
    float row = clamp(q / (1.0 + q) * rows, 0.5, rows - 0.5) + float(DERMIS_PREINTEGRATED_CURVATURES);
    return textureLod(uLightingTables, lightingTableUv(s.slot, x, row), 0.0);
}

#endif
