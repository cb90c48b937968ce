// Deferred lighting (DESIGN.md pass 4) into two targets:
//   0: diffuse irradiance times the pre-scatter albedo^mix (seed 000 §2.2.4),
//      the input of the SSS blur;
//   1: specular (Kelemen/Szirmay-Kalos), kept apart and added after the blur.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"
#include "Specular.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform sampler2D uBeckmann;
layout(binding = 4) uniform sampler2D uShadowMaps[DERMIS_MAX_SHADOWED_LIGHTS];

in vec2 vUv;
layout(location = 0) out vec4 oIrradiance;
layout(location = 1) out vec4 oSpecular;

// Radiance arriving from `light` and the unit direction towards it.
vec3 incidentRadiance(GpuLight light, vec3 worldPositionM, out vec3 L) {
    int type = int(light.positionType.w);
    if (type == DERMIS_LIGHT_DIRECTIONAL) {
        L = -light.directionShadow.xyz;
        return light.radiance.rgb;
    }
    vec3 toLight = light.positionType.xyz - worldPositionM;
    float distanceSquaredM2 = max(dot(toLight, toLight), 1e-6);
    L = toLight * inversesqrt(distanceSquaredM2);
    vec3 radiance = light.radiance.rgb / distanceSquaredM2;
    if (type == DERMIS_LIGHT_SPOT) {
        float cosAngle = dot(-L, light.directionShadow.xyz);
        radiance *= smoothstep(light.spot.y, light.spot.x, cosAngle);
    }
    return radiance;
}

void main() {
    float depth = texture(uDepth, vUv).r;
    if (depth >= 1.0) {
        oIrradiance = vec4(0.0);
        oSpecular = vec4(0.0);
        return;
    }
    vec3 albedo = texture(uAlbedo, vUv).rgb;
    vec4 normalMaterial = texture(uNormalMaterial, vUv);
    float roughness = normalMaterial.z;
    float rhoS = normalMaterial.w;

    vec3 viewPositionM = viewPositionFromDepth(vUv, depth, uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 N = safeNormalize(mat3(uFrame.worldFromView) * decodeNormal(normalMaterial.xy), vec3(0.0, 1.0, 0.0));
    vec3 V = safeNormalize(uFrame.cameraPositionM.xyz - worldPositionM, N);

    vec3 irradiance = uFrame.ambient.rgb;
    vec3 specular = vec3(0.0);
    int lightCount = int(uFrame.shading.z);
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        float nDotL = dot(N, L);
        if (nDotL <= 0.0) continue;
        int slot = int(light.directionShadow.w);
        float visibility = 1.0;
        if (slot >= 0) visibility = shadowVisibility(uShadowMaps[slot], light, worldPositionM, N, gl_FragCoord.xy);
        irradiance += radiance * (nDotL * visibility);
        specular += radiance * (visibility * ksSpecular(uBeckmann, N, L, V, roughness, rhoS));
    }

    float mixRatio = uFrame.shading.y;
    oIrradiance = vec4(sanitizeColour(irradiance * pow(albedo, vec3(mixRatio))), 1.0);
    oSpecular = vec4(sanitizeColour(specular), 1.0);
}
