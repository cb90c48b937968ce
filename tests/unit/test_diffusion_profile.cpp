// The diffusion profile (docs/screen-space.md, "Diffusion profiles"; Chappuis 2011 §2.1.3-2.1.4).
#include "sss/DiffusionProfile.h"

#include "Quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

using quadrature::simpson;

// The integral of R over the plane per channel, 2 pi r R(r) dr with r = e^t (the profiles span
// variances from 0.0064 to 42 mm^2, so a log grid resolves all of them).
double planeIntegral(const DiffusionProfile& profile, int channel) {
    return simpson([&](double t) {
        const double r = std::exp(t);
        return 2.0 * kPi * r * r * double(profile.radialProfile(float(r))[channel]);
    }, std::log(1e-6), std::log(200.0), 20000);
}

// The lit fraction reaching a point at signed distance x from the edge, in polar coordinates
// about the point: sum over rings of R(r) r times the angle of the ring inside x' > 0.
double halfPlaneIntegral(const DiffusionProfile& profile, double xMm, int channel) {
    const double a = std::fabs(xMm);
    const auto R = [&](double r) { return double(profile.radialProfile(float(r))[channel]); };
    // Rings inside |x| lie wholly in the lit (x > 0) or the dark (x < 0) half.
    const double inner = xMm > 0.0 ? simpson([&](double t) { const double r = std::exp(t); return 2.0 * kPi * r * r * R(r); },
                                             std::log(1e-6), std::log(a), 20000)
                                   : 0.0;
    // Beyond |x|, r = |x| cosh(t): the ring's angle inside the lit half is 2 acos(|x| / r) for a dark
    // point and 2 pi minus that for a lit one.
    const double outer = simpson([&](double t) {
        const double r = a * std::cosh(t);
        const double darkSideAngle = 2.0 * std::acos(std::fmin(a / r, 1.0));
        const double angle = xMm > 0.0 ? 2.0 * kPi - darkSideAngle : darkSideAngle;
        return angle * r * R(r) * a * std::sinh(t);
    }, 0.0, std::acosh(200.0 / a), 40000);
    return inner + outer;
}

// Jensen et al. 2001 (§2.4): the classical dipole for a semi-infinite medium.
struct Medium {
    double sigmaSPrime, sigmaA, eta;
};

double diffuseFresnelReflectance(double eta) { return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta; }

double dipoleRd(const Medium& medium, double r) {
    const double sigmaTPrime = medium.sigmaA + medium.sigmaSPrime;
    const double albedo = medium.sigmaSPrime / sigmaTPrime;
    const double sigmaTr = std::sqrt(3.0 * medium.sigmaA * sigmaTPrime);
    const double fdr = diffuseFresnelReflectance(medium.eta);
    const double A = (1.0 + fdr) / (1.0 - fdr);
    const double zr = 1.0 / sigmaTPrime;
    const double zv = zr * (1.0 + 4.0 * A / 3.0);
    const double dr = std::sqrt(r * r + zr * zr);
    const double dv = std::sqrt(r * r + zv * zv);
    return albedo / (4.0 * kPi) *
           (zr * (sigmaTr * dr + 1.0) * std::exp(-sigmaTr * dr) / (dr * dr * dr) +
            zv * (sigmaTr * dv + 1.0) * std::exp(-sigmaTr * dv) / (dv * dv * dv));
}

// Its integral over the plane, in closed form (Jensen et al. 2001, §2.4).
double dipoleTotalRd(const Medium& medium) {
    const double albedo = medium.sigmaSPrime / (medium.sigmaA + medium.sigmaSPrime);
    const double fdr = diffuseFresnelReflectance(medium.eta);
    const double A = (1.0 + fdr) / (1.0 - fdr);
    const double s = std::sqrt(3.0 * (1.0 - albedo));
    return 0.5 * albedo * (1.0 + std::exp(-4.0 / 3.0 * A * s)) * std::exp(-s);
}

const Medium kMarble[3] = {{2.19, 0.0021, 1.5}, {2.62, 0.0041, 1.5}, {3.00, 0.0071, 1.5}};

std::string createError(std::vector<ProfileGaussian> gaussians) {
    Result<DiffusionProfile> profile = DiffusionProfile::create("test", std::move(gaussians));
    return profile.ok() ? std::string("(accepted)") : profile.error().message();
}

}  // namespace

