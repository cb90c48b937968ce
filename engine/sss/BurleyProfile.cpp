#include "sss/BurleyProfile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dermis {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kChannelNames[3] = {"red", "green", "blue"};

// F(24 d) = 1 - 2.5e-4: the fit and its L2 error cover all but that tail.
constexpr double kFitRangeInShapeDistances = 24.0;
// Both on a log grid from 1e-5 d, so that the narrowest Gaussians and the cusp of r R(r) at
// r = 0 are resolved; the part below it carries 1e-5 / 2 of the light.
constexpr double kSampleFirstInShapeDistances = 1e-5;
constexpr int kFitSamples = 1024;
constexpr int kErrorSamples = 4096;
// The CDF error is taken on a log grid from 1e-5 d_min (where F grows linearly and the
// Gaussians quadratically) to 64 d_max (where F = 1 - 4e-10).
constexpr int kCdfErrorSamples = 20000;
constexpr double kCdfErrorFirstInShapeDistances = 1e-5;
constexpr double kCdfErrorLastInShapeDistances = 64.0;
// The search over the geometric series: the first standard deviation as a fraction of the
// smallest d, and the ratio q of successive variances; then a finer grid about the best.
// It minimises the worst channel's largest CDF error (on a coarser grid than
// measureBurleyFit's) rather than the L2 error of the least squares: that error is dominated
// by the cusp of 2 pi r R(r) at r = 0 (1 / 2d there, where every Gaussian term is 0), which a
// blur barely shows, while the CDF bounds the edge response.
constexpr int kSearchCdfSamples = 300;
constexpr double kSearchCdfFirstInShapeDistances = 1e-4;
constexpr double kFirstStdDevLow = 0.005, kFirstStdDevHigh = 1.0;
constexpr double kVarianceRatioLow = 1.5, kVarianceRatioHigh = 60.0;
constexpr int kSearchSteps = 24;
constexpr int kRefineSteps = 12;

// Samples of 2 pi r R(r) (the target) and of 2 pi r G(v_i, r) (the basis) at the midpoints of
// [1e-5 d, 24 d], reduced to the normal equations gram = B^T W B, rhs = B^T W y (W: the
// quadrature weights r dt of the log grid).
struct NormalEquations {
    int n = 0;
    std::vector<double> gram;
    std::vector<double> rhs;
};

NormalEquations normalEquations(double shapeDistanceMm, const std::vector<double>& variancesMm2, int samples) {
    NormalEquations eq;
    eq.n = int(variancesMm2.size());
    eq.gram.assign(size_t(eq.n * eq.n), 0.0);
    eq.rhs.assign(size_t(eq.n), 0.0);
    const double tLow = std::log(kSampleFirstInShapeDistances * shapeDistanceMm);
    const double dt = (std::log(kFitRangeInShapeDistances * shapeDistanceMm) - tLow) / samples;
    std::vector<double> basis(static_cast<size_t>(eq.n));
    for (int k = 0; k < samples; ++k) {
        const double r = std::exp(tLow + (k + 0.5) * dt);
        const double quadratureWeight = r * dt;
        const double y = 2.0 * kPi * r * burleyRadialProfile(r, shapeDistanceMm);
        for (int i = 0; i < eq.n; ++i) {
            const double v = variancesMm2[size_t(i)];
            basis[size_t(i)] = r / v * std::exp(-r * r / (2.0 * v));
        }
        for (int i = 0; i < eq.n; ++i) {
            eq.rhs[size_t(i)] += quadratureWeight * basis[size_t(i)] * y;
            for (int j = 0; j <= i; ++j) eq.gram[size_t(i * eq.n + j)] += quadratureWeight * basis[size_t(i)] * basis[size_t(j)];
        }
    }
    for (int i = 0; i < eq.n; ++i)
        for (int j = i + 1; j < eq.n; ++j) eq.gram[size_t(i * eq.n + j)] = eq.gram[size_t(j * eq.n + i)];
    return eq;
}

