// The disk technique (sss.technique = disk; shaders/include/DiskSss.glsl) against
// closed forms: the furnace with silhouettes, the analytic edge of the skin
// profile and of a Burley profile (its exact edge response, not its Gaussian
// fit's), the same image every render, and the LEAN variant lbb.
#include "AnalyticEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "sss/DiffusionProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

using namespace dermis;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

class DiskSss : public test::RenderFixture {};

// The scenes' example Burley profile (content/scenes/README.md).
constexpr const char* kSoftJson =
    R"({"soft": {"burley": {"albedo": [0.8, 0.6, 0.5], "mean_free_path_mm": [1.0, 0.4, 0.25]}}})";

}  // namespace

// The furnace with silhouettes: a 20 mm plane, uniformly lit, seen from 3 cm (3.4 px/mm, so the
// disk spans tens of pixels) so that its left and right edges lie in the frame against the
// background. A normalised kernel keeps uniform irradiance uniform, and beside the silhouette the
// edge test gives the background's samples over to the centre's value: every plane pixel must
// equal the same frame without SSS.
// Bound 0.1%: both are half-float irradiance through float sums of weights that add to 1 (the
// d'Eon chain's furnace measures 0.065% against its closed form); measured below.
// Broken on purpose: with a bilateral sample off the profile given its own value instead of the
// centre's (the background's zero comes in) the pixels at the silhouettes lose 52%/42%/40% (R/G/B,
// 40 samples; 71% red at 8); the control test is unaffected (0%), as designed.
TEST_F(DiskSss, FurnaceStaysUniformUpToTheSilhouettes) {
    const std::vector<std::string> scene = {"camera.position_m=[0,0.03,0]", "characters.0.transform.scale=0.02"};
    auto with = [&](std::vector<std::string> extra) {
        extra.insert(extra.begin(), scene.begin(), scene.end());
        return extra;
    };
    load("furnace.json", with({"sss.enabled=false"}));
    const Image reference = render(Aov::Diffuse, kWidth, kHeight);
    const Image albedo = render(Aov::Albedo, kWidth, kHeight);
    for (const char* blur : {"bilateral", "control"}) {
        for (int samples : {8, 40, 128}) {
            load("furnace.json", with({"sss.technique=disk", "sss.disk_samples=" + std::to_string(samples),
                                       std::string("sss.blur=") + blur}));
            const Image image = render(Aov::Diffuse, kWidth, kHeight);
            ASSERT_EQ(test::countNonFinite(image), 0u);
            const PassSummary* disk = pass("sss skin disk");
            EXPECT_TRUE(disk && disk->executed) << "the disk pass did not run";
            const PassSummary* chain = pass("sss skin g0 h");
            EXPECT_TRUE(!chain || !chain->executed) << "the d'Eon chain ran for a disk slot";
            glm::dvec3 worst(0.0);
            size_t plane = 0, background = 0;
            for (size_t i = 0; i < image.texels.size(); ++i) {
                if (albedo.texels[i].a < 0.5f) {
                    ++background;
                    continue;
                }
                ++plane;
                for (int c = 0; c < 3; ++c) {
                    const double error = double(image.texels[i][c]) / double(reference.texels[i][c]) - 1.0;
                    if (std::abs(error) > std::abs(worst[c])) worst[c] = error;
                }
            }
            std::printf("[ measured ] furnace %-9s %3d samples: worst relative error R %+.4f%% G %+.4f%% B %+.4f%% "
                        "(%zu plane, %zu background pixels)\n",
                        blur, samples, 100.0 * worst.r, 100.0 * worst.g, 100.0 * worst.b, plane, background);
            EXPECT_GT(plane, 10000u);
            EXPECT_GT(background, 1000u) << "the silhouettes must be in the frame";
            for (int c = 0; c < 3; ++c) EXPECT_LT(std::abs(worst[c]), 0.001) << blur << " " << samples << " channel " << c;
        }
    }
}

