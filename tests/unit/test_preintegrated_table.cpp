// Pre-integrated skin shading (Penner & Borshukov 2011; sss/PreintegratedTable.h): the ring model
// against its closed forms (no scattering on a flat surface, the flat-terminator limit, the
// integral kept by a convolution on the circle, the uniform kernel of a tiny sphere), the table
// against the direct value, and the ring model against a quadrature over a true sphere.
#include "core/GaussLegendre.h"
#include "sss/PreintegratedTable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

double standardNormalPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * kPi); }
double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// integral of f over [a, b] by the rule on each panel between consecutive sorted breaks.
template <class F>
double integratePanels(std::vector<double> breaks, const GaussLegendre& rule, F&& f) {
    std::sort(breaks.begin(), breaks.end());
    double sum = 0.0;
    for (size_t p = 0; p + 1 < breaks.size(); ++p) {
        const double half = 0.5 * (breaks[p + 1] - breaks[p]), mid = 0.5 * (breaks[p + 1] + breaks[p]);
        if (!(half > 0.0)) continue;
        for (size_t k = 0; k < rule.nodes.size(); ++k) sum += half * rule.weights[k] * f(mid + half * rule.nodes[k]);
    }
    return sum;
}

// Panel breaks on [0, pi] graded geometrically towards pi/2 (ratio 2, from `finest` up), where
// D bends over a width of each Gaussian's angular standard deviation.
std::vector<double> gradedAboutTerminator(double finest) {
    std::vector<double> breaks{0.0, 0.5 * kPi, kPi};
    for (double offset = finest; offset < 0.5 * kPi; offset *= 2.0) {
        breaks.push_back(0.5 * kPi - offset);
        breaks.push_back(0.5 * kPi + offset);
    }
    return breaks;
}

double smallestStdDevMm(const DiffusionProfile& profile) { return std::sqrt(double(profile.gaussians().front().varianceMm2)); }

double largestError(const glm::vec3& a, const glm::dvec3& b) {
    return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

// The scattered irradiance on a true sphere of radius r lit by a distant light, at a point P at
// angle theta from the light: integral over the sphere of cos+(angle of P' from the light)
// R(|P - P'|) dA' / integral over the sphere of R(|P - P'|) dA', per channel, R the profile at the
// chord distance d. In polar coordinates (alpha, beta) about P, the angle of P' from the light
// has cosine cos theta cos alpha + sin theta sin alpha cos beta (the spherical law of cosines), the
// beta integral of its positive part is closed (below), and r^2 sin alpha dalpha = d dd. The
// denominator is closed: 2 pi integral_0^{2r} G(v, d) d dd = 1 - exp(-2 r^2 / v).
double azimuthIntegral(double a, double b) {  // integral_0^{2 pi} max(a + b cos beta, 0) dbeta, b >= 0
    if (a >= b) return 2.0 * kPi * a;
    if (a <= -b) return 0.0;
    const double beta0 = std::acos(-a / b);
    return 2.0 * (a * beta0 + b * std::sin(beta0));
}

glm::dvec3 sphereScattering(const DiffusionProfile& profile, double radiusMm, double theta) {
    static const GaussLegendre kRule = makeGaussLegendre(10);
    glm::dvec3 numerator(0.0), denominator(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double v = g.varianceMm2;
        const double dMax = std::min(2.0 * radiusMm, 10.0 * std::sqrt(v));  // exp(-50) beyond
        std::vector<double> breaks;
        for (int k = 0; k <= 48; ++k) breaks.push_back(dMax * k / 48.0);
        // Where the azimuth integral changes form (a = +-b): alpha = |pi/2 - theta|, pi/2 + theta, 3 pi/2 - theta.
        for (double alpha : {std::fabs(0.5 * kPi - theta), 0.5 * kPi + theta, 1.5 * kPi - theta}) {
            const double d = 2.0 * radiusMm * std::sin(0.5 * std::min(alpha, kPi));
            if (d > 0.0 && d < dMax) breaks.push_back(d);
        }
        const double integral = integratePanels(breaks, kRule, [&](double d) {
            const double alpha = 2.0 * std::asin(std::min(d / (2.0 * radiusMm), 1.0));
            const double k = azimuthIntegral(std::cos(theta) * std::cos(alpha), std::sin(theta) * std::sin(alpha));
            return k * std::exp(-d * d / (2.0 * v)) / (2.0 * kPi * v) * d;
        });
        numerator += glm::dvec3(g.weight) * integral;
        denominator += glm::dvec3(g.weight) * -std::expm1(-2.0 * radiusMm * radiusMm / v);
    }
    return numerator / denominator;
}

}  // namespace

