// One draw's material (ObjectBlock, engine/render/FrameContext.cpp), as the
// G-buffer and the texture-space irradiance pass sample it
// (docs/materials.md):
//   base colour  tint x baseColorFactor (ObjectBlock.albedo) x albedo map x COLOR_0
//   roughness m  the roughness map's R; else glTF's metallic-roughness G x
//                roughnessFactor = r, mapped to Beckmann m = r^2 (glTF 2.0
//                Appendix B: GGX alpha = r^2; Walter et al. 2007 write Beckmann
//                and GGX with one width alpha, Beckmann's being m, and their
//                lobes nearly coincide at skin's small alpha); else the scalar
//   rho_s        material.x x the specular map's R
// The roughness map and the metallic-roughness map share a unit: a draw binds
// the one its source names.
#ifndef DERMIS_MATERIAL_GLSL
#define DERMIS_MATERIAL_GLSL

layout(binding = DERMIS_UNIT_ROUGHNESS) uniform sampler2D uRoughnessMap;
layout(binding = DERMIS_UNIT_SPECULAR) uniform sampler2D uSpecularMap;

// m below this is a mirror the Beckmann tables do not resolve.
const float kMinMaterialRoughness = 0.01;

vec3 materialAlbedo(sampler2D albedoMap, vec2 uv, vec3 vertexColour, float mipBias) {
    vec3 albedo = uObject.albedo * vertexColour;
    if (uObject.hasAlbedoMap > 0.5) albedo *= texture(albedoMap, uv, mipBias).rgb;
    return clamp(albedo, 0.0, 1.0);
}

float materialRoughness(vec2 uv, float mipBias) {
    int source = int(uObject.roughnessSource + 0.5);
    float m = uObject.roughness;
    if (source == DERMIS_ROUGHNESS_MAP) {
        m = texture(uRoughnessMap, uv, mipBias).r;
    } else if (source == DERMIS_ROUGHNESS_GLTF) {
        float r = texture(uRoughnessMap, uv, mipBias).g * uObject.roughnessFactor;
        m = r * r;
    }
    return clamp(m, kMinMaterialRoughness, 1.0);
}

float materialRhoS(vec2 uv, float mipBias) {
    float rhoS = uObject.rhoS;
    if (uObject.hasSpecularMap > 0.5) rhoS *= texture(uSpecularMap, uv, mipBias).r;
    return clamp(rhoS, 0.0, 1.0);
}

#endif