namespace {

// The flat edge of AnalyticEdge.h at 320x180: 0.1 mm per pixel.
double edgeMmPerPixel() {
    return 2.0 * test::kEdgeHeightM * 1000.0 * std::tan(test::kEdgeFovDeg * M_PI / 360.0) / kHeight;
}

// E_c(x, s): the response at x mm from a unit step lit for x > 0, of the profile widened by s.
using EdgeResponse = std::function<double(int c, double xMm, double scale)>;

// The exact diffusion of the rendered irradiance row at pixel x: each texel a box (the shader
// fetches the texel a sample rounds to), the row's jumps I_j - I_(j-1) each diffused by E, the
// border texels standing for everything beyond the frame (samples clamp there).
double exactDiffusion(const Image& irradiance, int row, int x, int c, double scale, const EdgeResponse& response) {
    double sum = irradiance.at(0, row)[c];
    for (int j = 1; j < kWidth; ++j) {
        const double jump = double(irradiance.at(j, row)[c]) - double(irradiance.at(j - 1, row)[c]);
        if (jump != 0.0) sum += jump * response(c, (x - j + 0.5) * edgeMmPerPixel(), scale);
    }
    return sum;
}

struct DiskEdge {
    double maxError = 0.0;        // largest |row mean - exact| of any channel, a fraction of its step
    glm::dvec3 widthScale{0.0};   // per channel, the width scale of the profile that fits best
    double noise = 0.0;           // RMS over the columns within reach of the std dev across rows, of the step
};

// The disk's noise is per pixel and the edge scene is uniform along y, so the rendered diffuse
// is averaged over all 180 rows (180 rotations of the spiral per column) before the comparison;
// the width scale is fitted by least squares over [0.90, 1.10] in steps of 0.0025 (over the
// pixels within reachMm of the step).
DiskEdge compareDiskEdge(const Image& irradiance, const Image& diffuse, const EdgeResponse& response, double reachMm) {
    const int row = kHeight / 2;
    const double mmPerPixel = edgeMmPerPixel();
    DiskEdge e;
    double noiseSquares = 0.0;
    int noiseColumns = 0;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> mean(kWidth, 0.0);
        for (int x = 0; x < kWidth; ++x) {
            for (int y = 0; y < kHeight; ++y) mean[size_t(x)] += diffuse.at(x, y)[c];
            mean[size_t(x)] /= kHeight;
        }
        const double step = irradiance.at(kWidth - 1, row)[c] - irradiance.at(0, row)[c];
        std::vector<int> pixels;
        for (int x = 0; x < kWidth; ++x)
            if (std::abs((x + 0.5 - kWidth / 2.0) * mmPerPixel) < reachMm) pixels.push_back(x);
        for (int x : pixels) {
            double variance = 0.0;
            for (int y = 0; y < kHeight; ++y) variance += std::pow(diffuse.at(x, y)[c] - mean[size_t(x)], 2.0);
            noiseSquares += variance / (kHeight - 1) / (step * step);
            ++noiseColumns;
        }
        double bestCost = 1e300;
        for (int k = -40; k <= 40; ++k) {
            const double scale = 1.0 + 0.0025 * k;
            double cost = 0.0;
            for (int x : pixels) {
                const double d = mean[size_t(x)] - exactDiffusion(irradiance, row, x, c, scale, response);
                cost += d * d;
            }
            if (cost < bestCost) {
                bestCost = cost;
                e.widthScale[c] = scale;
            }
        }
        for (int x : pixels)
            e.maxError = std::max(e.maxError, std::abs(mean[size_t(x)] - exactDiffusion(irradiance, row, x, c, 1.0, response)) / step);
    }
    e.noise = std::sqrt(noiseSquares / noiseColumns);
    return e;
}

// Skin's edge response from its Gaussians' data: sum_i w_i Phi(x / (s sqrt(v_i))).
double skinEdgeResponse(int c, double xMm, double scale) {
    double sum = 0.0;
    for (const ProfileGaussian& g : skinProfile().gaussians())
        sum += g.weight[c] * 0.5 * std::erfc(-xMm / (scale * std::sqrt(double(g.varianceMm2)) * M_SQRT2));
    return sum;
}