// kappa = 0: a flat surface, no light crosses the terminator: D = max(cos theta, 0) exactly. The
// table's first row sits at kappa = max / (2 x 64)^2 = 6.1e-5 /mm, where skin's widest Gaussian
// has s = 1.7e-4 rad, far inside the 1/64 from the nearest texel centre to the terminator: it
// differs from max(cos, 0) by the factor exp(-s^2 / 2) ~ 1 - 1.4e-8, below float rounding
// (6e-8); the bound is float rounding, 1e-6. Measured: 0 for both (the factor rounds away).
// Broken on purpose: the widest Gaussian dropped (weights not renormalised) gives 7.7e-2 on the
// table, red's weight of it (the direct value at kappa = 0 takes the no-scattering path).
TEST(PreintegratedTable, FlatSurfaceIsLambert) {
    const PreintegratedTable table = makePreintegratedTable(skinProfile(), 1.0f);
    ASSERT_EQ(table.texels.size(), size_t(table.cosines) * size_t(table.curvatures));
    double worstDirect = 0.0, worstTable = 0.0;
    for (int i = 0; i < table.cosines; ++i) {
        const float cosTheta = 2.0f * (float(i) + 0.5f) / float(table.cosines) - 1.0f;
        const glm::dvec3 lambert(std::max(double(cosTheta), 0.0));
        worstDirect = std::max(worstDirect, largestError(preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, 0.0f), lambert));
        worstTable = std::max(worstTable, largestError(table.at(cosTheta, 0.0f), lambert));
        worstTable = std::max(worstTable, largestError(table.texels[size_t(i)], lambert));
    }
    std::printf("[ measured ] kappa = 0: direct %.2e, table row 0 %.2e\n", worstDirect, worstTable);
    EXPECT_EQ(worstDirect, 0.0);
    EXPECT_LT(worstTable, 1e-6);
}

// Near the terminator (theta = pi/2 + delta) of a gently curved surface the ring is locally flat:
// cos(theta + x) = -sin(delta + x) ~ -(delta + x), and a Gaussian of angular standard deviation s
// gives E[max(-(delta + x), 0)] = s phi(delta / s) - delta Phi(-delta / s); skin sums that over its
// Gaussians with their weights. The linearisation drops (delta + x)^3 / 6 against (delta + x):
// relative O((s^2 + delta^2) / 6) <= 3e-5 for s, |delta| <= 0.01 (kappa below gives s = 0.01 for
// the widest Gaussian). Bound 1e-4 relative; measured 2.6e-5 (red, delta = -0.01), 1.3e-5 at
// delta = 0. (The implementation's quadrature error, relative to D, grows where D is a Gaussian
// tail; at delta = 0.01, 3.6 standard deviations into blue's shadow, it is below this.)
// Broken on purpose: widths x1.05 gives 5.0e-2 at delta = 0 (D ~ s there), 1.09 at worst (deep
// shadow); the widest Gaussian dropped 0.77; weights w_i / sqrt(v_i), the cross-section's, 0.91.
TEST(PreintegratedTable, FlatTerminatorClosedForm) {
    const DiffusionProfile& profile = skinProfile();
    const double widest = std::sqrt(double(profile.gaussians().back().varianceMm2));
    const float curvature = float(0.01 / widest);
    double worst = 0.0, worstDelta = 0.0, atZero = 0.0;
    int worstChannel = 0;
    for (int m = -10; m <= 10; ++m) {
        const float cosTheta = float(-std::sin(0.001 * m));
        const double delta = std::asin(-double(cosTheta));  // the delta of the float actually passed
        glm::dvec3 expected(0.0);
        for (const ProfileGaussian& g : profile.gaussians()) {
            const double s = std::sqrt(double(g.varianceMm2)) * double(curvature);
            expected += glm::dvec3(g.weight) * (s * standardNormalPdf(delta / s) - delta * normalCdf(-delta / s));
        }
        const glm::vec3 got = preintegratedDiffuse(profile, 1.0f, cosTheta, curvature);
        for (int c = 0; c < 3; ++c) {
            const double relative = std::fabs(got[c] - expected[c]) / expected[c];
            if (relative > worst) worst = relative, worstDelta = delta, worstChannel = c;
            if (m == 0) atZero = std::max(atZero, relative);
            EXPECT_LT(relative, 1e-4) << "delta " << delta << " channel " << c << ": " << got[c] << " vs " << expected[c];
        }
    }
    std::printf("[ measured ] flat terminator: largest relative error %.2e (channel %d, delta %.3f; bound 1e-4), at delta = 0 %.2e\n",
                worst, worstChannel, worstDelta, atZero);
}