// Solves the k x k system in place by Gaussian elimination with partial pivoting; false when
// a pivot is negligible (a nearly dependent subset, which a larger one will not need).
bool solve(std::vector<double>& a, std::vector<double>& b, int k) {
    for (int col = 0; col < k; ++col) {
        int pivot = col;
        for (int row = col + 1; row < k; ++row)
            if (std::fabs(a[size_t(row * k + col)]) > std::fabs(a[size_t(pivot * k + col)])) pivot = row;
        if (!(std::fabs(a[size_t(pivot * k + col)]) > 1e-300)) return false;
        if (pivot != col) {
            for (int j = 0; j < k; ++j) std::swap(a[size_t(col * k + j)], a[size_t(pivot * k + j)]);
            std::swap(b[size_t(col)], b[size_t(pivot)]);
        }
        for (int row = col + 1; row < k; ++row) {
            const double f = a[size_t(row * k + col)] / a[size_t(col * k + col)];
            for (int j = col; j < k; ++j) a[size_t(row * k + j)] -= f * a[size_t(col * k + j)];
            b[size_t(row)] -= f * b[size_t(col)];
        }
    }
    for (int row = k - 1; row >= 0; --row) {
        double sum = b[size_t(row)];
        for (int j = row + 1; j < k; ++j) sum -= a[size_t(row * k + j)] * b[size_t(j)];
        b[size_t(row)] = sum / a[size_t(row * k + row)];
    }
    return true;
}

// Non-negative least squares by enumerating the supports: the minimiser of the convex
// ||B w - y||^2 over w >= 0 is the unconstrained minimiser on its own support, so the best
// non-negative candidate among the 2^n - 1 supports is the optimum (n <= 8 keeps this cheap).
std::vector<double> nonNegativeLeastSquares(const NormalEquations& eq) {
    std::vector<double> best(static_cast<size_t>(eq.n), 0.0);
    double bestObjective = 0.0;  // w^T G w - 2 w^T b at w = 0
    std::vector<int> support;
    std::vector<double> a, b;
    for (unsigned mask = 1; mask < (1u << eq.n); ++mask) {
        support.clear();
        for (int i = 0; i < eq.n; ++i)
            if (mask & (1u << i)) support.push_back(i);
        const int k = int(support.size());
        a.assign(size_t(k * k), 0.0);
        b.assign(size_t(k), 0.0);
        for (int i = 0; i < k; ++i) {
            b[size_t(i)] = eq.rhs[size_t(support[size_t(i)])];
            for (int j = 0; j < k; ++j) a[size_t(i * k + j)] = eq.gram[size_t(support[size_t(i)] * eq.n + support[size_t(j)])];
        }
        if (!solve(a, b, k)) continue;
        if (std::any_of(b.begin(), b.end(), [](double w) { return !(w >= 0.0); })) continue;
        // At the support's least-squares solution G w = b, so the objective is -w^T b.
        double objective = 0.0;
        for (int i = 0; i < k; ++i) objective -= b[size_t(i)] * eq.rhs[size_t(support[size_t(i)])];
        if (objective < bestObjective) {
            bestObjective = objective;
            std::fill(best.begin(), best.end(), 0.0);
            for (int i = 0; i < k; ++i) best[size_t(support[size_t(i)])] = b[size_t(i)];
        }
    }
    return best;
}

double logLerp(double low, double high, double t) { return low * std::pow(high / low, t); }

// max |F_fit - F| over a log grid of r / d, after normalising the weights; infinite when they sum to 0.
double largestCdfError(double shapeDistanceMm, const std::vector<double>& variancesMm2, const std::vector<double>& weights) {
    double sum = 0.0;
    for (double w : weights) sum += w;
    if (!(sum > 0.0)) return std::numeric_limits<double>::infinity();
    double largest = 0.0;
    for (int k = 0; k < kSearchCdfSamples; ++k) {
        const double r = shapeDistanceMm * logLerp(kSearchCdfFirstInShapeDistances, kCdfErrorLastInShapeDistances,
                                                   k / double(kSearchCdfSamples - 1));
        double fitted = 0.0;
        for (size_t i = 0; i < weights.size(); ++i) fitted += weights[i] / sum * -std::expm1(-r * r / (2.0 * variancesMm2[i]));
        largest = std::fmax(largest, std::fabs(fitted - burleyRadialCdf(r, shapeDistanceMm)));
    }
    return largest;
}

std::vector<double> geometricVariances(double firstStdDevMm, double ratio, int n) {
    std::vector<double> variances(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) variances[size_t(i)] = firstStdDevMm * firstStdDevMm * std::pow(ratio, i);
    return variances;
}

