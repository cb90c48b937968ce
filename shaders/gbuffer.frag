// G-buffer layout (DESIGN.md, "The frame"):
//   depth/stencil  D24S8; stencil = SSS profile slot (0 = opaque), for the blurs
//   target 0       RGBA8 sRGB: albedo (linear after decode), a = object id / 255
//   target 1       RGBA16F: xy octahedral view-space normal, z roughness m, w rho_s
//   target 2       R32UI: profile slot and view depth packed, the key that
//                  depth-aware blurs compare (layout in UniformBlocks.glsl)
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uAlbedoMap;
layout(binding = 1) uniform sampler2D uNormalMap;

in vec3 vViewNormal;
in vec4 vViewTangent;
in vec2 vUv;

layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalMaterial;
layout(location = 2) out uint oDepthKey;

in vec3 vViewPositionM;

void main() {
    vec3 albedo = uObject.albedoRoughness.rgb;
    if (uObject.material.z > 0.5) albedo *= texture(uAlbedoMap, vUv).rgb;

    vec3 N = safeNormalize(vViewNormal, vec3(0.0, 0.0, 1.0));
    if (!gl_FrontFacing) N = -N;
    if (uObject.material.w > 0.5) {
        vec3 T = vViewTangent.xyz - N * dot(N, vViewTangent.xyz);
        T = safeNormalize(T, abs(N.x) < 0.9 ? normalize(cross(N, vec3(1, 0, 0))) : normalize(cross(N, vec3(0, 1, 0))));
        vec3 B = cross(N, T) * (vViewTangent.w < 0.0 ? -1.0 : 1.0);
        vec3 tangentNormal = texture(uNormalMap, vUv).xyz * 2.0 - 1.0;
        N = safeNormalize(mat3(T, B, N) * tangentNormal, N);
    }

    oAlbedo = vec4(clamp(albedo, 0.0, 1.0), uObject.material.y / 255.0);
    oNormalMaterial = vec4(encodeNormal(N), uObject.albedoRoughness.w, uObject.material.x);
    int objectId = int(uObject.material.y + 0.5);
    int slot = int(uCharacters.characters[objectId].params.x + 0.5);
    oDepthKey = makeDepthKey(slot, -vViewPositionM.z);
}
