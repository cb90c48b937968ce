// Composite (DESIGN.md pass 6): diffuse = irradiance x albedo^(1 - mix),
// plus specular; background where nothing was drawn. Linear HDR out.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uIrradiance;
layout(binding = 3) uniform sampler2D uSpecular;

in vec2 vUv;
layout(location = 0) out vec4 oColour;

void main() {
    if (texture(uDepth, vUv).r >= 1.0) {
        oColour = vec4(uFrame.background.rgb, 1.0);
        return;
    }
    vec3 albedo = texture(uAlbedo, vUv).rgb;
    vec3 diffuse = texture(uIrradiance, vUv).rgb * pow(albedo, vec3(1.0 - uFrame.shading.y));
    oColour = vec4(sanitizeColour(diffuse + texture(uSpecular, vUv).rgb), 1.0);
}
