#include "sss/PreintegratedTable.h"

#include "sss/BilinearTable.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Each Gaussian's kernel is cut at this many standard deviations (in angle): the mass beyond,
// erfc(8 / sqrt 2) = 1.2e-15, is below double rounding of the result.
constexpr double kTailStdDevs = 8.0;
// Uniform panels over [-8, 8] standard deviations: h = 1/16. Over whole panels the cubic-Hermite
// rule is the end-corrected trapezoid, exact to rounding for a Gaussian; on the part of a panel
// at an end of the lit arc its error is at most h^5 max|f''''| / 384 = 7.5e-9 of the kernel's
// unit mass (|f''''| <= 3 for exp(-t^2 / 2)). Relative to D that grows deep in the shadow, where D
// is itself a Gaussian tail: 128 panels left 1.9e-4 of D at 3.6 standard deviations past the
// terminator (D = 7e-10); 256 panels agree there with 512 to the flat-terminator closed form's
// own linearisation error (tests/unit/test_preintegrated_table.cpp). A 64 x 64 skin table
// (six Gaussians) takes 3.4 ms to build on one core.
constexpr int kPanels = 256;
// Below this angular standard deviation (rad) a Gaussian is a delta on the ring: its blur
// changes D by at most ~s = 1e-12, less than a float can hold next to values of order 1.
constexpr double kSmallestStdDevRad = 1e-12;

// One Gaussian's ring kernel at one curvature, in t = x / s (s the angular standard
// deviation), cut at t = +-tMax, tMax = min(8, pi / s): the weight e(t) = exp(-t^2 / 2) and its
// moments c(t) = e(t) cos(s t), n(t) = e(t) sin(s t), each as values f_k and h-scaled
// derivatives d_k = h f'(t_k) at the nodes t_k = -tMax + k h, and their cumulative integrals
// from -tMax through the piecewise-cubic Hermite interpolant.
struct RingKernel {
    double s = 0.0;
    double tMax = 0.0;
    double h = 0.0;
    double mass = 0.0;  // integral of e over [-tMax, tMax], by the same rule
    std::array<double, kPanels + 1> cValue{}, cSlope{}, cCumulative{};
    std::array<double, kPanels + 1> nValue{}, nSlope{}, nCumulative{};
};

// Integral over [0, h] of the cubic Hermite interpolant: the end-corrected trapezoid rule.
double panelIntegral(double h, double f0, double d0, double f1, double d1) { return h * (0.5 * (f0 + f1) + (d0 - d1) / 12.0); }

void buildRingKernel(RingKernel& kernel, double s) {
    kernel.s = s;
    kernel.tMax = std::min(kTailStdDevs, kPi / s);
    kernel.h = 2.0 * kernel.tMax / kPanels;
    const double h = kernel.h;
    double eValue[kPanels + 1], eSlope[kPanels + 1];
    for (int k = 0; k <= kPanels; ++k) {
        // The last node exactly at +tMax, so that the arc x in [-pi, pi] is covered exactly.
        const double t = k == kPanels ? kernel.tMax : -kernel.tMax + k * h;
        const double e = std::exp(-0.5 * t * t);
        const double c = std::cos(s * t), n = std::sin(s * t);
        eValue[k] = e;
        eSlope[k] = h * (-t * e);
        kernel.cValue[size_t(k)] = e * c;
        kernel.cSlope[size_t(k)] = h * e * (-t * c - s * n);
        kernel.nValue[size_t(k)] = e * n;
        kernel.nSlope[size_t(k)] = h * e * (-t * n + s * c);
    }
    double mass = 0.0, c = 0.0, n = 0.0;
    kernel.cCumulative[0] = kernel.nCumulative[0] = 0.0;
    for (size_t k = 0; k < size_t(kPanels); ++k) {
        mass += panelIntegral(h, eValue[k], eSlope[k], eValue[k + 1], eSlope[k + 1]);
        c += panelIntegral(h, kernel.cValue[k], kernel.cSlope[k], kernel.cValue[k + 1], kernel.cSlope[k + 1]);
        n += panelIntegral(h, kernel.nValue[k], kernel.nSlope[k], kernel.nValue[k + 1], kernel.nSlope[k + 1]);
        kernel.cCumulative[k + 1] = c;
        kernel.nCumulative[k + 1] = n;
    }
    kernel.mass = mass;
}

// The cumulative integral from -tMax to t (clamped to the kernel's support) of one moment.
double cumulativeAt(const RingKernel& kernel, const std::array<double, kPanels + 1>& value,
                    const std::array<double, kPanels + 1>& slope, const std::array<double, kPanels + 1>& cumulative, double t) {
    if (!(t > -kernel.tMax)) return 0.0;
    if (t >= kernel.tMax) return cumulative[size_t(kPanels)];
    const double position = (t + kernel.tMax) / kernel.h;
    const int k = std::min(int(position), kPanels - 1);
    const double u = position - k, u2 = u * u;
    // Integrals over [0, u] of the Hermite basis h00, h10, h01, h11.
    const double i00 = u * (1.0 + u2 * (0.5 * u - 1.0));
    const double i10 = u2 * (0.5 + u * (0.25 * u - 2.0 / 3.0));
    const double i01 = u2 * u * (1.0 - 0.5 * u);
    const double i11 = u2 * u * (0.25 * u - 1.0 / 3.0);
    const size_t a = size_t(k), b = a + 1;
    return cumulative[a] + kernel.h * (value[a] * i00 + slope[a] * i10 + value[b] * i01 + slope[b] * i11);
}

