#include "brdf/EnergyTable.h"

#include "include/SharedConstants.glsl"

#include "brdf/BeckmannTable.h"
#include "core/GaussLegendre.h"

#include <algorithm>
#include <cmath>
#include <system_error>
#include <thread>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Schlick's F0 for skin (Chappuis 2011 §2.3), shared with shaders/include/Specular.glsl.
constexpr double kSkinF0 = DERMIS_SKIN_F0;
// beckmannPH's own floor on m, so rhoDt integrates the lobe that ksSpecular evaluates.
constexpr double kMinRoughness = 1e-3;

// Schlick's approximation, Chappuis 2011 listing 2.3.
double fresnelSchlick(double vDotH) {
    const double base = 1.0 - std::clamp(vDotH, 0.0, 1.0);
    const double exponential = base * base * base * base * base;
    return exponential + kSkinF0 * (1.0 - exponential);
}

// Gauss-Legendre nodes and weights mapped to [0, 1].
GaussLegendre makeUnitGaussLegendre(int n) {
    GaussLegendre rule = makeGaussLegendre(n);
    for (size_t i = 0; i < rule.nodes.size(); ++i) {
        rule.nodes[i] = 0.5 * (1.0 - rule.nodes[i]);
        rule.weights[i] *= 0.5;
    }
    return rule;
}

// rho_dt (Chappuis 2011 §2.6) by quadrature. The view direction is v = (sin, 0, cos) and n = +z.
// In the half-vector domain (Walter et al. 2007, eq. 14),
// dw_l = 4 (v.h) dw_h and |l + v|^2 = 4 (v.h)^2, so the KS integrand f (n.l) dw_l becomes
// P_H F (n.l) / (v.h) dw_h. Substituting u = 1 - exp(-tan^2(theta_h) / m^2) (the Beckmann
// CDF) gives P_H sin(theta_h) d(theta_h) = du / (2 cos(theta_h)), so what is left to integrate,
// F (n.l) / (2 cos(theta_h) (v.h)), is bounded and smooth: the peak is in the mapping, not in
// the integrand. n.l > 0 exactly when cos(phi_h) > c* (below), so the azimuth runs over
// [-phi*, phi*] with phi* = acos(c*), and the Beckmann-mapped angle stops where the
// mirror direction in the plane of incidence reaches the horizon.
struct ViewSetup {
    double cosV, sinV, m;
};

double azimuthIntegral(const ViewSetup& view, double u, const GaussLegendre& phiRule) {
    const double tan2 = -view.m * view.m * std::log1p(-u);
    if (!(tan2 < 1e30)) return 0.0;
    const double cosH = 1.0 / std::sqrt(1.0 + tan2);
    const double sinH = std::sqrt(tan2) * cosH;
    const double d = view.sinV * sinH;  // v.h = d cos(phi) + cosV cosH
    double phiMax;
    if (d < 1e-12) {
        phiMax = view.cosV * (2.0 * cosH * cosH - 1.0) > 0.0 ? kPi : 0.0;
    } else {
        const double cStar = view.cosV * (1.0 - 2.0 * cosH * cosH) / (2.0 * cosH * d);
        phiMax = cStar >= 1.0 ? 0.0 : (cStar <= -1.0 ? kPi : std::acos(cStar));
    }
    if (phiMax <= 0.0) return 0.0;
    // phi = phiMax s (2 - s) puts the nodes close to phi*, where n.l -> 0 and (near grazing) the
    // integrand rises over an azimuth range only about cos(theta_v) wide.
    double sum = 0.0;
    for (size_t k = 0; k < phiRule.nodes.size(); ++k) {
        const double s = phiRule.nodes[k];
        const double phi = phiMax * s * (2.0 - s);
        const double vDotH = d * std::cos(phi) + view.cosV * cosH;
        const double nDotL = 2.0 * vDotH * cosH - view.cosV;
        if (nDotL <= 0.0 || vDotH <= 0.0) continue;
        sum += phiRule.weights[k] * 2.0 * (1.0 - s) * fresnelSchlick(vDotH) * nDotL / (2.0 * cosH * vDotH);
    }
    return 2.0 * phiMax * sum;  // both signs of phi
}

double panelIntegral(const ViewSetup& view, double uLow, double uHigh, const GaussLegendre& uRule, const GaussLegendre& phiRule) {
    if (!(uHigh > uLow)) return 0.0;
    double sum = 0.0;
    for (size_t k = 0; k < uRule.nodes.size(); ++k)
        sum += uRule.weights[k] * azimuthIntegral(view, uLow + (uHigh - uLow) * uRule.nodes[k], phiRule);
    return (uHigh - uLow) * sum;
}

