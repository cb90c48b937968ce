// The diffuse radiance leaving a pixel, shared by composite.frag and aov.frag.
// Expects uAlbedo, uDiffuse, uNormalMaterial and uEnergy to be declared and
// EnergyConservation.glsl to be included, as both callers do.
#ifndef DERMIS_OUTGOING_DIFFUSE_GLSL
#define DERMIS_OUTGOING_DIFFUSE_GLSL

// The diffuse radiance leaving the surface (also the `diffuse` AOV).
vec3 outgoingDiffuse(ivec2 pixel, float depth) {
    vec3 albedo = texelFetch(uAlbedo, pixel, 0).rgb;
    vec3 diffuse = texelFetch(uDiffuse, pixel, 0).rgb * albedoPower(albedo, 1.0 - uFrame.shading.y);
    if (uFrame.features.x > 0.5) {
        vec4 normalMaterial = texelFetch(uNormalMaterial, pixel, 0);
        vec3 viewPositionM = viewPositionFromDepth(vUv, depth, uFrame.viewFromClip);
        vec3 N = decodeNormal(normalMaterial.xy);  // view space, like V below
        vec3 V = safeNormalize(-viewPositionM, N);
        diffuse *= energyLeftForDiffuse(uEnergy, clamp(dot(N, V), 0.0, 1.0), normalMaterial.z, normalMaterial.w);
    }
    return diffuse;
}

#endif