// integral over the kernel's support of cos+(theta + x) g(x) dx, g the kernel normalised to 1.
double ringIntegral(const RingKernel& kernel, double cosTheta, double sinTheta, double theta) {
    // cos(theta + x) > 0 on x in (-pi/2 - theta, pi/2 - theta), and, for theta > pi/2, on
    // (3 pi/2 - theta, pi]; cos(theta + x) = cos theta cos x - sin theta sin x.
    const auto arc = [&](double xLow, double xHigh) {
        const double low = xLow / kernel.s, high = xHigh / kernel.s;
        if (!(high > -kernel.tMax) || !(low < kernel.tMax)) return 0.0;
        const double c = cumulativeAt(kernel, kernel.cValue, kernel.cSlope, kernel.cCumulative, high) -
                         cumulativeAt(kernel, kernel.cValue, kernel.cSlope, kernel.cCumulative, low);
        const double n = cumulativeAt(kernel, kernel.nValue, kernel.nSlope, kernel.nCumulative, high) -
                         cumulativeAt(kernel, kernel.nValue, kernel.nSlope, kernel.nCumulative, low);
        return cosTheta * c - sinTheta * n;
    };
    double sum = arc(-0.5 * kPi - theta, 0.5 * kPi - theta);
    if (theta > 0.5 * kPi) sum += arc(1.5 * kPi - theta, kPi);
    return std::max(sum / kernel.mass, 0.0);
}

// D(theta) at one curvature, per channel, for each cosine into out[]. `kernels` is scratch.
void diffuseAtCurvature(const DiffusionProfile& profile, double widthScale, double curvature, std::vector<RingKernel>& kernels,
                        const std::vector<double>& cosines, glm::vec3* out) {
    const std::vector<ProfileGaussian>& gaussians = profile.gaussians();
    kernels.resize(gaussians.size());
    for (size_t i = 0; i < gaussians.size(); ++i) {
        const double s = std::sqrt(double(gaussians[i].varianceMm2)) * widthScale * curvature;
        kernels[i].s = s;
        if (s >= kSmallestStdDevRad) buildRingKernel(kernels[i], s);
    }
    for (size_t k = 0; k < cosines.size(); ++k) {
        const double cosTheta = cosines[k];
        const double sinTheta = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
        const double theta = std::acos(cosTheta);
        glm::dvec3 sum(0.0);
        for (size_t i = 0; i < gaussians.size(); ++i) {
            const glm::dvec3 weight(gaussians[i].weight);
            if (weight == glm::dvec3(0.0)) continue;
            const double blurred = kernels[i].s >= kSmallestStdDevRad ? ringIntegral(kernels[i], cosTheta, sinTheta, theta)
                                                                       : std::max(cosTheta, 0.0);
            sum += weight * blurred;
        }
        out[k] = glm::vec3(sum);
    }
}

bool scatters(float widthScale, float curvaturePerMm) {
    return std::isfinite(widthScale) && widthScale > 0.0f && std::isfinite(curvaturePerMm) && curvaturePerMm > 0.0f;
}

}  // namespace

glm::vec3 preintegratedDiffuse(const DiffusionProfile& profile, float widthScale, float cosTheta, float curvaturePerMm) {
    if (std::isnan(cosTheta)) return glm::vec3(0.0f);
    const double c = std::clamp(double(cosTheta), -1.0, 1.0);
    if (!scatters(widthScale, curvaturePerMm)) return glm::vec3(float(std::max(c, 0.0)));
    std::vector<RingKernel> kernels;
    glm::vec3 result(0.0f);
    diffuseAtCurvature(profile, widthScale, curvaturePerMm, kernels, {c}, &result);
    return result;
}

PreintegratedTable makePreintegratedTable(const DiffusionProfile& profile, float widthScale) {
    PreintegratedTable table;
    const size_t columns = size_t(table.cosines);
    table.texels.resize(columns * size_t(table.curvatures));
    std::vector<double> cosines(columns);
    for (size_t i = 0; i < columns; ++i) cosines[i] = 2.0 * ((double(i) + 0.5) / double(table.cosines)) - 1.0;
    std::vector<RingKernel> kernels;
    for (int j = 0; j < table.curvatures; ++j) {
        const double y = (j + 0.5) / table.curvatures;
        const double curvature = double(table.maxCurvaturePerMm) * y * y;
        glm::vec3* row = table.texels.data() + size_t(j) * columns;
        if (scatters(widthScale, float(curvature))) {
            diffuseAtCurvature(profile, widthScale, curvature, kernels, cosines, row);
        } else {
            for (size_t i = 0; i < columns; ++i) row[i] = glm::vec3(float(std::max(cosines[i], 0.0)));
        }
    }
    return table;
}

glm::vec3 PreintegratedTable::at(float cosTheta, float curvaturePerMm) const {
    const float c = std::isnan(cosTheta) ? 0.0f : std::clamp(cosTheta, -1.0f, 1.0f);
    if (cosines < 1 || curvatures < 1 || texels.size() != size_t(cosines) * size_t(curvatures) || !(maxCurvaturePerMm > 0.0f))
        return glm::vec3(std::max(c, 0.0f));
    // fmax and fmin map NaN to the other operand: a NaN curvature reads as 0.
    const float kappa = std::fmin(std::fmax(curvaturePerMm, 0.0f), maxCurvaturePerMm);
    const float x = 0.5f * (c + 1.0f);
    const float y = std::sqrt(kappa / maxCurvaturePerMm);
    return sampleBilinear(texels, cosines, curvatures, x * float(cosines) - 0.5f, y * float(curvatures) - 0.5f);
}

}  // namespace dermis
