// Composite (docs/screen-space.md, step 7): diffuse = SSS-accumulated irradiance x
// albedo^(1 - mix) x the energy the specular lobe lets out towards the viewer,
// 1 - rho_s rho_dt(N.V, m) (Chappuis 2011 §2.6), plus specular; the background
// where nothing was drawn. Linear HDR out. With COMPOSITE_LEAN (variants lcb
// and lbb) the specular of characters with LEAN maps comes from their blurred
// moments here (include/LeanLights.glsl) rather than from the lighting pass.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "EnergyConservation.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uDiffuse;
layout(binding = 3) uniform sampler2D uSpecular;
layout(binding = 4) uniform sampler2D uNormalMaterial;
layout(binding = DERMIS_UNIT_ENERGY) uniform sampler2D uEnergy;
#ifdef COMPOSITE_LEAN
layout(binding = 5) uniform sampler2D uLeanMoments;  // blurred (B'.x, B'.y, M'.xx, M'.yy); M'.xy is uDiffuse's alpha
layout(binding = 6) uniform sampler2D uVisibility;   // the lighting pass's shadow visibility
#endif

in vec2 vUv;
layout(location = 0) out vec4 oColour;

#include "OutgoingDiffuse.glsl"
#ifdef COMPOSITE_LEAN
#include "LeanLights.glsl"
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // From the pixel, not the interpolated vUv: the pass draws the characters'
    // rectangles (passes/FullscreenPass.h), whose interpolation rounds otherwise.
    vec2 uv = gl_FragCoord.xy * uFrame.pixelSizeUv;
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (depth >= 1.0) {
        oColour = vec4(uFrame.background.rgb, 1.0);
        return;
    }
    vec4 accumulated = texelFetch(uDiffuse, pixel, 0);
    vec4 normalMaterial = texelFetch(uNormalMaterial, pixel, 0);
    vec4 lightingSpecular = texelFetch(uSpecular, pixel, 0);
    vec3 diffuse = outgoingDiffuseOf(texelFetch(uAlbedo, pixel, 0).rgb, scatteredIrradiance(pixel, accumulated.rgb),
                                     normalMaterial, depth);
#ifdef COMPOSITE_LEAN
    vec3 specular = leanPixelSpecular(pixel, uv, depth, lightingSpecular, accumulated.a, normalMaterial.w,
                                      uLeanMoments, uVisibility);
#else
    vec3 specular = lightingSpecular.rgb;
#endif
    oColour = vec4(sanitizeColour(diffuse + specular), 1.0);
}