// The soft Burley profile's exact edge response: d = l / s(A), s(A) = 1.85 - A + 7 |A - 0.8|^3
// (Christensen & Burley 2015), in closed form through the Bickley function (AnalyticEdge.h).
double softEdgeResponse(int c, double xMm, double scale) {
    const double albedo[3] = {0.8, 0.6, 0.5};
    const double meanFreePathMm[3] = {1.0, 0.4, 0.25};
    const double a = albedo[c];
    const double d = meanFreePathMm[c] / (1.85 - a + 7.0 * std::pow(std::abs(a - 0.8), 3.0));
    return test::burleyEdgeResponse(xMm, d * scale);
}

class DiskSssEdge : public test::RenderFixture {
protected:
    DiskEdge renderEdge(const std::string& profile, const std::vector<std::string>& overrides) {
        const bool soft = profile == "soft";
        const std::string path = test::writeEdgeScene(mDir, profile, soft ? kSoftJson : "");
        std::vector<std::string> all = {"sss.technique=disk"};
        all.insert(all.end(), overrides.begin(), overrides.end());
        load(path, all);
        const Image irradiance = render(Aov::Irradiance, kWidth, kHeight);
        const Image diffuse = render(Aov::Diffuse, kWidth, kHeight);
        const PassSummary* disk = pass("sss " + profile + " disk");
        EXPECT_TRUE(disk && disk->executed) << "the disk pass did not run";
        // Skin's widest Gaussian is 2.72 mm (3 sigma: 8 mm); the soft profile's red d is
        // 0.95 mm, 3d = 2.9 mm, and 8 mm holds all but 5% of its light.
        return compareDiskEdge(irradiance, diffuse, soft ? softEdgeResponse : skinEdgeResponse, 8.0);
    }
    test::TempDir mDir;
};

void printEdge(const std::string& what, const DiskEdge& e) {
    std::printf("[ measured ] edge %-28s row-mean max error %.4f of the step; fitted width scale %.4f %.4f %.4f; "
                "per-pixel noise (RMS std dev) %.4f of the step\n",
                what.c_str(), e.maxError, e.widthScale.r, e.widthScale.g, e.widthScale.b, e.noise);
}

// Bounds, at 40 samples (the default) and more: the row mean within 1% of the step, and the fitted
// width within 2% of 1 per channel. Measured (max error; fitted widths R G B; per-pixel noise):
//   skin  40: 0.0082; 0.9875 0.9975 0.9950; 0.0145     128: 0.0029; 1.0000 1.0000 1.0000; 0.0061
//   soft  40: 0.0087; 0.9950 0.9975 0.9975; 0.0207     128: 0.0028; 0.9975 1.0000 1.0000; 0.0081
// The row mean averages 180 rotations of the spiral, so what is left is the radial quadrature's
// bias (stratified radii, fixed for every pixel), which falls with N: at 16 samples it is 1.85%
// (skin) and 2.5% (soft), with red fitted 4% and 2.75% narrow, so 16 is not held to these bounds.
// Broken on purpose: the widths x0.95 and x1.05 (the next test) fit 0.945-0.950 and 1.045-1.050,
// with row-mean errors 1.32% and 1.25%; every channel weighted by red's weights (DiskSss.glsl
// reading weights[j].rrr) gave row-mean errors of 23% and green and blue at the end of the fitted
// range (1.10) for both profiles and every sample count.
constexpr double kEdgeMaxError = 0.01;
constexpr double kEdgeWidthTolerance = 0.02;

}  // namespace

