// Shadow pass: the nearest linear light depth in metres. The distance to a
// point light is not linear across a triangle, so it is taken per fragment;
// the axial depth of 2-D maps is, and is interpolated as before.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"

in vec3 vWorldPositionM;
in float vLightDepthM;
layout(location = 0) out float oDepthM;

void main() {
    GpuLight light = uLights.lights[int(uObject.lightIndex)];
    oDepthM = debugPlant(isCubeShadow(light) ? lightLinearDepth(light, vWorldPositionM) : vLightDepthM);
}
