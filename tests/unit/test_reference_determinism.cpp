// The reference's image depends on the scene, the density and the samples per
// pixel only: not on the thread count (the sub-samples' jitter is a hash of the
// pixel, results are written per sub-sample).
#include "ReferenceTestScenes.h"

#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

using namespace dermis;
using namespace dermis::test;

namespace {

Image renderWithThreads(int threads) {
    reference::ReferenceOptions options;
    options.quadrature.density = 2.0f;  // the check needs no accuracy
    options.threads = threads;
    options.samplesPerPixel = 4;  // jittered sub-samples
    auto renderer = reference::ReferenceRenderer::create(sphereScene(), sphereSceneModels(true), options);
    EXPECT_TRUE(renderer.ok());
    return renderer->renderDiffuse(20, 15);
}

}  // namespace

TEST(ReferenceDeterminism, OneAndTwoThreadsGiveIdenticalImages) {
    const Image one = renderWithThreads(1);
    const Image two = renderWithThreads(2);
    ASSERT_EQ(one.texels.size(), two.texels.size());
    size_t covered = 0;
    for (size_t i = 0; i < one.texels.size(); ++i) {
        ASSERT_EQ(one.texels[i], two.texels[i]) << "pixel " << i;  // bit for bit
        covered += one.texels[i].a > 0.0f;
    }
    EXPECT_GT(covered, 30u);  // the sphere is in view
}