double ksDirectionalAlbedoWith(float cosTheta, float m, const RhoDtQuadrature& quadrature, const GaussLegendre& uRule,
                               const GaussLegendre& phiRule) {
    ViewSetup view;
    view.cosV = std::fmin(std::fmax(double(cosTheta), 0.0), 1.0);  // fmax maps NaN to 0
    view.sinV = std::sqrt(1.0 - view.cosV * view.cosV);
    view.m = std::fmax(double(m), kMinRoughness);
    const double thetaV = std::acos(view.cosV);
    const auto beckmannCdf = [&](double thetaH) {
        if (thetaH >= 0.5 * kPi - 1e-9) return 1.0;
        const double t = std::tan(thetaH);
        return -std::expm1(-t * t / (view.m * view.m));
    };
    // Below uFull every azimuth reflects above the horizon; above uMax none does.
    const double uFull = beckmannCdf(0.5 * (0.5 * kPi - thetaV));
    const double uMax = beckmannCdf(0.5 * (0.5 * kPi + thetaV));
    double sum = panelIntegral(view, 0.0, uFull, uRule, phiRule);
    // Just above uFull, phi* falls from pi over a range of u about as wide as uFull itself, which
    // is tiny near grazing: panels shrinking by 4x towards uFull resolve it.
    std::vector<double> breaks{uMax};
    double width = uMax - uFull;
    const int gradedPanels = std::clamp(quadrature.gradedPanels, 1, 32);
    for (int k = 1; k < gradedPanels && width > uFull; ++k) {
        width *= 0.25;
        breaks.push_back(uFull + width);
    }
    breaks.push_back(uFull);
    for (size_t k = breaks.size() - 1; k > 0; --k) sum += panelIntegral(view, breaks[k], breaks[k - 1], uRule, phiRule);
    return std::isfinite(sum) ? sum : 0.0;
}

const RhoDtQuadrature kDefaultQuadrature{};

}  // namespace

float ksSpecular(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float m) {
    // Chappuis 2011 listing 2.5, step for step as Specular.glsl's ksSpecular (rho_s = 1).
    const float nDotL = glm::dot(n, l);
    if (!(nDotL > 0.0f)) return 0.0f;
    const glm::vec3 h = l + v;
    const float hLengthSquared = glm::dot(h, h);
    if (!(hLengthSquared >= 1e-6f)) return 0.0f;
    const glm::vec3 halfVector = h / std::sqrt(hLengthSquared);
    const float nDotH = std::clamp(glm::dot(n, halfVector), 0.0f, 1.0f);
    const float pH = beckmannPH(nDotH, m);
    const float fresnel = static_cast<float>(fresnelSchlick(double(glm::dot(v, halfVector))));
    const float specular = std::fmax(pH * fresnel / hLengthSquared, 0.0f) * nDotL;
    return std::isfinite(specular) ? specular : 0.0f;
}

double ksDirectionalAlbedo(float cosTheta, float m, const RhoDtQuadrature& quadrature) {
    const int thetaNodes = std::clamp(quadrature.thetaNodes, 1, 256);
    const int phiNodes = std::clamp(quadrature.phiNodes, 1, 256);
    if (thetaNodes == kDefaultQuadrature.thetaNodes && phiNodes == kDefaultQuadrature.phiNodes) {
        static const GaussLegendre kThetaRule = makeUnitGaussLegendre(kDefaultQuadrature.thetaNodes);
        static const GaussLegendre kPhiRule = makeUnitGaussLegendre(kDefaultQuadrature.phiNodes);
        return ksDirectionalAlbedoWith(cosTheta, m, quadrature, kThetaRule, kPhiRule);
    }
    return ksDirectionalAlbedoWith(cosTheta, m, quadrature, makeUnitGaussLegendre(thetaNodes), makeUnitGaussLegendre(phiNodes));
}

float rhoDt(float cosTheta, float m) {
    return static_cast<float>(std::clamp(ksDirectionalAlbedo(cosTheta, m, kDefaultQuadrature), 0.0, 1.0));
}

std::vector<float> makeEnergyTable(int size) {
    if (size < 2) return {};
    std::vector<float> table(static_cast<size_t>(size) * static_cast<size_t>(size));
    const auto fillRows = [&table, size](int first, int stride) {
        for (int j = first; j < size; j += stride) {
            const float m = float(j) / float(size - 1);  // m = 0 is floored inside, as beckmannPH does
            for (int i = 0; i < size; ++i)
                table[static_cast<size_t>(j) * static_cast<size_t>(size) + static_cast<size_t>(i)] = rhoDt(float(i) / float(size - 1), m);
        }
    };
    // Computed at renderer start-up: spread the rows over the cores.
    const int workers = std::clamp(int(std::thread::hardware_concurrency()), 1, std::min(size, 8));
    std::vector<std::thread> threads;
    for (int w = 1; w < workers; ++w) {
        try {
            threads.emplace_back(fillRows, w, workers);
        } catch (const std::system_error&) {
            fillRows(w, workers);
        }
    }
    fillRows(0, workers);
    for (std::thread& thread : threads) thread.join();
    return table;
}

}  // namespace dermis
