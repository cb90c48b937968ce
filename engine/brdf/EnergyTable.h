#pragma once
// Energy conservation between the specular lobe and the diffuse/SSS term
// (Chappuis 2011 §2.6): rho_dt(cos, m) = integral over the hemisphere of the
// Kelemen/Szirmay-Kalos BRDF (with rho_s = 1) times cos(theta_o). The diffuse
// light is scaled by 1 - rho_s * rho_dt(N.L, m) on the way in and by
// 1 - rho_s * rho_dt(N.V, m) on the way out (the BRDF is reciprocal).
//
// Texel (i, j): cos = i / (size - 1), m = j / (size - 1) (texel centres on the
// sample points; shaders look up uv = (vec2(cos, m) * (size - 1) + 0.5) / size).

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

constexpr int kEnergyTableSize = 64;

// The KS BRDF (rho_s = 1) times N.L, as shaders/include/Specular.glsl computes
// it, but with the closed-form Beckmann term instead of the table. Unit vectors.
float ksSpecular(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float m);
// The hemispherical integral at one (cos, m), by numerical quadrature.
float rhoDt(float cosTheta, float m);
// Empty for size < 2. Row m = 0 uses beckmannPH's floor m = 1e-3 (finite, near the m -> 0 limit).
std::vector<float> makeEnergyTable(int size = kEnergyTableSize);  // row-major, row = m

// The quadrature behind rhoDt (see EnergyTable.cpp): Gauss-Legendre in the Beckmann-mapped
// half-vector angle, over one panel where every azimuth reflects above the horizon and up to
// gradedPanels panels beyond it, and in the half-vector azimuth. The defaults are within 2e-4
// of the converged integral at the table's sample points and 5e-4 anywhere (the worst is just
// off grazing); tests compare them with finer rules and with Monte Carlo.
struct RhoDtQuadrature {
    int thetaNodes = 12;   // per panel, clamped to [1, 256]
    int phiNodes = 8;      // clamped to [1, 256]
    int gradedPanels = 4;  // clamped to [1, 32]
};
// The hemispherical integral before rhoDt's clamp to [0, 1]. It exceeds 1 near grazing: seed
// 000's P_H (listing 2.4) lacks the 1/pi of the normalised Beckmann distribution, so the lobe's
// albedo tends to pi * F as m -> 0 (0.088 at normal incidence, above 1 below cos ~ 0.2).
// rhoDt(c, m) = clamp(this(c, m), 0, 1).
double ksDirectionalAlbedo(float cosTheta, float m, const RhoDtQuadrature& quadrature = RhoDtQuadrature{});

}  // namespace dermis
