#include "AnalyticEdge.h"

#include "sss/BurleyProfile.h"
#include "sss/DiffusionProfile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace dermis::test {

std::string writeEdgeScene(const TempDir& dir, const std::string& profile, const std::string& profilesJson) {
    Image step;
    step.width = 4096;
    step.height = 4;
    step.colourSpace = ColourSpace::Linear;
    for (int y = 0; y < step.height; ++y) {
        for (int x = 0; x < step.width; ++x) {
            const float v = x < step.width / 2 ? 0.0f : 1.0f;
            step.texels.push_back(glm::vec4(v, v, v, 1.0f));
        }
    }
    EXPECT_TRUE(saveImage(dir.file("step.png"), step).ok());
    char json[4096];
    std::snprintf(json, sizeof json, R"({
      "camera": {"position_m": [0, %.6f, 0], "target_m": [0, 0, 0], "up": [0, 0, -1],
                 "vertical_fov_deg": %.1f, "near_m": 0.005, "far_m": 1},
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1, "shadow": false}],
      "characters": [{"name": "step", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.04},
                      "material": {"albedo": [1, 1, 1], "albedo_map": "step.png", "rho_s": 0, "profile": "%s"}}],%s%s
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "energy_conservation": false, "ssao": {"enabled": false},
                   "transmittance": {"enabled": false}, "sss": {"mix": 1}}
    })",
                  kEdgeHeightM, kEdgeFovDeg, profile.c_str(), profilesJson.empty() ? "" : "\n      \"profiles\": ",
                  profilesJson.empty() ? "" : (profilesJson + ",").c_str());
    writeTextFile(dir.file("edge.json"), json);
    return dir.file("edge.json");
}

double bickleyKi1(double x) {
    // Trapezoid rule on [0, inf): the integrand is even and analytic in the strip |Im t| < pi/2
    // (the poles of 1/cosh), so the error falls like exp(-pi^2 / h) (Trefethen & Weideman 2014,
    // Theorem 5.1): about 1e-43 at h = 0.1, far below double rounding.
    constexpr double h = 0.1;
    double sum = 0.5 * std::exp(-x);
    for (int k = 1;; ++k) {
        const double c = std::cosh(k * h);
        const double term = std::exp(-x * c) / c;
        sum += term;
        if (term < 1e-17 * sum) break;
    }
    return h * sum;
}

double burleyEdgeResponse(double xMm, double shapeDistanceMm) {
    const double a = std::fabs(xMm);
    const double d = shapeDistanceMm;
    const double dark = (bickleyKi1(a / d) + 3.0 * bickleyKi1(a / (3.0 * d))) / (4.0 * M_PI);
    return xMm < 0.0 ? dark : 1.0 - dark;
}

EdgeError edgeError(const Image& diffuse, int width, int height, const DiffusionProfile* profile) {
    const DiffusionProfile& skin = profile ? *profile : skinProfile();
    const double mmPerPixel = 2.0 * kEdgeHeightM * 1000.0 * std::tan(kEdgeFovDeg * M_PI / 360.0) / height;
    EdgeError e;
    double sumSquares = 0.0;
    int samples = 0;
    const int row = height / 2;
    for (int x = 0; x < width; ++x) {
        const double xMm = (x + 0.5 - width / 2.0) * mmPerPixel;
        const glm::vec3 expected = skin.edgeResponse(static_cast<float>(xMm));
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(double(diffuse.at(x, row)[c]) - expected[c]);
            e.max = std::max(e.max, error);
            sumSquares += error * error;
            ++samples;
        }
    }
    e.rms = std::sqrt(sumSquares / samples);
    return e;
}