// A convolution on the circle keeps the integral: integral_{-pi}^{pi} D = integral cos+ = 2, and
// D is even, so integral_0^pi D(theta) dtheta = 1 at every curvature, for every profile.
// Quadrature: 8-point Gauss-Legendre on panels graded towards pi/2 from a quarter of the
// narrowest Gaussian's angular standard deviation, where D bends; against 16 points it moves by
// 3e-8, the values' float rounding (6e-8 relative). Bound 1e-6; measured 3.6e-8.
// Through the table (at(), 2048 midpoints in theta) the edge texels clamp: for cos > 1 - 1/64 it
// returns the last texel centre's value instead of cos theta, which loses
// integral_0^{t1} (cos t - cos t1) dt = sin t1 - t1 cos t1 = 1.8e-3 at t1 = acos(1 - 1/64)
// (and next to nothing at cos < -1 + 1/64, where D is ~0); linear interpolation across the
// smoothed kink adds at most (1/32)^2 / 8 = 1.2e-4. Bound 2.2e-3; measured 1.76e-3.
// Broken on purpose: the widest Gaussian dropped without renormalising gives 0.15 (marble's red
// weight of it; skin's is 7.8e-2). A wrong width keeps the integral: widths x1.05 pass here,
// and the flat-terminator and sphere tests catch them.
TEST(PreintegratedTable, RingIntegralIsKept) {
    const GaussLegendre rule = makeGaussLegendre(8);
    double worstDirect = 0.0, worstTable = 0.0;
    for (const DiffusionProfile* profile : {&skinProfile(), &marbleProfile()}) {
        for (float curvature : {0.0f, 1e-4f, 1e-3f, 0.01f, 0.05f, 0.2f, 0.5f, 1.0f, 3.0f}) {
            const double finest = std::max(0.25 * smallestStdDevMm(*profile) * double(curvature), 1e-7);
            glm::dvec3 integral(0.0);
            for (int c = 0; c < 3; ++c)
                integral[c] = integratePanels(gradedAboutTerminator(finest), rule, [&](double theta) {
                    return double(preintegratedDiffuse(*profile, 1.0f, float(std::cos(theta)), curvature)[c]);
                });
            worstDirect = std::max(worstDirect, largestError(glm::vec3(1.0f), integral));
            EXPECT_NEAR(integral.r, 1.0, 1e-6) << profile->name() << " kappa " << curvature;
            EXPECT_NEAR(integral.g, 1.0, 1e-6) << profile->name() << " kappa " << curvature;
            EXPECT_NEAR(integral.b, 1.0, 1e-6) << profile->name() << " kappa " << curvature;
        }
        const PreintegratedTable table = makePreintegratedTable(*profile, 1.0f);
        for (int j = 0; j < table.curvatures; j += 9) {
            const double y = (j + 0.5) / table.curvatures;
            const float curvature = float(table.maxCurvaturePerMm * y * y);
            glm::dvec3 integral(0.0);
            constexpr int kSteps = 2048;
            for (int k = 0; k < kSteps; ++k)
                integral += glm::dvec3(table.at(float(std::cos(kPi * (k + 0.5) / kSteps)), curvature)) * (kPi / kSteps);
            worstTable = std::max(worstTable, largestError(glm::vec3(1.0f), integral));
            EXPECT_NEAR(integral.r, 1.0, 2.2e-3) << profile->name() << " row " << j;
            EXPECT_NEAR(integral.g, 1.0, 2.2e-3) << profile->name() << " row " << j;
            EXPECT_NEAR(integral.b, 1.0, 2.2e-3) << profile->name() << " row " << j;
        }
    }
    std::printf("[ measured ] ring integral: direct %.2e (bound 1e-6), table %.2e (bound 2.2e-3)\n", worstDirect, worstTable);
}

