// Writes one linear component of the frame, before tone mapping, for
// `dermis render --aov`. The AOV id is uFrame.shading.w (render/Aov.h).
#include "Common.glsl"
#include "UniformBlocks.glsl"

#define AOV_ALBEDO 1
#define AOV_NORMAL 2
#define AOV_DEPTH 3
#define AOV_DIFFUSE 4
#define AOV_SPECULAR 5
#define AOV_IRRADIANCE 6

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform sampler2D uIrradiance;
layout(binding = 4) uniform sampler2D uSpecular;

in vec2 vUv;
layout(location = 0) out vec4 oValue;

void main() {
    int aov = int(uFrame.shading.w);
    float depth = texture(uDepth, vUv).r;
    bool background = depth >= 1.0;
    vec3 value = vec3(0.0);
    if (aov == AOV_DEPTH) {
        // Linear view depth in metres; the far plane for the background.
        value = vec3(background ? uFrame.depthRangeM.y : -viewPositionFromDepth(vUv, depth, uFrame.viewFromClip).z);
    } else if (!background) {
        if (aov == AOV_ALBEDO) value = texture(uAlbedo, vUv).rgb;
        else if (aov == AOV_NORMAL) value = mat3(uFrame.worldFromView) * decodeNormal(texture(uNormalMaterial, vUv).xy);
        else if (aov == AOV_IRRADIANCE) value = texture(uIrradiance, vUv).rgb;
        else if (aov == AOV_DIFFUSE)
            value = texture(uIrradiance, vUv).rgb * pow(texture(uAlbedo, vUv).rgb, vec3(1.0 - uFrame.shading.y));
        else if (aov == AOV_SPECULAR) value = texture(uSpecular, vUv).rgb;
    }
    oValue = vec4(value, background ? 0.0 : 1.0);
}
