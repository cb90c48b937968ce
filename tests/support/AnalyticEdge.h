#pragma once
// The analytic-edge set-up shared by the screen-space and texture-space render
// tests: a 40 mm skin plane seen straight down from kEdgeHeightM, its albedo a
// hard black|white step at x = 0. With mix = 1 all albedo is applied before
// the blur, so the blur's input is exactly a step in irradiance (Chappuis 2011
// §2.2.4) and the diffuse AOV is the blurred step, whose closed form is
// sum_i w_i Phi(x / sqrt(v_i)) (DiffusionProfile::edgeResponse).

#include "TestSupport.h"

#include "core/Image.h"

#include <glm/glm.hpp>

#include <string>

namespace dermis {
class DiffusionProfile;
}

namespace dermis::test {

constexpr double kEdgeFovDeg = 30.0;
constexpr double kEdgeHeightM = 0.0336;

// Writes step.png and edge.json into `dir`; returns the scene's path. The
// plane's material uses `profile`; `profilesJson`, when given, is the
// scene's "profiles" object (user profiles).
std::string writeEdgeScene(const TempDir& dir, const std::string& profile = "skin",
                           const std::string& profilesJson = "");

struct EdgeError {
    double max = 0.0;  // largest |rendered - closed form| of any channel, as a fraction of the unit step
    double rms = 0.0;
};

// The Bickley-Naylor function Ki_1(x) = integral over t in [0, inf) of exp(-x cosh t) / cosh t
// (Abramowitz & Stegun 1964, 11.2.17; x >= 0).
double bickleyKi1(double x);

// Burley's normalized diffusion's edge response (docs/reference.md) at x mm for shape distance
// d mm, in closed form. A point at distance a on the dark side receives the light of each ring of
// radius r > a in proportion to the angle 2 acos(a / r) that lies in the lit half:
// dark(a) = integral over r > a of R(r) 2 r acos(a / r) dr. For each of the profile's two terms
// e^(-r/l) / (8 pi d r) (l = d, 3d), integrating by parts and setting r = a cosh t leaves
// (l / (4 pi d)) Ki_1(a / l), so dark(a) = (Ki_1(a/d) + 3 Ki_1(a/3d)) / (4 pi); at a = 0,
// Ki_1(0) = pi/2 gives 1/2.
double burleyEdgeResponse(double xMm, double shapeDistanceMm);

// The diffuse AOV's middle row against the profile's edge response (skin when null).
EdgeError edgeError(const Image& diffuse, int width, int height, const DiffusionProfile* profile = nullptr);

// The diffuse AOV's middle row against the exact diffusion of the rendered
// irradiance row (each texel a box, the profile's marginal across the row;
// independent of any shader), for the edge scene at any size. Used by the
// d'Eon chain's and Separable SSS's edge tests.
struct EdgeComparison {
    double maxError = 0.0;      // largest |rendered - exact| of any channel, a fraction of that channel's step
    double rms = 0.0;           // over the pixels within 3 widest sigmas of the step
    glm::dvec3 widthScale{0.0};  // per channel: the profile width scale in [0.85, 1.15] whose exact diffusion fits best
    double irradianceOffStep = 0.0;  // largest departure of the irradiance row from a step, 2 px from it
};
EdgeComparison compareEdge(const Image& irradiance, const Image& diffuse, const DiffusionProfile* profile = nullptr);
// One line: the comparison's figures, labelled `what`.
void printEdge(const char* what, const EdgeComparison& e);

}  // namespace dermis::test
