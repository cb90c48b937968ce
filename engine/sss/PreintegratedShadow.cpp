#include "sss/PreintegratedShadow.h"

#include "core/GaussLegendre.h"
#include "sss/BilinearTable.h"

#include <algorithm>
#include <cmath>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
// The Gaussian's support, in its standard deviations: the mass beyond, erfc(8 / sqrt 2) = 1.2e-15,
// is far below the table's half floats.
constexpr double kSupportStdDevs = 8.0;
// The penumbra part of the integral: this many Gauss-Legendre panels of kNodes nodes over the
// part of the penumbra the Gaussian reaches, in phi (t = h sin phi), where the integrand is smooth
// (A's derivative is singular at the penumbra's ends in t, not in phi) and spans at most 16
// standard deviations of the Gaussian: 64 nodes hold it to 1e-9 (the unit test's brute-force
// quadrature agrees to 1e-7).
constexpr int kPanels = 4;
constexpr int kNodes = 16;

double discLitShare(double d) {
    d = std::clamp(d, -1.0, 1.0);
    return 1.0 - (std::acos(d) - d * std::sqrt(1.0 - d * d)) / kPi;
}

// The d in [-1, 1] at which discLitShare(d) = c, by bisection (discLitShare increases).
double discOffset(double c) {
    double low = -1.0, high = 1.0;
    for (int i = 0; i < 64; ++i) {
        const double middle = 0.5 * (low + high);
        (discLitShare(middle) < c ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

// integral g_sigma(x - t) A(t / h) dt: A is 1 past the penumbra (t > h), giving
// Phi((x - h) / sigma), 0 before it, and inside it the integral runs over phi.
double scatteredEdge(double x, double sigma, double h, const GaussLegendre& rule) {
    if (!(h > 0.0)) return sigma > 0.0 ? standardNormalCdf(x / sigma) : (x > 0.0 ? 1.0 : x < 0.0 ? 0.0 : 0.5);
    if (!(sigma > 0.0)) return discLitShare(x / h);
    double sum = standardNormalCdf((x - h) / sigma);
    const double t0 = std::max(-h, x - kSupportStdDevs * sigma);
    const double t1 = std::min(h, x + kSupportStdDevs * sigma);
    if (t1 <= t0) return sum;
    const double phi0 = std::asin(std::clamp(t0 / h, -1.0, 1.0));
    const double phi1 = std::asin(std::clamp(t1 / h, -1.0, 1.0));
    const double panel = (phi1 - phi0) / kPanels;
    const double norm = 1.0 / (sigma * std::sqrt(2.0 * kPi));
    for (int p = 0; p < kPanels; ++p) {
        const double centre = phi0 + (p + 0.5) * panel;
        for (size_t n = 0; n < rule.nodes.size(); ++n) {
            const double phi = centre + 0.5 * panel * rule.nodes[n];
            const double s = std::sin(phi);
            const double u = (x - h * s) / sigma;
            sum += 0.5 * panel * rule.weights[n] * norm * std::exp(-0.5 * u * u) * discLitShare(s) * h * std::cos(phi);
        }
    }
    return sum;
}

glm::vec4 shadowAt(const DiffusionProfile& profile, double sigmaMax, double coverage, double q, const GaussLegendre& rule) {
    if (!(coverage > 0.0)) return glm::vec4(0.0f);
    if (coverage >= 1.0) return glm::vec4(1.0f);
    q = std::max(q, 0.0);
    // Scaled by the widest standard deviation: the disc's radius, the penumbra's half-width.
    const double x = kPreintegratedShadowStdDevs * std::sqrt(1.0 + q * q) * discOffset(coverage);
    const double h = 2.0 * q;
    glm::dvec3 scattered(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double sigma = sigmaMax > 0.0 ? std::sqrt(double(g.varianceMm2)) / sigmaMax : 0.0;
        scattered += glm::dvec3(g.weight) * scatteredEdge(x, sigma, h, rule);
    }
    const double visibility = scatteredEdge(x, 0.0, h, rule);
    return glm::vec4(glm::vec3(scattered), float(visibility));
}

// The widest standard deviation among the Gaussians that carry at least kMainWeight of some
// channel (the widest of all if none does).
constexpr float kMainWeight = 0.1f;
double widestStdDevMm(const DiffusionProfile& profile) {
    double widest = 0.0, widestMain = 0.0;
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double sigma = std::sqrt(double(std::max(g.varianceMm2, 0.0f)));
        widest = std::max(widest, sigma);
        if (std::max({g.weight.r, g.weight.g, g.weight.b}) >= kMainWeight) widestMain = std::max(widestMain, sigma);
    }
    return widestMain > 0.0 ? widestMain : widest;
}

}  // namespace

double preintegratedShadowSigmaMm(const DiffusionProfile& profile, float widthScale) {
    return widestStdDevMm(profile) * double(widthScale);
}

glm::vec4 preintegratedShadow(const DiffusionProfile& profile, float coverage, float penumbraRatio) {
    if (std::isnan(coverage)) return glm::vec4(0.0f);
    const GaussLegendre rule = makeGaussLegendre(kNodes);
    return shadowAt(profile, widestStdDevMm(profile), coverage, std::isnan(penumbraRatio) ? 0.0 : penumbraRatio, rule);
}

PreintegratedShadowTable makePreintegratedShadowTable(const DiffusionProfile& profile) {
    PreintegratedShadowTable table;
    table.texels.resize(size_t(table.coverages) * size_t(table.rows));
    const GaussLegendre rule = makeGaussLegendre(kNodes);
    const double sigmaMax = widestStdDevMm(profile);
    for (int j = 0; j < table.rows; ++j) {
        const double y = (j + 0.5) / table.rows;
        const double q = y / (1.0 - y);
        for (int i = 0; i < table.coverages; ++i) {
            const double coverage = double(i) / double(table.coverages - 1);
            table.texels[size_t(j) * size_t(table.coverages) + size_t(i)] = shadowAt(profile, sigmaMax, coverage, q, rule);
        }
    }
    return table;
}

glm::vec4 PreintegratedShadowTable::at(float coverage, float penumbraRatio) const {
    if (coverages < 2 || rows < 1 || texels.size() != size_t(coverages) * size_t(rows)) return glm::vec4(0.0f);
    // fmax and fmin map NaN to the other operand: NaN reads as 0.
    const float c = std::fmin(std::fmax(coverage, 0.0f), 1.0f);
    const float q = std::fmax(penumbraRatio, 0.0f);
    const float xTexel = c * float(coverages - 1);
    const float yTexel = std::isinf(q) ? float(rows) - 0.5f : q / (1.0f + q) * float(rows) - 0.5f;
    return sampleBilinear(texels, coverages, rows, xTexel, yTexel);
}

}  // namespace dermis