TEST(DiffusionProfile, SkinIsChappuisFigure27) {
    const DiffusionProfile& skin = skinProfile();
    const float variances[6] = {0.0064f, 0.0484f, 0.187f, 0.567f, 1.99f, 7.41f};
    const glm::vec3 weights[6] = {{0.233f, 0.455f, 0.649f}, {0.100f, 0.336f, 0.344f}, {0.118f, 0.198f, 0.0f},
                                  {0.113f, 0.007f, 0.007f}, {0.358f, 0.004f, 0.0f},   {0.078f, 0.0f, 0.0f}};
    ASSERT_EQ(skin.size(), 6u);
    EXPECT_EQ(skin.name(), "skin");
    glm::dvec3 sums(0.0);
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(skin.gaussians()[i].varianceMm2, variances[i]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(skin.gaussians()[i].weight[c], weights[i][c], 1e-6f) << "Gaussian " << i << " channel " << c;
        sums += glm::dvec3(skin.gaussians()[i].weight);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sums[c], 1.0, 1e-6);
}

TEST(DiffusionProfile, CreateNormalisesEachChannel) {
    Result<DiffusionProfile> profile = DiffusionProfile::create("user", {{1.0f, {2.0f, 1.0f, 0.0f}}, {4.0f, {2.0f, 3.0f, 5.0f}}});
    ASSERT_TRUE(profile.ok()) << profile.error().message();
    EXPECT_EQ(profile->gaussians()[0].weight, glm::vec3(0.5f, 0.25f, 0.0f));
    EXPECT_EQ(profile->gaussians()[1].weight, glm::vec3(0.5f, 0.75f, 1.0f));
    EXPECT_FLOAT_EQ(profile->largestStdDevMm(), 2.0f);
}

TEST(DiffusionProfile, CreateRejectsBadInputsWithMessages) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(createError({}), "diffusion profile \"test\": has no Gaussians");
    EXPECT_NE(createError({{0.0f, glm::vec3(1.0f)}}).find("Gaussian 1 has variance 0.000000 mm^2; variances must be finite and > 0"),
              std::string::npos);
    EXPECT_NE(createError({{-1.0f, glm::vec3(1.0f)}}).find("variances must be finite and > 0"), std::string::npos);
    EXPECT_NE(createError({{nan, glm::vec3(1.0f)}}).find("variances must be finite and > 0"), std::string::npos);
    EXPECT_NE(createError({{inf, glm::vec3(1.0f)}}).find("variances must be finite and > 0"), std::string::npos);
    EXPECT_NE(createError({{1.0f, glm::vec3(1.0f)}, {1.0f, glm::vec3(1.0f)}}).find("Gaussian 2 has variance 1.000000 mm^2, not more than Gaussian 1's"),
              std::string::npos);
    EXPECT_NE(createError({{2.0f, glm::vec3(1.0f)}, {1.0f, glm::vec3(1.0f)}}).find("variances must strictly increase"), std::string::npos);
    EXPECT_NE(createError({{1.0f, {1.0f, -0.5f, 1.0f}}}).find("Gaussian 1 has weight (1, -0.5, 1); weights must be finite and >= 0"),
              std::string::npos);
    EXPECT_NE(createError({{1.0f, {1.0f, 1.0f, nan}}}).find("weights must be finite and >= 0"), std::string::npos);
    EXPECT_NE(createError({{1.0f, {inf, 1.0f, 1.0f}}}).find("weights must be finite and >= 0"), std::string::npos);
    EXPECT_NE(createError({{1.0f, {1.0f, 0.0f, 1.0f}}, {2.0f, {1.0f, 0.0f, 1.0f}}}).find("the green weights sum to 0"), std::string::npos);
    EXPECT_EQ(createError({{1.0f, {1.0f, 1.0f, 1.0f}}}), "(accepted)");
}

TEST(DiffusionProfile, RadialProfileIntegratesToOneOverThePlane) {
    for (const DiffusionProfile* profile : {&skinProfile(), &marbleProfile()})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(planeIntegral(*profile, c), 1.0, 1e-5) << profile->name() << " channel " << c;
}