struct SeriesFit {
    double worstError = std::numeric_limits<double>::infinity();  // largest CDF error over the channels
    double firstStdDevMm = 0.0;
    double ratio = 0.0;
    std::vector<double> weights[3];
};

SeriesFit fitSeries(const glm::dvec3& shapeDistanceMm, double firstStdDevMm, double ratio, int n) {
    SeriesFit fit;
    fit.firstStdDevMm = firstStdDevMm;
    fit.ratio = ratio;
    const std::vector<double> variances = geometricVariances(firstStdDevMm, ratio, n);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const NormalEquations eq = normalEquations(shapeDistanceMm[c], variances, kFitSamples);
        fit.weights[c] = nonNegativeLeastSquares(eq);
        worst = std::fmax(worst, largestCdfError(shapeDistanceMm[c], variances, fit.weights[c]));
    }
    fit.worstError = worst;
    return fit;
}

}  // namespace

double burleyScalingFactor(double albedo) {
    const double offset = std::fabs(albedo - 0.8);
    return 1.85 - albedo + 7.0 * offset * offset * offset;  // Christensen & Burley 2015, searchlight, mean free path
}

glm::dvec3 burleyShapeDistanceMm(const BurleyParameters& parameters) {
    glm::dvec3 d;
    for (int c = 0; c < 3; ++c) d[c] = double(parameters.scatteringDistanceMm[c]) / burleyScalingFactor(parameters.albedo[c]);
    return d;
}

double burleyRadialProfile(double radiusMm, double shapeDistanceMm) {
    const double r = std::fabs(radiusMm);
    const double d = shapeDistanceMm;
    return (std::exp(-r / d) + std::exp(-r / (3.0 * d))) / (8.0 * kPi * d * r);
}

double burleyRadialCdf(double radiusMm, double shapeDistanceMm) {
    const double r = std::fmax(radiusMm, 0.0);
    const double d = shapeDistanceMm;
    return 1.0 - 0.25 * std::exp(-r / d) - 0.75 * std::exp(-r / (3.0 * d));
}

glm::dvec3 burleyRadialProfile(const BurleyParameters& parameters, double radiusMm) {
    const glm::dvec3 d = burleyShapeDistanceMm(parameters);
    return {burleyRadialProfile(radiusMm, d.x), burleyRadialProfile(radiusMm, d.y), burleyRadialProfile(radiusMm, d.z)};
}

glm::dvec3 burleyRadialCdf(const BurleyParameters& parameters, double radiusMm) {
    const glm::dvec3 d = burleyShapeDistanceMm(parameters);
    return {burleyRadialCdf(radiusMm, d.x), burleyRadialCdf(radiusMm, d.y), burleyRadialCdf(radiusMm, d.z)};
}

Status validateBurleyParameters(const BurleyParameters& parameters) {
    for (int c = 0; c < 3; ++c) {
        const float a = parameters.albedo[c];
        const float l = parameters.scatteringDistanceMm[c];
        if (!(a >= 0.0f && a <= 1.0f))
            return makeError("", std::string("Burley parameters: the ") + kChannelNames[c] + " albedo is " + std::to_string(a) +
                                     "; it must be in [0, 1]");
        if (!(l > 0.0f) || !std::isfinite(l))
            return makeError("", std::string("Burley parameters: the ") + kChannelNames[c] + " scattering distance is " +
                                     std::to_string(l) + " mm; it must be finite and > 0");
    }
    return success();
}

glm::dvec3 gaussianRadialCdf(const DiffusionProfile& profile, double radiusMm) {
    const double r2 = radiusMm * radiusMm;
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : profile.gaussians())
        sum += glm::dvec3(g.weight) * -std::expm1(-r2 / (2.0 * double(g.varianceMm2)));
    return sum;
}