namespace {

double edgeMmPerPixel(int height) {
    return 2.0 * kEdgeHeightM * 1000.0 * std::tan(kEdgeFovDeg * M_PI / 360.0) / height;
}

// The exact diffusion of the rendered irradiance row: each texel a box, the
// profile's marginal across the row sum_i w_i N(0, v_i s^2) (the row is
// uniform in y, so the 2-D integral is this 1-D one), evaluated at the pixel
// centres. An independent computation: it shares nothing with the shader.
double exactDiffusion(const Image& irradiance, const DiffusionProfile& profile, int row, int x, int c, double mmPerPixel,
                      double widthScale) {
    // Sum over texels j of I_j x (the marginal's mass over texel j), written as the left border
    // texel plus each jump I_j - I_(j-1) times the mass beyond the boundary between them, so only
    // the few texels where the row changes cost anything. The border texels stand for everything
    // beyond the frame (the shader clamps its taps there).
    double sum = irradiance.at(0, row)[c];
    for (int j = 1; j < irradiance.width; ++j) {
        const double jump = double(irradiance.at(j, row)[c]) - double(irradiance.at(j - 1, row)[c]);
        if (jump == 0.0) continue;
        const double boundaryMm = (j - 0.5 - x) * mmPerPixel;
        double beyond = 0.0;
        for (const ProfileGaussian& g : profile.gaussians()) {
            const double sigma = std::sqrt(double(g.varianceMm2)) * widthScale;
            beyond += g.weight[c] * 0.5 * std::erfc(boundaryMm / (sigma * M_SQRT2));
        }
        sum += jump * beyond;
    }
    return sum;
}

}  // namespace

EdgeComparison compareEdge(const Image& irradiance, const Image& diffuse, const DiffusionProfile* profile) {
    const DiffusionProfile& exact = profile ? *profile : skinProfile();
    const int width = irradiance.width;
    const double mmPerPixel = edgeMmPerPixel(irradiance.height);
    const int row = irradiance.height / 2;
    const double reachMm = 3.0 * exact.largestStdDevMm();
    EdgeComparison e;
    double sumSquares = 0.0;
    int samples = 0;
    for (int c = 0; c < 3; ++c) {
        const double low = irradiance.at(0, row)[c];
        const double high = irradiance.at(width - 1, row)[c];
        const double step = high - low;
        // Beyond the two texels either side of the step (which the albedo map's filtering mixes).
        for (int x = 0; x < width; ++x) {
            if (std::abs(x + 0.5 - width / 2.0) < 2.0) continue;
            const double ideal = x < width / 2 ? low : high;
            e.irradianceOffStep = std::max(e.irradianceOffStep, std::abs(irradiance.at(x, row)[c] - ideal) / step);
        }
        // Width-scale fit: the scale in [0.85, 1.15] (steps of 0.001) whose exact diffusion is
        // nearest (least squares) to the rendered row, over the pixels the widest Gaussian reaches.
        double bestScale = 0.0;
        double bestCost = 1e300;
        std::vector<int> pixels;
        for (int x = 0; x < width; ++x) {
            if (std::abs((x + 0.5 - width / 2.0) * mmPerPixel) < reachMm) pixels.push_back(x);
        }
        for (int k = -150; k <= 150; ++k) {
            const double scale = 1.0 + 0.001 * k;
            double cost = 0.0;
            for (int x : pixels) {
                const double d = diffuse.at(x, row)[c] - exactDiffusion(irradiance, exact, row, x, c, mmPerPixel, scale);
                cost += d * d;
            }
            if (cost < bestCost) {
                bestCost = cost;
                bestScale = scale;
            }
        }
        e.widthScale[c] = bestScale;
        for (int x = 0; x < width; ++x) {
            const double error =
                std::abs(diffuse.at(x, row)[c] - exactDiffusion(irradiance, exact, row, x, c, mmPerPixel, 1.0)) / step;
            e.maxError = std::max(e.maxError, error);
            if (std::abs((x + 0.5 - width / 2.0) * mmPerPixel) < reachMm) {
                sumSquares += error * error;
                ++samples;
            }
        }
    }
    e.rms = std::sqrt(sumSquares / samples);
    return e;
}

void printEdge(const char* what, const EdgeComparison& e) {
    std::printf("edge %-22s max error %.4f, RMS %.4f of the step; fitted width scale %.3f %.3f %.3f; "
                "irradiance off its step by %.4f\n",
                what, e.maxError, e.rms, e.widthScale.r, e.widthScale.g, e.widthScale.b, e.irradianceOffStep);
}

}  // namespace dermis::test
