// The engine's shadows of lights with a size (docs/shadows.md): the PCSS
// penumbra of a straight edge on a flat plane against the disc-segment closed
// form (support/PenumbraEdge.h) for a 5-degree directional light and spot and
// point lights of a 20 mm radius (a point light through its cube map), and a
// delta light's edge as sharp as the map allows.
#include "PenumbraEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct EdgeLight {
    std::string json;       // the light's JSON object
    glm::dvec2 positionXY;  // spot and point: (x, height); directional: unused
    double radiusM = 0.0;   // spot and point
    double angularDiameterDeg = -1.0;  // directional: its size; < 0 for spot and point
    double cameraXM = 0.0;  // the camera looks straight down at the geometric shadow edge
};

// A directional light travelling along (1, -1, 0): the centre of its shadow edge falls at x = 0.
EdgeLight directional(double diameterDeg) {
    EdgeLight l;
    l.json = R"({"type": "directional", "direction": [1, -1, 0], "intensity": 1, "angular_diameter_deg": )" +
             std::to_string(diameterDeg) + "}";
    l.angularDiameterDeg = diameterDeg;
    l.cameraXM = kEdgeBlockerXM + kEdgeBlockerHeightM;
    return l;
}

// A spot or point light at (-0.15, 0.25): the ray over the edge lands at x = -0.025.
EdgeLight lamp(const std::string& type, double radiusM) {
    EdgeLight l;
    l.positionXY = {-0.15, 0.25};
    l.json = R"({"type": ")" + type + R"(", "position_m": [-0.15, 0.25, 0], "direction": [0.5, -1, 0], "intensity": 0.05,
                 "spot_inner_deg": 35, "spot_outer_deg": 40, "radius_m": )" + std::to_string(radiusM) + "}";
    l.radiusM = radiusM;
    l.cameraXM = kEdgeBlockerXM + (kEdgeBlockerXM - l.positionXY.x) * kEdgeBlockerHeightM / (l.positionXY.y - kEdgeBlockerHeightM);
    return l;
}

std::string writeScene(const TempDir& dir, const EdgeLight& light) {
    const std::string cx = std::to_string(light.cameraXM);
    writeTextFile(dir.file("penumbra.json"), R"({
      "camera": {"position_m": [)" + cx + R"(, 0.15, 0], "target_m": [)" + cx + R"(, 0, 0], "up": [0, 0, -1],
                 "vertical_fov_deg": 30, "near_m": 0.01, "far_m": 2},
      "lights": [)" + light.json + R"(],
      "characters": [
        {"name": "floor", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.3},
         "material": {"albedo": [1, 1, 1], "profile": "none"}},
        {"name": "blocker", "mesh": {"procedural": "plane"}, "transform": {"translation_m": [-0.15, 0.05, 0], "scale": 0.2},
         "material": {"albedo": [1, 1, 1], "profile": "none"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "energy_conservation": false, "ssao": {"enabled": false},
                   "transmittance": {"enabled": false}, "shadow": {"map_size": 2048}}
    })");
    return dir.file("penumbra.json");
}

// World x of column `column`'s centre on the floor.
double floorX(const EdgeLight& light, int column) {
    const double metresPerPixel = 2.0 * kEdgeCameraHeightM * std::tan(0.5 * kEdgeFovDeg * kPi / 180.0) / kEdgeHeight;
    return light.cameraXM + (column + 0.5 - 0.5 * kEdgeWidth) * metresPerPixel;
}

// The closed-form visibility at floor x: the light's disc of angular radius
// alpha cut by the plane through the point and the blocker's edge, at angle
// delta = theta_edge - theta_light in the x-y plane (support/PenumbraEdge.h).
double closedForm(const EdgeLight& light, double x) {
    const double thetaEdge = std::atan2(kEdgeBlockerHeightM, kEdgeBlockerXM - x);
    double thetaLight = 0.75 * kPi;  // towards (-1, 1)
    double sinRadius = std::sin(0.5 * light.angularDiameterDeg * kPi / 180.0);
    if (light.angularDiameterDeg < 0.0) {
        const glm::dvec2 toLight = light.positionXY - glm::dvec2(x, 0.0);
        thetaLight = std::atan2(toLight.y, toLight.x);
        sinRadius = light.radiusM / glm::length(toLight);
    }
    return discSegmentVisibility(std::sin(thetaEdge - thetaLight) / sinRadius);
}

struct Profiles {
    std::vector<double> xsM, measured, closedForm;
};

