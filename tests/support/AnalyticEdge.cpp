#include "AnalyticEdge.h"

#include "Quadrature.h"

#include "sss/BurleyProfile.h"
#include "sss/DiffusionProfile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

double burleyEdgeResponse(double xMm, double shapeDistanceMm, int intervals) {
    if (xMm == 0.0) return 0.5;
    const double a = std::fabs(xMm);
    const double dMm = shapeDistanceMm;
    const double dark = quadrature::simpson([&](double t) {
        const double r = a * std::cosh(t);
        return 2.0 * M_PI * r * burleyRadialProfile(r, dMm) * std::acos(1.0 / std::cosh(t)) / M_PI * a * std::sinh(t);
    }, 0.0, std::acosh(std::fmax(200.0 * dMm / a, 1.0)), intervals);
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

}  // namespace dermis::test
