// Radiance arriving from a GpuLight (directional, spot or point) at a point.
#ifndef DERMIS_LIGHTS_GLSL
#define DERMIS_LIGHTS_GLSL

// Returns the radiance (irradiance on a surface facing the light) and sets L
// to the unit direction towards the light. Spot and point lights fall off as
// 1/r^2; spots fade between the outer and inner cone angles.
vec3 incidentRadiance(GpuLight light, vec3 worldPositionM, out vec3 L) {
    int type = int(light.type);
    if (type == DERMIS_LIGHT_DIRECTIONAL) {
        L = -light.direction;
        return light.radiance;
    }
    vec3 toLight = light.positionM - worldPositionM;
    float distanceSquaredM2 = max(dot(toLight, toLight), 1e-6);
    L = toLight * inversesqrt(distanceSquaredM2);
    vec3 radiance = light.radiance / distanceSquaredM2;
    if (type == DERMIS_LIGHT_SPOT) radiance *= smoothstep(light.spotCosOuter, light.spotCosInner, dot(-L, light.direction));
    return radiance;
}

#endif