TEST(DiffusionProfile, EdgeResponseLimitsAndMonotonicity) {
    const float inf = std::numeric_limits<float>::infinity();
    for (const DiffusionProfile* profile : {&skinProfile(), &marbleProfile()}) {
        EXPECT_EQ(profile->edgeResponse(-inf), glm::vec3(0.0f));
        EXPECT_EQ(profile->edgeResponse(inf), glm::vec3(1.0f));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(profile->edgeResponse(0.0f)[c], 0.5f, 1e-6f);
            EXPECT_NEAR(profile->edgeResponse(1000.0f)[c], 1.0f, 1e-6f);
            EXPECT_NEAR(profile->edgeResponse(-1000.0f)[c], 0.0f, 1e-6f);
        }
        glm::vec3 previous = profile->edgeResponse(-100.0f);
        for (float x = -100.0f; x <= 100.0f; x += 0.01f) {
            const glm::vec3 response = profile->edgeResponse(x);
            for (int c = 0; c < 3; ++c) ASSERT_GE(response[c], previous[c]) << profile->name() << " x " << x;
            previous = response;
        }
    }
}

TEST(DiffusionProfile, EdgeResponseIsTheHalfPlaneIntegralOfR) {
    for (const DiffusionProfile* profile : {&skinProfile(), &marbleProfile()})
        for (double x : {-3.0, -0.7, -0.05, 0.02, 0.4, 2.5})
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(profile->edgeResponse(float(x))[c], halfPlaneIntegral(*profile, x, c), 2e-5)
                    << profile->name() << " x " << x << " channel " << c;
}

TEST(DiffusionProfile, LargestStdDevIsTheWidestWeightedGaussian) {
    EXPECT_FLOAT_EQ(skinProfile().largestStdDevMm(), std::sqrt(7.41f));
    EXPECT_NEAR(marbleProfile().largestStdDevMm(), std::sqrt(0.036 * std::pow(4.1, 5)), 1e-4);
    Result<DiffusionProfile> profile = DiffusionProfile::create("tail", {{1.0f, glm::vec3(1.0f)}, {9.0f, glm::vec3(0.0f)}});
    ASSERT_TRUE(profile.ok());
    EXPECT_FLOAT_EQ(profile->largestStdDevMm(), 1.0f);
}

TEST(DiffusionProfile, TestDipoleMatchesItsClosedFormTotal) {
    for (const Medium& medium : kMarble) {
        const double numeric = simpson([&](double t) { const double r = std::exp(t); return 2.0 * kPi * r * r * dipoleRd(medium, r); },
                                       std::log(1e-6), std::log(5000.0), 40000);
        EXPECT_NEAR(numeric / dipoleTotalRd(medium), 1.0, 1e-3);
    }
}

TEST(DiffusionProfile, MarbleFitsTheJensenDipoleWithinTheStatedError) {
    // The fit's claim (ProfileLibrary.cpp): relative L2 error of r R(r) over 0..20 mm below 2%.
    const DiffusionProfile& marble = marbleProfile();
    EXPECT_EQ(marble.name(), "marble");
    ASSERT_EQ(marble.size(), 6u);
    for (int c = 0; c < 3; ++c) {
        const double total = dipoleTotalRd(kMarble[c]);
        double errorSquared = 0.0, normSquared = 0.0;
        constexpr int kSteps = 20000;
        constexpr double kStepMm = 20.0 / kSteps;
        for (int i = 0; i < kSteps; ++i) {
            const double r = (i + 0.5) * kStepMm;
            const double target = r * dipoleRd(kMarble[c], r) / total;
            const double fit = r * double(marble.radialProfile(float(r))[c]);
            errorSquared += (fit - target) * (fit - target);
            normSquared += target * target;
        }
        const double relativeError = std::sqrt(errorSquared / normSquared);
        std::printf("marble channel %d: relative L2 error of r R(r) over 0..20 mm = %.4f\n", c, relativeError);
        EXPECT_LT(relativeError, 0.02) << "channel " << c;
    }
}

TEST(DiffusionProfile, RegistryFindsTheBuiltinsAndListsThemOnError) {
    EXPECT_EQ(profileNames(), (std::vector<std::string>{"skin", "marble"}));
    Result<const DiffusionProfile*> skin = findProfile("skin");
    ASSERT_TRUE(skin.ok());
    EXPECT_EQ(*skin, &skinProfile());
    Result<const DiffusionProfile*> marble = findProfile("marble");
    ASSERT_TRUE(marble.ok());
    EXPECT_EQ(*marble, &marbleProfile());
    Result<const DiffusionProfile*> unknown = findProfile("x");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().where, "");
    EXPECT_EQ(unknown.error().what, "unknown diffusion profile \"x\" (known: skin, marble)");
}