// The table against the direct value at random points. Between texel centres the bilinear
// error is largest where D still has the kink of max(cos, 0) (small curvature): at cos = 0, midway
// between the centres +-1/64, the interpolant reads 1/128 = 7.8e-3 where D ~ 0; the error along
// y (D ~ linear in kappa = max y^2 near the terminator) is second order, (1/64)^2 / 4 of the
// slope. Bound 8.5e-3; measured 7.81e-3 at that point (cos = 0 on the first row), 5.1e-3 at the
// 2000 random points. Between the last texel centre and the edge (1/128 in x,
// 1/64 in cos) the sampler clamps: D's slope in cos there is at most 1 (Lambert's, shrunk by the
// blur), so the error is at most 1/64 = 1.56e-2. Bound 1.6e-2; measured 1.55e-2.
TEST(PreintegratedTable, TableFollowsTheDirectValue) {
    const PreintegratedTable table = makePreintegratedTable(skinProfile(), 1.0f);
    std::mt19937 rng(20110601);
    const float firstCos = 1.0f / float(table.cosines) - 1.0f, lastCos = 1.0f - 1.0f / float(table.cosines);
    const float firstY = 0.5f / float(table.curvatures), lastY = 1.0f - firstY;
    std::uniform_real_distribution<float> inside(0.0f, 1.0f);
    // The worst point: the kink midway between texel centres, on the first row.
    const float firstRow = table.maxCurvaturePerMm * firstY * firstY;
    const double atKink = largestError(table.at(0.0f, firstRow), glm::dvec3(preintegratedDiffuse(skinProfile(), 1.0f, 0.0f, firstRow)));
    double worstInside = atKink, worstEdge = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const float cosTheta = firstCos + (lastCos - firstCos) * inside(rng);
        const float y = firstY + (lastY - firstY) * inside(rng);
        const float curvature = table.maxCurvaturePerMm * y * y;
        const glm::vec3 exact = preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, curvature);
        worstInside = std::max(worstInside, largestError(table.at(cosTheta, curvature), glm::dvec3(exact)));
    }
    for (int k = 0; k < 200; ++k) {
        const float y = inside(rng);
        const float curvature = table.maxCurvaturePerMm * y * y;
        const float edge = (1.0f - lastCos) * inside(rng);
        for (float cosTheta : {-1.0f + edge, 1.0f - edge}) {
            const glm::vec3 exact = preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, curvature);
            worstEdge = std::max(worstEdge, largestError(table.at(cosTheta, curvature), glm::dvec3(exact)));
        }
    }
    std::printf("[ measured ] table vs direct: at the kink %.2e, inside %.2e (bound 8.5e-3), edge %.2e (bound 1.6e-2)\n", atKink,
                worstInside, worstEdge);
    EXPECT_LT(worstInside, 8.5e-3);
    EXPECT_LT(worstEdge, 1.6e-2);
}

// The ring model against a true sphere (sphereScattering above: the profile at the chord
// distance, over the whole surface, normalised by its integral there). The ring blurs along one
// great circle only; on the sphere the surface also curves away ACROSS it, so at a lit point the
// kernel sees cos(angle) ~ cos theta (1 - (a^2 + b^2) / 2) over both tangent axes a, b: to second
// order the sphere keeps cos theta (1 - s^2) of band 1 where the ring keeps cos theta (1 - s^2/2)
// (s = sigma kappa per Gaussian). So the sphere is darker by max(cos theta, 0) sum_i w_i s_i^2 / 2
// on the lit side: 2.77e-2 for red at r = 5 mm (its widest Gaussians, 1.4 and 2.7 mm, are s = 0.28
// and 0.54 rad there), 1.73e-3 at r = 20 mm. Measured largest differences (red, theta = 0):
// 2.79e-2 and 1.73e-3; bounds 3e-2 and 2e-3, just above. With that term added back, what is left is
// the next order, which scales as r^-3 (measured 1.51e-3 at 5 mm, red, 0.42 rad past the
// terminator, where the sphere wraps more light round; 2.31e-5 at 20 mm: x65 for x4 in r);
// bounds 2e-3 and 3e-5.
// Broken on purpose: widths x1.05 pass the first bounds (a wider ring is darker on the lit side,
// towards the sphere) but leave residuals 8.9e-4 (20 mm) and 3.9e-3 (5 mm); the widest Gaussian
// dropped gives 7.6e-2 and 3.9e-2 (residuals 7.7e-2, 6.7e-2); weights w_i / sqrt(v_i), the
// cross-section's, 1.3e-2 and 5.0e-2.
TEST(PreintegratedTable, RingMatchesATrueSphere) {
    struct Case {
        double radiusMm, rawBound, residualBound;
    };
    for (const Case& test : {Case{20.0, 2e-3, 3e-5}, Case{5.0, 3e-2, 2e-3}}) {
        glm::dvec3 transverse(0.0);  // sum_i w_i s_i^2 / 2
        for (const ProfileGaussian& g : skinProfile().gaussians())
            transverse += glm::dvec3(g.weight) * (double(g.varianceMm2) / (2.0 * test.radiusMm * test.radiusMm));
        double worstRaw = 0.0, worstResidual = 0.0;
        for (int k = 0; k <= 60; ++k) {
            const float cosTheta = float(std::cos(kPi * k / 60.0));
            const glm::dvec3 sphere = sphereScattering(skinProfile(), test.radiusMm, std::acos(double(cosTheta)));
            const glm::vec3 ring = preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, float(1.0 / test.radiusMm));
            worstRaw = std::max(worstRaw, largestError(ring, sphere));
            worstResidual = std::max(worstResidual, largestError(ring, sphere + std::max(double(cosTheta), 0.0) * transverse));
        }
        std::printf("[ measured ] sphere r = %.0f mm: largest difference %.2e (bound %.0e), less the transverse term %.2e (bound %.0e)\n",
                    test.radiusMm, worstRaw, test.rawBound, worstResidual, test.residualBound);
        EXPECT_LT(worstRaw, test.rawBound) << "r = " << test.radiusMm << " mm";
        EXPECT_LT(worstResidual, test.residualBound) << "r = " << test.radiusMm << " mm";
    }
}