TEST_F(DiskSssEdge, SkinAndBurleyMatchTheirExactEdgeResponses) {
    for (const char* profile : {"skin", "soft"}) {
        for (int samples : {40, 128}) {
            const DiskEdge e = renderEdge(profile, {"sss.disk_samples=" + std::to_string(samples)});
            printEdge(std::string(profile) + ", " + std::to_string(samples) + " samples", e);
            EXPECT_LT(e.maxError, kEdgeMaxError) << profile << " " << samples;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(e.widthScale[c], 1.0, kEdgeWidthTolerance) << profile << " " << samples << " channel " << c;
        }
    }
}

TEST_F(DiskSssEdge, ComparisonFailsWhenEveryWidthIsFivePercentOff) {
    for (const char* scale : {"0.95", "1.05"}) {
        const DiskEdge e = renderEdge("soft", {std::string("sss.width_scale=") + scale});
        printEdge(std::string("soft, width scale ") + scale, e);
        bool widths = true;
        for (int c = 0; c < 3; ++c) widths = widths && std::abs(e.widthScale[c] - 1.0) < kEdgeWidthTolerance;
        EXPECT_FALSE(widths && e.maxError < kEdgeMaxError) << "width scale " << scale << " passed the edge comparison";
    }
}

// The same image every render and every renderer: the rotation is a hash of the pixel.
TEST_F(DiskSss, SameImageEveryRender) {
    load("default.json", {"sss.technique=disk"});
    const Image first = render(Aov::Final, kWidth, kHeight);
    const Image second = render(Aov::Final, kWidth, kHeight);
    load("default.json", {"sss.technique=disk"});
    const Image third = render(Aov::Final, kWidth, kHeight);
    ASSERT_EQ(first.texels.size(), second.texels.size());
    EXPECT_EQ(std::memcmp(first.texels.data(), second.texels.data(), first.texels.size() * sizeof(glm::vec4)), 0);
    EXPECT_EQ(std::memcmp(first.texels.data(), third.texels.data(), first.texels.size() * sizeof(glm::vec4)), 0);
}

// LEAN lbb with the disk: the moments go through the disk's samples with one scalar weight
// (DiskSss.glsl, EXTRA TARGETS AND ALPHA). The diffuse and specular AOVs stay finite and
// non-negative and close to the d'Eon chain's (the same profile, sampled instead of blurred).
// Measured at 320x180, relative L1 against the chain: diffuse 0.21%; specular 2.6% at 40 samples
// (6.2% at 8, 1.9% at 128: the moments' noise shows in the highlights), while switching LEAN off
// altogether (variant c) moves the specular by 9.5%. Bounds: diffuse 2%, specular 5%, half of what
// dropping the moments' blur costs.
TEST_F(DiskSss, LeanLbbRunsWithTheDisk) {
    auto relativeL1 = [](const Image& a, const Image& b) {
        double difference = 0.0, sum = 0.0;
        for (size_t i = 0; i < a.texels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                difference += std::abs(double(a.texels[i][c]) - double(b.texels[i][c]));
                sum += std::abs(double(b.texels[i][c]));
            }
        return difference / sum;
    };
    for (Aov aov : {Aov::Diffuse, Aov::Specular}) {
        load("default.json", {"sss.variant=lbb", "sss.technique=disk"});
        const Image disk = render(aov, kWidth, kHeight);
        const PassSummary* pass = this->pass("sss skin disk");
        EXPECT_TRUE(pass && pass->executed);
        load("default.json", {"sss.variant=lbb"});
        const Image chain = render(aov, kWidth, kHeight);
        ASSERT_EQ(test::countNonFinite(disk), 0u);
        float lowest = 0.0f;
        for (const glm::vec4& t : disk.texels) lowest = std::min({lowest, t.r, t.g, t.b});
        EXPECT_GE(lowest, 0.0f);
        const double l1 = relativeL1(disk, chain);
        std::printf("[ measured ] lbb, %s: disk vs d'Eon chain relative L1 %.4f\n", aov == Aov::Diffuse ? "diffuse" : "specular", l1);
        EXPECT_LT(l1, aov == Aov::Diffuse ? 0.02 : 0.05);
    }
}
