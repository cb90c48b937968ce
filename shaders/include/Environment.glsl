// Environment light (docs/environment.md): a lat-long radiance map around the
// scene, as nine SH coefficients for the diffuse light and as a prefiltered
// map for the specular.
//
// Integration:
//   - include Common.glsl and UniformBlocks.glsl first; uEnvironment (binding
//     DERMIS_BINDING_ENVIRONMENT) is uploaded once per frame by
//     render/FrameResources.cpp, which binds the map (with its prefiltered
//     mips, include/EnvironmentSpecular.glsl) to DERMIS_UNIT_ENVIRONMENT;
//   - diffuse: environmentIrradiance(N) where nothing occludes, or with the
//     transfer interpolated from the vertices (transferIrradiance, in a
//     vertex shader reading DERMIS_LOCATION_TRANSFER) transferredIrradiance;
//     either times environmentDiffuseShare(m, rho_s) when energy conservation
//     is on. uEnvironment.diffuseMode says where the unoccluded light comes
//     from: DERMIS_ENV_DIFFUSE_MAP the irradiance map (env/IrradianceMap.h) at
//     DERMIS_UNIT_ENVIRONMENT_IRRADIANCE, DERMIS_ENV_DIFFUSE_SH the nine
//     coefficients;
//   - specular: environmentSpecular(), times specularOcclusion(). The lighting
//     pass gives it; for pixels whose specular the LEAN lobe gives
//     (include/LeanLights.glsl) it writes the occlusion instead, and the
//     LEAN lobe's mean normal and width are used after the blur.
// Both are added only where uEnvironment.lit is 1.
//
// DERMIS_ENVIRONMENT (define before including; default 1)
//   1  environmentLit() reads uEnvironment.lit at run time;
//   0  environmentLit() is false: every environment term compiles out, for
//      frames whose scene has no environment (render/Programs.h builds the
//      programs that light with it both ways). A branch on a uniform is not
//      free everywhere: llvmpipe runs the body under an all-off mask, which
//      cost the 1280x720 lighting pass about 8% with no environment.
#ifndef DERMIS_ENVIRONMENT_GLSL
#define DERMIS_ENVIRONMENT_GLSL

#ifndef DERMIS_ENVIRONMENT
#define DERMIS_ENVIRONMENT 1
#endif
#if DERMIS_ENVIRONMENT != 0 && DERMIS_ENVIRONMENT != 1
#error "DERMIS_ENVIRONMENT is 1 (decided at run time by uEnvironment) or 0 (compiled out)"
#endif

#include "EnergyConservation.glsl"
#include "EnvironmentSpecular.glsl"
#include "ShBasis.glsl"

layout(binding = DERMIS_UNIT_ENVIRONMENT) uniform sampler2D uEnvironmentMap;
// The cosine powers E_1 .. E_4 (env/IrradianceMap.h; E_1 the irradiance),
// stacked down one texture, each between copies of its first and last rows
// so that bilinear reads stay inside it (render/GpuEnvironment.cpp).
layout(binding = DERMIS_UNIT_ENVIRONMENT_IRRADIANCE) uniform sampler2D uEnvironmentIrradiance;

// E_(k+1) at lat-long coordinates uv.
vec3 irradiancePower(vec2 uv, int k) {
    float rows = float(textureSize(uEnvironmentIrradiance, 0).y);
    float tile = rows / float(DERMIS_IRRADIANCE_POWERS);
    return textureLod(uEnvironmentIrradiance, vec2(uv.x, (float(k) * tile + 1.0 + uv.y * (tile - 2.0)) / rows), 0.0).rgb;
}

#if DERMIS_SH_COEFFICIENTS != 9
#error "Environment.glsl evaluates bands 0-2: nine coefficients"
#endif

bool environmentLit() { return DERMIS_ENVIRONMENT == 1 && uEnvironment.lit > 0.5; }
int environmentOcclusion() { return int(uEnvironment.occlusion + 0.5); }
int environmentSpecularMode() { return int(uEnvironment.specularMode + 0.5); }
int environmentDiffuseMode() { return int(uEnvironment.diffuseMode + 0.5); }

// The map's exact irradiance at N, bilinear between its texels as
// env/IrradianceMap.h's sampleIrradianceMap reads it.
vec3 mapIrradiance(vec3 N) {
    return irradiancePower(latLongUv(mat3(uEnvironment.mapFromWorld) * N), 0) * uEnvironment.intensity;
}
vec3 environmentIrradiance(vec3 N) {
    return environmentDiffuseMode() == DERMIS_ENV_DIFFUSE_MAP ? mapIrradiance(N) : shIrradiance(uEnvironment.sh, N);
}

