// Transmittance through thin regions: light that enters where a shadowed
// light meets the character and leaves at a point x behind it (an ear, the
// rim of a nostril). Both modes use it: screen space adds it into the
// irradiance before the SSS blur, texture space into its gathered diffuse
// light (docs/screen-space.md, "Transmittance against the reference").
//
// THE MODEL (d'Eon & Luebke 2007's translucent shadow maps, carried out over
// the light's shadow map instead of one texel of it)
//   The reference carries light through a thin part by the profile over 3-D
//   distance: x receives R(|x - y|) E(y) dA from every point y the light
//   meets, E(y) = radiance cos(theta_y). Over the plane perpendicular to the
//   light ray through x, dA cos(theta_y) is that plane's area element, so the
//   cosine cancels:
//     T(x) = radiance x integral over the plane of R(|x - y(p)|) dA_p,
//   y(p) the first surface the light meets along the ray through p, which is
//   what the shadow map stores. With R = sum_i w_i G(v_i, r),
//   G(v, r) = exp(-r^2 / 2v) / (2 pi v) (d'Eon & Luebke 2007) and
//   |x - y|^2 = delta^2 + rho^2 (delta along the ray, rho across it):
//     T(x) = radiance x sum_i w_i integral exp(-delta(p)^2 / 2v_i) G2(v_i, rho) dA_p.
//   For a flat slab of thickness s facing the light this is
//   sum_i w_i exp(-s^2 / 2v_i) (profileTransmittance, the closed form).
//
// QUADRATURE
//   Rings around x, their radii in units of the widest Gaussian's sigma
//   (kBackRingEdges). A ring's radial mass for Gaussian i,
//   exp(-a^2 / 2v_i) - exp(-b^2 / 2v_i), is exact, so a Gaussian much narrower
//   than the ring spacing is still integrated right; its kBackTapsPerRing taps
//   each read delta from the shadow map. The last ring reaches to infinity,
//   so a flat slab comes out exact.
//   - 24 taps per ring: where a thin rim's edge crosses the rings, the angular
//     quadrature decides how much of it they see. On the thin wedge of
//     tests/render/test_sss.cpp (0.28-0.97 mm) 6 / 12 / 16 / 24 / 48 taps read
//     12.7 / 9.1 / 10.7 / 5.2 / 4.5% (red) against the dense integral, and the
//     default head's scatter error in texture space 1.06 / 1.00 / 0.99 / 0.98 /
//     0.98% (docs/texture-space.md, "The transmittance's rings"). Most pixels
//     skip the rings (backSurfaceBeyondReach), so the pass costs 1.2-1.3x the
//     6 taps' (20 -> 25 ms on the default head, 20 -> 26 ms on the scan, at
//     640x360 on llvmpipe).
//   - The centre disc is the slab at x's own thickness s, facing as x's surface
//     does: its share carries saturate(-N.L), as the back-normal
//     transmittance of Jimenez et al. 2010 does for the whole plane. Without
//     it, a point beside a shadow terminator, whose map texel holds its own
//     surface a fraction of a millimetre away, took light at full strength.
//   - A ring tap whose y lies less than DERMIS_SELF_THICKNESS_MM behind x's
//     tangent plane is x's own surface, whose light the SSS blur already
//     carries; from there to DERMIS_OWN_SURFACE_RAMP_END_MM it counts in part
//     (smoothstep). The shading normal's tilt spreads its own surface over
//     a few tenths of a millimetre at the outer rings.
//   - A point whose back surfaces all lie DERMIS_TRANSMITTANCE_SKIP_SIGMAS
//     widest sigmas beyond the rings' reach (backSurfaceBeyondReach, from the
//     back light's max-depth mips) skips the rings: they would add under
//     1.5e-8 of the light.
//   Calibration (default.json and the head scan, `dermis compare --errors`
//   at 320x180, scatter error ss): ramp end 0.5 mm: 1.97% / 1.23%; 0.75 mm:
//   1.96% / 1.16%; 1.0 mm: 2.06% / 1.14%. docs/screen-space.md has the table.
#ifndef DERMIS_TRANSMITTANCE_GLSL
#define DERMIS_TRANSMITTANCE_GLSL

// Light-space depth (m) of the first surface over worldPositionM; false
// outside the map, where nothing is known to be lit.
bool firstSurfaceDepthM(sampler2D shadowMap, GpuLight light, vec3 worldPositionM, out float depthM) {
    vec4 clip = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
    if (clip.w <= kTiny) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return false;
    depthM = texture(shadowMap, uv).r;
    return true;
}

// Stored depth of the first surface along the light ray through
// worldPositionM; outside the map, the point's own depth (it is the surface).
float shadowMapDepthM(sampler2D shadowMap, GpuLight light, vec3 worldPositionM) {
    float depthM;
    return firstSurfaceDepthM(shadowMap, light, worldPositionM, depthM) ? depthM : lightLinearDepth(light, worldPositionM);
}

