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
// Every map is read through a MapFootprint, the UV and the mip level's source:
// the pixel quad's own gradients (the G-buffer), or gradients given per
// screen pixel (the texture-space irradiance pass, which rasterises the UV
// layout and takes them from the camera's projection, so that a surface point
// reads the maps as the pixel that shows it does: ts_irradiance.frag).
#ifndef DERMIS_MATERIAL_GLSL
#define DERMIS_MATERIAL_GLSL

layout(binding = DERMIS_UNIT_ROUGHNESS) uniform sampler2D uRoughnessMap;
layout(binding = DERMIS_UNIT_SPECULAR) uniform sampler2D uSpecularMap;

// m below this is a mirror the Beckmann tables do not resolve.
const float kMinMaterialRoughness = 0.01;

struct MapFootprint {
    vec2 uv;
    float mipBias;           // with the pixel quad's gradients
    bool explicitGradients;  // else the two below, in UV per screen pixel
    vec2 dUvDx;
    vec2 dUvDy;
};

MapFootprint pixelFootprint(vec2 uv, float mipBias) { return MapFootprint(uv, mipBias, false, vec2(0.0), vec2(0.0)); }

MapFootprint projectedFootprint(vec2 uv, vec2 dUvDx, vec2 dUvDy) { return MapFootprint(uv, 0.0, true, dUvDx, dUvDy); }

vec4 readMap(sampler2D map, MapFootprint at) {
    return at.explicitGradients ? textureGrad(map, at.uv, at.dUvDx, at.dUvDy) : texture(map, at.uv, at.mipBias);
}

vec3 materialAlbedo(sampler2D albedoMap, MapFootprint at, vec3 vertexColour) {
    vec3 albedo = uObject.albedo * vertexColour;
    if (uObject.hasAlbedoMap > 0.5) albedo *= readMap(albedoMap, at).rgb;
    return clamp(albedo, 0.0, 1.0);
}

float materialRoughness(MapFootprint at) {
    int source = int(uObject.roughnessSource + 0.5);
    float m = uObject.roughness;
    if (source == DERMIS_ROUGHNESS_MAP) {
        m = readMap(uRoughnessMap, at).r;
    } else if (source == DERMIS_ROUGHNESS_GLTF) {
        float r = readMap(uRoughnessMap, at).g * uObject.roughnessFactor;
        m = r * r;
    }
    return clamp(m, kMinMaterialRoughness, 1.0);
}

float materialRhoS(MapFootprint at) {
    float rhoS = uObject.rhoS;
    if (uObject.hasSpecularMap > 0.5) rhoS *= readMap(uSpecularMap, at).r;
    return clamp(rhoS, 0.0, 1.0);
}

#endif