class Shadows : public RenderFixture {
protected:
    // The diffuse AOV's middle rows (averaged) over the lit level, and the closed form, per column.
    Profiles measure(const EdgeLight& light, const std::vector<std::string>& overrides = {}) {
        TempDir dir;
        load(writeScene(dir, light), overrides);
        const Image image = render(Aov::Diffuse, kEdgeWidth, kEdgeHeight);
        Profiles p;
        if (image.empty()) return p;
        std::vector<double> row(kEdgeWidth, 0.0);
        const int rows = 20;
        for (int y = kEdgeHeight / 2 - rows / 2; y < kEdgeHeight / 2 + rows / 2; ++y) {
            for (int x = 0; x < kEdgeWidth; ++x) row[x] += image.at(x, y).g / rows;
        }
        // The unshadowed light: constant for the sun; N.L / d^2 = height / d^3
        // for spot and point lights (inside the spot's inner cone here).
        auto unshadowed = [&](double x) {
            if (light.angularDiameterDeg >= 0.0) return 1.0;
            const double d = glm::length(light.positionXY - glm::dvec2(x, 0.0));
            return light.positionXY.y / (d * d * d);
        };
        // The lit level: the right tenth of the frame, over 1 cm from the edge.
        double lit = 0.0;
        for (int x = kEdgeWidth * 9 / 10; x < kEdgeWidth; ++x) {
            lit += row[x] / unshadowed(floorX(light, x)) / (kEdgeWidth - kEdgeWidth * 9 / 10);
        }
        // Only the floor within 12 mm of the geometric edge: further left the
        // camera sees the blocker's lit top.
        for (int x = 0; x < kEdgeWidth; ++x) {
            if (std::fabs(floorX(light, x) - light.cameraXM) > 0.012) continue;
            p.xsM.push_back(floorX(light, x));
            p.measured.push_back(row[x] / (lit * unshadowed(p.xsM.back())));
            p.closedForm.push_back(closedForm(light, p.xsM.back()));
        }
        return p;
    }
};

// Bounds: the 10-90 width within 8% of the closed form's. The map's texels
// (0.25 mm for the sun, up to 0.5 mm on a cube face, against 6-8 mm widths),
// 64 fixed taps and PCSS's mean blocker depth move it by a few percent
// (measured: 2.8-3.3% wide); scaling the PCSS kernel by 1.2 or 1/1.2 in
// include/Shadows.glsl gave ratios 1.21-1.25 and 0.84-0.86, which fail. The
// 50% crossing within 0.5 mm of the geometric edge, about two texels of bias
// and quantisation (measured within 0.08 mm; reading the wrong cube-atlas
// cells fails it).
void expectPenumbra(const std::vector<double>& xs, const std::vector<double>& measured,
                    const std::vector<double>& closedForm, const char* what) {
    const double width = width10To90(xs, measured);
    const double expected = width10To90(xs, closedForm);
    const double centre = firstCrossing(xs, measured, 0.5);
    const double expectedCentre = firstCrossing(xs, closedForm, 0.5);
    std::printf("%s: 10-90 width %.3f mm, closed form %.3f mm (ratio %.4f); 50%% at %.3f mm, closed form %.3f mm\n",
                what, width * 1e3, expected * 1e3, width / expected, centre * 1e3, expectedCentre * 1e3);
    EXPECT_NEAR(width / expected, 1.0, 0.08) << what;
    EXPECT_NEAR(centre, expectedCentre, 0.0005) << what;
}

}  // namespace

TEST_F(Shadows, FiveDegreeSunPenumbraMatchesTheClosedForm) {
    const EdgeLight light = directional(5.0);
    const auto p = measure(light, {"sss.enabled=false"});
    ASSERT_FALSE(p.xsM.empty());
    expectPenumbra(p.xsM, p.measured, p.closedForm, "5-degree sun");
}

TEST_F(Shadows, SpotAndPointSpherePenumbraMatchesTheClosedForm) {
    for (const char* type : {"spot", "point"}) {
        const EdgeLight light = lamp(type, 0.02);
        const auto p = measure(light, {"sss.enabled=false"});
        ASSERT_FALSE(p.xsM.empty());
        expectPenumbra(p.xsM, p.measured, p.closedForm, type);
        if (std::string(type) == "point") EXPECT_NE(pass("shadow:light0(point)"), nullptr);
    }
}

// A delta light's exact shadow is a step. pcss gives it bilinear PCF, a ramp
// one map texel wide (0.25 mm here, 0.35 mm across the floor at 45 degrees,
// under a pixel of 0.45 mm); pcf4x4's box of 4x4 taps is four texels wide.
// Bound: the pcss edge's 10-90 width at most half of pcf4x4's (measured
// ratio in the comment's output); pcf4x4's path for a delta light, as before,
// gives 1 and fails. Both 50% crossings within 0.5 mm of the geometric edge
// (x = 0), as for the lights with a size.
TEST_F(Shadows, DeltaLightEdgeIsAsSharpAsTheMapAllows) {
    const EdgeLight light = directional(0.0);
    const auto pcss = measure(light, {"sss.enabled=false", "shadow.filter=pcss"});
    const auto pcf = measure(light, {"sss.enabled=false", "shadow.filter=pcf4x4"});
    ASSERT_FALSE(pcss.xsM.empty());
    ASSERT_EQ(pcss.xsM.size(), pcf.xsM.size());
    const double sharp = width10To90(pcss.xsM, pcss.measured);
    const double box = width10To90(pcf.xsM, pcf.measured);
    std::printf("delta sun: 10-90 width pcss %.3f mm, pcf4x4 %.3f mm (ratio %.3f); 50%% at %.3f and %.3f mm\n",
                sharp * 1e3, box * 1e3, sharp / box, firstCrossing(pcss.xsM, pcss.measured, 0.5) * 1e3,
                firstCrossing(pcf.xsM, pcf.measured, 0.5) * 1e3);
    EXPECT_GT(box, 0.0);
    EXPECT_LT(sharp, 0.5 * box);
    EXPECT_NEAR(firstCrossing(pcss.xsM, pcss.measured, 0.5), 0.0, 0.0005);
    EXPECT_NEAR(firstCrossing(pcf.xsM, pcf.measured, 0.5), 0.0, 0.0005);
}
