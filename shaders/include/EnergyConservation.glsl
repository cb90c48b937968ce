// Energy conservation between specular and diffuse (Chappuis 2011 §2.6).
//
// Integration: bind the table made by engine/brdf/EnergyTable.cpp (R32F,
// DERMIS_ENERGY_SIZE a side: x = cos(theta), y = roughness m, texel centres on
// the sample points) and call energyLeftForDiffuse() with N.L for light going
// in and with N.V for light coming out: the KS BRDF is reciprocal, so the one
// table serves both (Chappuis 2011 §2.6).
#ifndef DERMIS_ENERGY_CONSERVATION_GLSL
#define DERMIS_ENERGY_CONSERVATION_GLSL

#ifndef DERMIS_ENERGY_SIZE
#define DERMIS_ENERGY_SIZE 64
#endif
#if DERMIS_ENERGY_SIZE < 2
#error "DERMIS_ENERGY_SIZE must be at least 2"
#endif

// 1 - rho_s * rho_dt(cos, m): the share of light the specular lobe leaves to
// the diffuse (subsurface) term. In [0, 1] for rho_s in [0, 1].
float energyLeftForDiffuse(sampler2D energyTable, float cosTheta, float m, float rhoS) {
    vec2 st = clamp(vec2(cosTheta, m), 0.0, 1.0);
    float rhoDt = texture(energyTable, (st * float(DERMIS_ENERGY_SIZE - 1) + 0.5) / float(DERMIS_ENERGY_SIZE)).r;
    return clamp(1.0 - rhoS * rhoDt, 0.0, 1.0);
}

#endif
