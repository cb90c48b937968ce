// Convergence of the CPU reference on the procedural sphere (radius 0.1 m,
// skin profile, a spot light and a card's hard shadow across it): the error
// against the densest run falls as the sample density rises. Prints the table
// (density, time, relative RMSE) that docs/reference.md quotes.
// Labelled `slow` (tests/CMakeLists.txt): it renders the sphere six times.
#include "ReferenceTestScenes.h"

#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr int kWidth = 40;
constexpr int kHeight = 30;

Image renderAt(float density, double* seconds) {
    reference::ReferenceOptions options;
    options.quadrature.density = density;
    options.samplesPerPixel = 1;  // the quadrature's convergence alone (test_reference_pixels.cpp: the sub-samples')
    auto renderer = reference::ReferenceRenderer::create(sphereScene(), sphereSceneModels(false), options);
    EXPECT_TRUE(renderer.ok());
    const auto start = std::chrono::steady_clock::now();
    Image image = renderer->renderDiffuse(kWidth, kHeight);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

// Relative RMSE over the pixels both images cover: sqrt(sum d^2 / sum ref^2), RGB.
double relativeRmse(const Image& reference, const Image& test) {
    double squaredError = 0.0, squaredReference = 0.0;
    for (size_t i = 0; i < reference.texels.size(); ++i) {
        if (reference.texels[i].a == 0.0f || test.texels[i].a == 0.0f) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(test.texels[i][c]) - double(reference.texels[i][c]);
            squaredError += d * d;
            squaredReference += double(reference.texels[i][c]) * double(reference.texels[i][c]);
        }
    }
    return std::sqrt(squaredError / squaredReference);
}

}  // namespace

// ctest: slow
TEST(ReferenceConvergence, ErrorFallsWithDensityOnTheSphere) {
    const float densities[] = {1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
    const float densest = 64.0f;
    double seconds = 0.0;
    const Image best = renderAt(densest, &seconds);
    std::printf("sphere %dx%d, error against density %.0f (%.2f s):\n", kWidth, kHeight, densest, seconds);
    std::printf("| density (samples per s^2) | time (s) | relative RMSE |\n|---|---|---|\n");
    double previous = INFINITY;
    for (float density : densities) {
        const Image image = renderAt(density, &seconds);
        const double error = relativeRmse(best, image);
        std::printf("| %g | %.2f | %.5f |\n", double(density), seconds, error);
        EXPECT_LT(error, previous) << "density " << density;
        previous = error;
        if (density == 8.0f) {
            EXPECT_LT(error, 0.005) << "the default density";
        }
    }
}
