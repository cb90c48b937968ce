// Writes one linear component of the frame, before tone mapping, for
// `dermis render --aov`. The AOV id is uFrame.aov (plan/Aov.h).
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "EnergyConservation.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uDiffuse;      // SSS-accumulated irradiance (diffuse AOV)
layout(binding = 3) uniform sampler2D uSpecular;
layout(binding = 4) uniform sampler2D uNormalMaterial;
layout(binding = 5) uniform sampler2D uComponent;    // irradiance, AO, transmittance, a UV-space texture or the composite
layout(binding = DERMIS_UNIT_ENERGY) uniform sampler2D uEnergy;

in vec2 vUv;
layout(location = 0) out vec4 oValue;

#include "OutgoingDiffuse.glsl"

// The component at this pixel; a culled producer leaves a 1x1 stand-in. No
// filtering: linear sampling at texel centres is not exact on every GPU.
vec4 component(ivec2 pixel) {
    return textureSize(uComponent, 0) == ivec2(1) ? texelFetch(uComponent, ivec2(0), 0) : texelFetch(uComponent, pixel, 0);
}

// The UV-space AOVs show the unit UV square as large as the frame allows,
// centred, v upwards; each pixel shows the texel under its centre (no
// filtering: chart borders stay sharp). False outside the square.
bool uvLayoutTexel(ivec2 pixel, out vec4 texel) {
    vec2 frameSize = uFrame.viewportPx;
    float side = min(frameSize.x, frameSize.y);
    vec2 uv = (vec2(pixel) + 0.5 - 0.5 * (frameSize - side)) / side;
    texel = vec4(0.0);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
    ivec2 size = textureSize(uComponent, 0);
    ivec2 at = size == ivec2(1) ? ivec2(0) : min(ivec2(uv * vec2(size)), size - 1);  // 1x1: no character on screen
    texel = texelFetch(uComponent, at, 0);
    return true;
}

void shade() {
    int aov = uFrame.aov;
    if (aov == DERMIS_AOV_STRETCH || aov == DERMIS_AOV_IRRADIANCE_TEXTURE) {
        vec4 texel;
        bool inside = uvLayoutTexel(ivec2(gl_FragCoord.xy), texel);
        oValue = vec4(aov == DERMIS_AOV_STRETCH ? vec3(texel.rg, 0.0) : texel.rgb, inside ? 1.0 : 0.0);
        return;
    }
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uDepth, pixel, 0).r;
    bool background = depth >= 1.0;
    if (aov == DERMIS_AOV_RADIANCE) {
        // The composite's frame, the background's radiance included.
        oValue = vec4(component(pixel).rgb, background ? 0.0 : 1.0);
        return;
    }
    vec3 value = vec3(0.0);
    if (aov == DERMIS_AOV_DEPTH) {
        // Linear view depth in metres; the far plane for the background.
        value = vec3(background ? uFrame.farM : -viewPositionFromDepth(vUv, depth, uFrame.viewFromClip).z);
    } else if (aov == DERMIS_AOV_AO) {
        value = vec3(background ? 1.0 : component(pixel).r);
    } else if (!background) {
        if (aov == DERMIS_AOV_ALBEDO) value = texelFetch(uAlbedo, pixel, 0).rgb;
        else if (aov == DERMIS_AOV_NORMAL) value = mat3(uFrame.worldFromView) * decodeNormal(texelFetch(uNormalMaterial, pixel, 0).xy);
        else if (aov == DERMIS_AOV_DIFFUSE) value = outgoingDiffuse(pixel, depth);
        else if (aov == DERMIS_AOV_SPECULAR) value = texelFetch(uSpecular, pixel, 0).rgb;
        else if (aov == DERMIS_AOV_OBJECT) value = vec3(floor(texelFetch(uAlbedo, pixel, 0).a * 255.0 + 0.5));
        else if (aov == DERMIS_AOV_SCATTER) value = vec3(texelFetch(uScatter, pixel, 0).rg, 0.0);
        else value = component(pixel).rgb;  // irradiance, transmittance, thickness
    }
    oValue = vec4(value, background ? 0.0 : 1.0);
}

// The pass's output goes through the planted NaN of docs/stress.md.
void main() {
    shade();
    oValue = debugPlant(oValue);
}
