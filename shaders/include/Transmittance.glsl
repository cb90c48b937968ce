// Back-normal transmittance through thin regions (Jimenez et al. 2010,
// "Real-Time Realistic Skin Translucency", as Papanikolaou 2013 §4.3 describes it).
//
// For a pixel on an SSS surface and a light behind it:
//   1. Shrink the surface point inwards along its normal by `shrinkMm`
//      (Papanikolaou 2013 §4.3; default 0: see the calibration below).
//   2. Thickness s = (light-space depth of the shrunk point) - (depth stored
//      in the shadow map: the surface nearest the light), in mm. Where s is
//      below DERMIS_SELF_THICKNESS_MM the point is that nearest surface (or
//      lies in front of it, at the light's silhouette, where the map's texel
//      may be empty): it is lit directly, its neighbours' light reaches it
//      through the blur, and it takes no transmitted light. Clamping s to 0
//      there instead gave T = 1 and added up to 1.6 (more than the direct
//      irradiance) along the scan's shoulders, which a back light grazes.
//   3. T(s) = sum_i w_i exp(-s^2 / v_i), with the pixel's profile.
//   4. E = saturate(dot(-N, L)): the cosine at the back face, whose normal
//      is about -N. Jimenez et al. 2010 add a 0.3 wrap here.
// Calibration against the CPU reference (docs/screen-space.md, "Transmittance
// against the reference"): the reference carries light through thin parts by
// the profile over 3-D distance, with the back face's own cosine. The 0.3
// wrap and a 1 mm shrink (the old defaults) both add light the reference does
// not have: on default.json at 320x180 the ear's relative RMSE was 130%;
// without the wrap and with no shrink it is 20%, below the texture-space
// TSM's 25%. Without the wrap, a surface facing the light gets E = 0, so no
// shrink is needed to keep it from reading its own depth as zero thickness.
// The caller adds radiance x T(s) x E into the diffuse irradiance before the
// SSS blur, which then softens it like any other light.
#ifndef DERMIS_TRANSMITTANCE_GLSL
#define DERMIS_TRANSMITTANCE_GLSL

// Stored depth of the first surface along the light ray through worldPositionM.
float shadowMapDepthM(sampler2D shadowMap, GpuLight light, vec3 worldPositionM) {
    vec4 clip = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
    if (clip.w <= kTiny) return lightLinearDepth(light, worldPositionM);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return lightLinearDepth(light, worldPositionM);
    return texture(shadowMap, uv).r;
}

// Thickness in mm (step 2), or -1 where the point is the surface nearest the light.
float thicknessMm(sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, float shrinkMm) {
    vec3 shrunkM = worldPositionM - N * (shrinkMm * 1e-3);
    float occluderM = shadowMapDepthM(shadowMap, light, shrunkM);
    float sMm = (lightLinearDepth(light, shrunkM) - occluderM) * 1000.0;
    return sMm < DERMIS_SELF_THICKNESS_MM ? -1.0 : sMm;
}

vec3 profileTransmittance(ProfileParams profile, float sMm) {
    vec3 t = vec3(0.0);
    int count = profile.gaussianCount;
    for (int i = 0; i < count; ++i) {
        float varianceMm2 = max(profile.gaussians[i].a, 1e-6);
        t += profile.gaussians[i].rgb * exp(-sMm * sMm / varianceMm2);
    }
    return t;
}

float backLightFactor(vec3 N, vec3 L) { return clamp(dot(-N, L), 0.0, 1.0); }

#endif