// A sphere far smaller than the profile (kappa = 1e6 /mm: even skin's narrowest Gaussian spans
// s = 8e4 rad) spreads the light evenly round the ring: D -> (1 / 2 pi) integral cos+ = 1 / pi.
// The kernel's departure from uniform, x^2 / 2 s^2 < 1e-9, is below float rounding: bound 1e-6.
TEST(PreintegratedTable, TinySphereIsUniform) {
    for (float cosTheta : {-1.0f, -0.3f, 0.0f, 0.7f, 1.0f}) {
        const glm::vec3 d = preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, 1e6f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], 1.0 / kPi, 1e-6) << cosTheta;
    }
}

// Only s = sqrt(v) widthScale kappa enters: doubling the width is doubling the curvature.
TEST(PreintegratedTable, WidthScaleActsAsCurvature) {
    for (float cosTheta : {-0.2f, 0.0f, 0.1f, 0.6f}) {
        const glm::vec3 wide = preintegratedDiffuse(skinProfile(), 2.0f, cosTheta, 0.1f);
        const glm::vec3 curved = preintegratedDiffuse(skinProfile(), 1.0f, cosTheta, 0.2f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(wide[c], curved[c], 1e-6) << cosTheta;
    }
}

TEST(PreintegratedTable, AlwaysFinite) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const float huge = std::numeric_limits<float>::max();
    for (float widthScale : {1.0f, 0.0f, -1.0f, nan, inf, 1e-30f, 1e30f})
        for (float curvature : {0.0f, 1e-30f, 1e-3f, 1.0f, 1e6f, huge, inf, nan, -1.0f})
            for (float cosTheta : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f, -2.0f, 2.0f, nan}) {
                const glm::vec3 d = preintegratedDiffuse(skinProfile(), widthScale, cosTheta, curvature);
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(d[c])) << widthScale << " " << curvature << " " << cosTheta;
                    EXPECT_GE(d[c], 0.0f);
                    EXPECT_LE(d[c], 1.0f + 1e-6f);
                }
                // No scattering: exactly Lambert (0 for a NaN cosine).
                if (!(widthScale > 0.0f) || !std::isfinite(widthScale) || !(curvature > 0.0f) || !std::isfinite(curvature)) {
                    const float lambert = std::isnan(cosTheta) ? 0.0f : std::clamp(cosTheta, 0.0f, 1.0f);
                    EXPECT_EQ(d, glm::vec3(lambert)) << widthScale << " " << curvature << " " << cosTheta;
                }
            }
    const PreintegratedTable flat = makePreintegratedTable(skinProfile(), 0.0f);
    for (size_t k = 0; k < flat.texels.size(); ++k) {
        const float cosTheta = 2.0f * (float(k % size_t(flat.cosines)) + 0.5f) / float(flat.cosines) - 1.0f;
        ASSERT_EQ(flat.texels[k], glm::vec3(std::max(cosTheta, 0.0f))) << k;
    }
    const PreintegratedTable table = makePreintegratedTable(skinProfile(), 1.0f);
    for (const glm::vec3& texel : table.texels) ASSERT_TRUE(std::isfinite(texel.r + texel.g + texel.b));
    for (float curvature : {nan, -1.0f, 0.0f, 1.0f, huge, inf})
        for (float cosTheta : {nan, -2.0f, -1.0f, 0.0f, 1.0f, 2.0f}) {
            const glm::vec3 d = table.at(cosTheta, curvature);
            EXPECT_TRUE(std::isfinite(d.r + d.g + d.b)) << cosTheta << " " << curvature;
        }
}
