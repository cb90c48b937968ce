// Shadow pass: positions into the light's clip space (a cube face's for point
// lights, include/Shadows.glsl); the world position out for the depth.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"

layout(location = 0) in vec3 aPosition;

out vec3 vWorldPositionM;
out float vLightDepthM;

void main() {
    GpuLight light = uLights.lights[int(uObject.lightIndex)];
    vec3 worldPositionM = (uObject.worldFromObject * vec4(aPosition, 1.0)).xyz;
    vWorldPositionM = worldPositionM;
    vLightDepthM = lightLinearDepth(light, worldPositionM);
    if (isCubeShadow(light)) {
        gl_Position = cubeFaceClip(int(uObject.cubeFace + 0.5), worldPositionM - light.positionM,
                                   light.shadowNearM, light.shadowFarM);
    } else {
        gl_Position = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
    }
}
