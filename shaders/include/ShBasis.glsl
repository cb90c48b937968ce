// The real SH basis of bands 0-2 in the order of engine/env/SphericalHarmonics.h
// (index l^2 + l + m), and the clamped cosine's band factors (Ramamoorthi &
// Hanrahan 2001, eq. 8), and the irradiance of SH light, for every shader
// that evaluates or turns SH.
#ifndef DERMIS_SH_BASIS_GLSL
#define DERMIS_SH_BASIS_GLSL

const float kShBand0 = 0.282095;   // Y00
const float kShBand1 = 0.488603;   // Y1m = kShBand1 (y, z, x)
const float kShBand2xy = 1.092548;  // Y2-2 = kShBand2xy xy, Y2-1 = kShBand2xy yz, Y21 = kShBand2xy xz
const float kShBand20 = 0.315392;   // Y20 = kShBand20 (3 z^2 - 1) = kShBand20 (2 z^2 - x^2 - y^2) on the sphere
const float kShBand22 = 0.546274;   // Y22 = kShBand22 (x^2 - y^2)

// The clamped cosine's factor per coefficient, A_l = pi, 2 pi / 3, pi / 4:
// irradiance E(N) = sum_i kShClampedCosine[i] L_i Y_i(N).
const float kShClampedCosine[9] = float[9](3.141593, 2.094395, 2.094395, 2.094395, 0.785398, 0.785398, 0.785398,
                                           0.785398, 0.785398);

void shBasis9(vec3 d, out float basis[9]) {
    basis[0] = kShBand0;
    basis[1] = kShBand1 * d.y;
    basis[2] = kShBand1 * d.z;
    basis[3] = kShBand1 * d.x;
    basis[4] = kShBand2xy * d.x * d.y;
    basis[5] = kShBand2xy * d.y * d.z;
    basis[6] = kShBand20 * (3.0 * d.z * d.z - 1.0);
    basis[7] = kShBand2xy * d.x * d.z;
    basis[8] = kShBand22 * (d.x * d.x - d.y * d.y);
}

// Irradiance of the band-limited light at normal N (Ramamoorthi & Hanrahan
// 2001, eq. 7-8): sum A_l L_lm Y_lm(N), A = pi, 2 pi / 3, pi / 4.
vec3 shIrradiance(vec4 sh[9], vec3 N) {
    float basis[9];
    shBasis9(N, basis);
    vec3 irradiance = vec3(0.0);
    for (int i = 0; i < 9; ++i) irradiance += sh[i].rgb * (kShClampedCosine[i] * basis[i]);
    return max(irradiance, vec3(0.0));
}

#endif