// Thickness in mm along the light ray, or -1 where the point is the surface
// nearest the light (less than DERMIS_SELF_THICKNESS_MM behind it, in front
// of it at the light's silhouette, or outside the map): that point is lit
// directly, its neighbours' light reaches it through the blur, and it takes
// no transmitted light. `shrinkMm` moves the point inwards along N first
// (Papanikolaou 2013 §4.3; default 0).
float thicknessMm(sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, float shrinkMm) {
    vec3 shrunkM = worldPositionM - N * (shrinkMm * 1e-3);
    float occluderM = shadowMapDepthM(shadowMap, light, shrunkM);
    float sMm = (lightLinearDepth(light, shrunkM) - occluderM) * 1000.0;
    return sMm < DERMIS_SELF_THICKNESS_MM ? -1.0 : sMm;
}

// A flat slab of thickness sMm facing the light: sum_i w_i exp(-s^2 / 2v_i),
// the plane integral above in closed form. For KHR_materials_volume, whose
// thickness the file gives, and for characters too small on screen for the
// rings (thinRegionTransmittance).
vec3 profileTransmittance(ProfileParams profile, float sMm) {
    vec3 t = vec3(0.0);
    int count = profile.gaussianCount;
    for (int i = 0; i < count; ++i) {
        float varianceMm2 = max(profile.gaussians[i].a, 1e-6);
        t += profile.gaussians[i].rgb * exp(-sMm * sMm / (2.0 * varianceMm2));
    }
    return t;
}

float backLightFactor(vec3 N, vec3 L) { return clamp(dot(-N, L), 0.0, 1.0); }

const int kBackRings = 6;
const int kBackTapsPerRing = 24;
// Ring edges and tap radii in units of the widest Gaussian's sigma; ring 0 is the centre disc.
const float kBackRingEdges[kBackRings + 1] =
    float[](0.0, DERMIS_TRANSMITTANCE_CENTRE_DISC_SIGMAS, 0.25, 0.5, 1.0, 2.0, 1e6);
const float kBackRingRadii[kBackRings] = float[](0.0, 0.175, 0.375, 0.75, 1.5, 2.6);
// A Gaussian with less of its mass in a ring is left out there (the narrow ones in the outer rings).
const float kNegligibleMass = 1e-5;