Result<DiffusionProfile> fitBurleyGaussians(const BurleyParameters& parameters, int gaussians, std::string name) {
    if (Status valid = validateBurleyParameters(parameters); !valid.ok()) return valid.error();
    if (gaussians < 1 || gaussians > kMaxBurleyGaussians)
        return makeError("", "Burley fit: " + std::to_string(gaussians) + " Gaussians; the fit takes 1 to " +
                                 std::to_string(kMaxBurleyGaussians));
    const glm::dvec3 d = burleyShapeDistanceMm(parameters);
    const double smallestDMm = std::fmin(d.x, std::fmin(d.y, d.z));

    SeriesFit best;
    for (int i = 0; i < kSearchSteps; ++i)
        for (int j = 0; j < kSearchSteps; ++j) {
            const double sigma = smallestDMm * logLerp(kFirstStdDevLow, kFirstStdDevHigh, i / double(kSearchSteps - 1));
            const double ratio = gaussians == 1 ? 2.0 : logLerp(kVarianceRatioLow, kVarianceRatioHigh, j / double(kSearchSteps - 1));
            SeriesFit fit = fitSeries(d, sigma, ratio, gaussians);
            if (fit.worstError < best.worstError) best = std::move(fit);
        }
    // A finer grid spanning one coarse step either side of the best.
    const double sigmaStep = std::pow(kFirstStdDevHigh / kFirstStdDevLow, 1.0 / (kSearchSteps - 1));
    const double ratioStep = std::pow(kVarianceRatioHigh / kVarianceRatioLow, 1.0 / (kSearchSteps - 1));
    const SeriesFit coarse = best;
    for (int i = 0; i < kRefineSteps; ++i)
        for (int j = 0; j < kRefineSteps; ++j) {
            const double sigma = coarse.firstStdDevMm * logLerp(1.0 / sigmaStep, sigmaStep, i / double(kRefineSteps - 1));
            const double ratio = gaussians == 1 ? 2.0 : coarse.ratio * logLerp(1.0 / ratioStep, ratioStep, j / double(kRefineSteps - 1));
            if (ratio <= 1.0) continue;
            SeriesFit fit = fitSeries(d, sigma, ratio, gaussians);
            if (fit.worstError < best.worstError) best = std::move(fit);
        }
    if (!std::isfinite(best.worstError)) return makeError("", "Burley fit: no series of " + std::to_string(gaussians) + " Gaussians fits");

    const std::vector<double> variances = geometricVariances(best.firstStdDevMm, best.ratio, gaussians);
    std::vector<ProfileGaussian> profileGaussians(static_cast<size_t>(gaussians));
    for (int i = 0; i < gaussians; ++i) {
        profileGaussians[size_t(i)].varianceMm2 = float(variances[size_t(i)]);
        for (int c = 0; c < 3; ++c) profileGaussians[size_t(i)].weight[c] = float(best.weights[c][size_t(i)]);
    }
    Result<DiffusionProfile> profile = DiffusionProfile::create(std::move(name), std::move(profileGaussians));
    if (profile.ok()) profile->setBurley(parameters);
    return profile;
}

BurleyFitError measureBurleyFit(const BurleyParameters& parameters, const DiffusionProfile& profile) {
    const glm::dvec3 d = burleyShapeDistanceMm(parameters);
    BurleyFitError error;
    for (int c = 0; c < 3; ++c) {
        const double tLow = std::log(kSampleFirstInShapeDistances * d[c]);
        const double dt = (std::log(kFitRangeInShapeDistances * d[c]) - tLow) / kErrorSamples;
        double difference = 0.0, norm = 0.0;
        for (int k = 0; k < kErrorSamples; ++k) {
            const double r = std::exp(tLow + (k + 0.5) * dt);
            const double target = 2.0 * kPi * r * burleyRadialProfile(r, d[c]);
            const double fitted = 2.0 * kPi * r * double(profile.radialProfile(float(r))[c]);
            difference += r * (fitted - target) * (fitted - target);
            norm += r * target * target;
        }
        error.relativeL2[c] = std::sqrt(difference / norm);
    }
    // The edge response is E(-a) = integral over r > a of f(r) h(r) dr, with f = dF/dr and
    // h(r) = acos(a/r) / pi rising from 0 to 1/2; by parts, E_fit - E = -integral (F_fit - F) h' dr,
    // so it is off by at most max |F_fit - F| / 2.
    const double low = kCdfErrorFirstInShapeDistances * std::fmin(d.x, std::fmin(d.y, d.z));
    const double high = kCdfErrorLastInShapeDistances * std::fmax(d.x, std::fmax(d.y, d.z));
    for (int k = 0; k < kCdfErrorSamples; ++k) {
        const double r = logLerp(low, high, k / double(kCdfErrorSamples - 1));
        const glm::dvec3 difference = glm::abs(gaussianRadialCdf(profile, r) - burleyRadialCdf(parameters, r));
        error.largestCdfError = glm::max(error.largestCdfError, difference);
    }
    return error;
}

}  // namespace dermis
