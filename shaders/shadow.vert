// Shadow pass: positions into the light's clip space; linear light depth out.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"

layout(location = 0) in vec3 aPosition;

out float vLightDepthM;

void main() {
    GpuLight light = uLights.lights[int(uObject.mapping.y)];
    vec3 worldPositionM = (uObject.worldFromObject * vec4(aPosition, 1.0)).xyz;
    vLightDepthM = lightLinearDepth(light, worldPositionM);
    gl_Position = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
}