// Two unit vectors across the ray and each other, the rings' axes.
void acrossRay(vec3 ray, out vec3 across1, out vec3 across2) {
    across1 = normalize(cross(ray, abs(ray.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    across2 = cross(ray, across1);
}

// The profile's widest Gaussian's sigma (mm): variances increase.
float widestSigmaMm(ProfileParams profile) { return sqrt(max(profile.gaussians[max(profile.gaussianCount - 1, 0)].a, 1e-6)); }

// T(x) / radiance (the model above) for x at thickness centreMm (thicknessMm,
// not -1), N its shading normal, towardsLight the unit vector to the light,
// sigmaMaxMm = widestSigmaMm(profile).
vec3 backSurfaceTransmittance(sampler2D shadowMap, GpuLight light, ProfileParams profile, vec3 x, vec3 N,
                              vec3 towardsLight, float centreMm, float sigmaMaxMm) {
    int count = profile.gaussianCount;
    vec3 ray = -towardsLight;
    vec3 across1, across2;
    acrossRay(ray, across1, across2);
    // Light-space depth runs along the light's axis (2-D maps) or the ray (cube maps).
    float depthPerRayM = isCubeShadow(light) ? 1.0 : max(dot(ray, light.direction), 0.05);
    vec3 t = vec3(0.0);
    for (int ring = 0; ring < kBackRings; ++ring) {
        int taps = ring == 0 ? 1 : kBackTapsPerRing;
        float innerMm = kBackRingEdges[ring] * sigmaMaxMm;
        float outerMm = kBackRingEdges[ring + 1] * sigmaMaxMm;
        float radiusMm = kBackRingRadii[ring] * sigmaMaxMm;
        // Each Gaussian's radial mass in the ring, shared by its taps.
        float massPerTap[DERMIS_MAX_PROFILE_GAUSSIANS];
        for (int i = 0; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
            if (i >= count) break;
            float twoVarianceMm2 = 2.0 * max(profile.gaussians[i].a, 1e-6);
            massPerTap[i] = (exp(-innerMm * innerMm / twoVarianceMm2) - exp(-outerMm * outerMm / twoVarianceMm2)) / float(taps);
        }
        for (int k = 0; k < taps; ++k) {
            float deltaMm = centreMm;
            float share = backLightFactor(N, towardsLight);
            if (ring > 0) {
                // Every other ring turned by half a tap, so that taps do not line up radially.
                float angle = (float(k) + 0.5 * float(ring & 1)) * (6.2831853 / float(taps));
                vec3 p = x + (across1 * cos(angle) + across2 * sin(angle)) * (radiusMm * 1e-3);
                float depthM;
                if (!firstSurfaceDepthM(shadowMap, light, p, depthM)) continue;
                deltaMm = (lightLinearDepth(light, p) - depthM) / depthPerRayM * 1000.0;
                vec3 y = p - ray * (deltaMm * 1e-3);
                share = smoothstep(DERMIS_SELF_THICKNESS_MM, DERMIS_OWN_SURFACE_RAMP_END_MM, dot(x - y, N) * 1000.0);
            }
            if (share <= 0.0) continue;
            vec3 tap = vec3(0.0);
            for (int i = 0; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
                if (i >= count) break;
                if (massPerTap[i] < kNegligibleMass) continue;
                float twoVarianceMm2 = 2.0 * max(profile.gaussians[i].a, 1e-6);
                tap += profile.gaussians[i].rgb * (exp(-deltaMm * deltaMm / twoVarianceMm2) * massPerTap[i]);
            }
            t += tap * share;
        }
    }
    return t;
}

// True when the rings around x cannot carry more than exp(-k^2 / 2) of the
// light, k = uFrame.transmittanceSkipSigmas (0: never): every first surface
// over the rings' footprint lies at least k sigmaMaxMm in front of x along
// the ray. A tap p at distance r <= reach from x has light depth at least
// x's less r, its first surface at most the deepest the map's max-depth mips
// (shaders/shadow_max.comp) hold over the footprint, and delta >= their
// difference (depthPerRayM <= 1); each Gaussian's masses over the rings sum
// to 1 and its weight is at most 1, so T <= exp(-(k sigma_max)^2 / 2v_max).
// The block level is the first whose blocks are wider than the footprint, so
// its four corners' blocks cover it. Not for cube atlases (their faces).
bool backSurfaceBeyondReach(sampler2D shadowMap, GpuLight light, vec3 x, vec3 towardsLight, float centreMm,
                            float sigmaMaxMm) {
    float skipSigmas = uFrame.transmittanceSkipSigmas;
    if (!(skipSigmas > 0.0) || isCubeShadow(light) || centreMm < skipSigmas * sigmaMaxMm) return false;
    float reachMm = kBackRingRadii[kBackRings - 1] * sigmaMaxMm;
    vec4 clip = light.shadowClipFromWorld * vec4(x, 1.0);
    if (clip.w <= kTiny) return false;
    vec2 size = vec2(textureSize(shadowMap, 0));
    vec2 centreTexel = (clip.xy / clip.w * 0.5 + 0.5) * size;
    vec3 across1, across2;
    acrossRay(-towardsLight, across1, across2);
    float radiusTexels = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec3 offset = (k < 2 ? across1 : across2) * ((k % 2 == 0 ? 1.0 : -1.0) * reachMm * 1e-3);
        vec4 edge = light.shadowClipFromWorld * vec4(x + offset, 1.0);
        if (edge.w <= kTiny) return false;
        radiusTexels = max(radiusTexels, length((edge.xy / edge.w * 0.5 + 0.5) * size - centreTexel));
    }
    radiusTexels += 1.0;  // the nearest-texel reads round to a neighbour
    int level = int(ceil(log2(2.0 * radiusTexels + 1.0)));
    if (level >= textureQueryLevels(shadowMap)) return false;
    ivec2 levelSize = textureSize(shadowMap, level);
    ivec2 lo = clamp(ivec2(floor(centreTexel - radiusTexels)), ivec2(0), ivec2(size) - 1) >> level;
    ivec2 hi = clamp(ivec2(floor(centreTexel + radiusTexels)), ivec2(0), ivec2(size) - 1) >> level;
    lo = min(lo, levelSize - 1);
    hi = min(hi, levelSize - 1);
    float deepestM = max(max(texelFetch(shadowMap, lo, level).r, texelFetch(shadowMap, ivec2(hi.x, lo.y), level).r),
                         max(texelFetch(shadowMap, ivec2(lo.x, hi.y), level).r, texelFetch(shadowMap, hi, level).r));
    float nearestMm = (lightLinearDepth(light, x) - deepestM) * 1000.0 - reachMm;
    return nearestMm >= skipSigmas * sigmaMaxMm;
}

// T(x) / radiance where x's thickness along the ray is centreMm (not -1):
// the integral above, or the slab's closed form where the widest Gaussian is
// under DERMIS_TRANSMITTANCE_SLAB_BELOW_PX pixels (pixelsPerMm at x), so that
// the rings would resolve nothing the pixel can show.
vec3 thinRegionTransmittance(sampler2D shadowMap, GpuLight light, ProfileParams profile, vec3 x, vec3 N,
                             vec3 towardsLight, float centreMm, float pixelsPerMm) {
    float sigmaMaxMm = widestSigmaMm(profile);
    if (sigmaMaxMm * pixelsPerMm < DERMIS_TRANSMITTANCE_SLAB_BELOW_PX) {
        return profileTransmittance(profile, centreMm) * backLightFactor(N, towardsLight);
    }
    if (backSurfaceBeyondReach(shadowMap, light, x, towardsLight, centreMm, sigmaMaxMm)) return vec3(0.0);
    return backSurfaceTransmittance(shadowMap, light, profile, x, N, towardsLight, centreMm, sigmaMaxMm);
}

#endif
