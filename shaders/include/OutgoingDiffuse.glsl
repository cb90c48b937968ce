// The diffuse radiance leaving a pixel, shared by composite.frag and aov.frag.
// Expects uAlbedo, uDiffuse, uNormalMaterial and uEnergy to be declared and
// EnergyConservation.glsl to be included, as both callers do.
#ifndef DERMIS_OUTGOING_DIFFUSE_GLSL
#define DERMIS_OUTGOING_DIFFUSE_GLSL

layout(binding = DERMIS_UNIT_UNSCATTERED) uniform sampler2D uUnscattered;  // the lighting pass's irradiance
layout(binding = DERMIS_UNIT_SCATTER) uniform sampler2D uScatter;          // G-buffer: R = the scattering share s

// The irradiance a pixel sends out: (1 - s) x its own + s x the SSS
// accumulation (docs/materials.md, "Skin only where there is skin"). Where s
// is 1 (skin) this is the accumulation to the bit, where s is 0 (opaque) the
// accumulation already holds the pixel's own irradiance.
vec3 scatteredIrradiance(ivec2 pixel, vec3 accumulated) {
    float s = texelFetch(uScatter, pixel, 0).r;
    return s >= 1.0 ? accumulated : mix(texelFetch(uUnscattered, pixel, 0).rgb, accumulated, s);
}

// The diffuse radiance leaving the surface, from the pixel's albedo,
// SSS-accumulated irradiance and G-buffer normal+material (fetched by the
// caller, which may need them too: on llvmpipe every fetch counts).
vec3 outgoingDiffuseOf(vec3 albedo, vec3 accumulated, vec4 normalMaterial, float depth) {
    vec3 diffuse = accumulated * albedoPower(albedo, 1.0 - uFrame.mixRatio);
    if (uFrame.energyConservation != 0) {
        // The pixel's own uv, whether the caller draws the frame or rectangles of it.
        vec3 viewPositionM = viewPositionFromDepth(gl_FragCoord.xy * uFrame.pixelSizeUv, depth, uFrame.viewFromClip);
        vec3 N = decodeNormal(normalMaterial.xy);  // view space, like V below
        vec3 V = safeNormalize(-viewPositionM, N);
        diffuse *= energyLeftForDiffuse(uEnergy, clamp(dot(N, V), 0.0, 1.0), normalMaterial.z, normalMaterial.w);
    }
    return diffuse;
}

// The same, fetching them (also the `diffuse` AOV).
vec3 outgoingDiffuse(ivec2 pixel, float depth) {
    return outgoingDiffuseOf(texelFetch(uAlbedo, pixel, 0).rgb, scatteredIrradiance(pixel, texelFetch(uDiffuse, pixel, 0).rgb),
                             texelFetch(uNormalMaterial, pixel, 0), depth);
}

#endif
