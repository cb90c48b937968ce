// Shadow pass: the nearest linear depth along the light's axis, in metres.
in float vLightDepthM;
layout(location = 0) out float oDepthM;
void main() { oDepthM = vLightDepthM; }