// Occlusion "transfer", from transferIrradiance (include/EnvironmentTransfer.glsl):
//   map: the map's irradiance at N times the share of the light that
//        occlusion leaves (rgb);
//   sh:  the vertices' L.T of the smooth light (rgb, and the visible share in
//        a) plus the hot, windowed part lit at the normal times that share
//        (env/RingingFreeSh.h: a sun's hot part through the transfer's
//        integrated vectors could take light away).
vec3 transferredIrradiance(vec4 transfer, vec3 N) {
    if (environmentDiffuseMode() == DERMIS_ENV_DIFFUSE_MAP) return mapIrradiance(N) * transfer.rgb;
    return transfer.rgb + shIrradiance(uEnvironment.hotSh, N) * transfer.a;
}

// The share of the environment's light the specular lobe leaves to the
// diffuse (Chappuis 2011 §2.6 applied per direction, as the CPU reference
// does): sum L cos (1 - rho_s rho_dt(cos, m)) dw over sum L cos dw.
//   map: rho_dt(cos, m) as a cubic in cos (EnvironmentBlock.rhoDtFits) over
//        the map's cosine powers E_1 .. E_4 at N: 1 - rho_s sum_k c_k E_(k+1) / E_1;
//   sh:  1 - rho_s rho_avg(m), rho_avg the cosine-weighted hemispherical
//        mean of rho_dt: the light taken as uniform (exact for a uniform map,
//        the white furnace, where the map's form gives the same).
vec3 environmentDiffuseShare(vec3 N, float m, float rhoS) {
    float x = clamp(m, 0.0, 1.0) * float(DERMIS_AVERAGE_ALBEDO_SIZE - 1);
    int i = min(int(x), DERMIS_AVERAGE_ALBEDO_SIZE - 2);
    float f = x - float(i);
    if (environmentDiffuseMode() == DERMIS_ENV_DIFFUSE_MAP) {
        vec4 c = mix(uEnvironment.rhoDtFits[i], uEnvironment.rhoDtFits[i + 1], f);
        vec2 uv = latLongUv(mat3(uEnvironment.mapFromWorld) * N);
        vec3 e1 = irradiancePower(uv, 0);
        vec3 taken = c.x * e1 + c.y * irradiancePower(uv, 1) + c.z * irradiancePower(uv, 2) + c.w * irradiancePower(uv, 3);
        return clamp(1.0 - rhoS * taken / max(e1, vec3(1e-8)), 0.0, 1.0);
    }
    float a = uEnvironment.averageAlbedo[i / 4][i % 4];
    float b = uEnvironment.averageAlbedo[(i + 1) / 4][(i + 1) % 4];
    return vec3(clamp(1.0 - rhoS * mix(a, b, f), 0.0, 1.0));
}

// Specular occlusion from a cosine-weighted visibility (Lagarde & de Rousiers
// 2014, "Moving Frostbite to PBR", eq. 65 with their roughness taken as m).
float specularOcclusion(float nDotV, float visibility, float m) {
    return clamp(pow(max(nDotV + visibility, 0.0), exp2(-16.0 * m - 1.0)) - 1.0 + visibility, 0.0, 1.0);
}

// The environment's specular light towards V from a surface of normal N
// (world space), before occlusion: split sum (Karis 2013) with the
// Kelemen/Szirmay-Kalos lobe's directional albedo rho_s rho_dt(N.V, m) (the
// energy table) times the radiance prefiltered for roughness m around the
// reflection, or with specular "sh" the SH light's cosine-blurred radiance
// there, E(R) / pi.
vec3 environmentSpecular(sampler2D energyTable, vec3 N, vec3 V, float m, float rhoS) {
    int mode = environmentSpecularMode();
    if (mode == DERMIS_ENV_SPECULAR_OFF) return vec3(0.0);
    float nDotV = clamp(dot(N, V), 0.0, 1.0);
    float albedo = 1.0 - energyLeftForDiffuse(energyTable, nDotV, m, rhoS);
    vec3 R = reflect(-V, N);
    vec3 radiance = mode == DERMIS_ENV_SPECULAR_SH
                        ? environmentIrradiance(R) * (1.0 / 3.14159265)
                        : prefilteredRadiance(uEnvironmentMap, mat3(uEnvironment.mapFromWorld) * R, m) *
                              uEnvironment.intensity;
    return radiance * albedo;
}

#endif
