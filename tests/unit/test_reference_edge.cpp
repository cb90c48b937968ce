// The CPU reference against the analytic edge (docs/reference.md): a plane
// lit from straight above, half of it in the exact shadow of a blocker, must
// respond across the shadow's edge as sum_i w_i Phi(x / sqrt(v_i)) per channel.
#include "ReferenceTestScenes.h"

#include "reference/ReferenceRenderer.h"
#include "sss/DiffusionProfile.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;
using namespace dermis::test;

namespace {

// The edge runs at a generic angle through a generic point, so that it lines
// up with nothing in the plane's tessellation.
constexpr float kEdgeAngleRad = 0.3f;
const glm::vec3 kEdgePointM(0.0123f, 0.0f, -0.0071f);

struct EdgeScene {
    Scene scene;
    glm::vec3 across;  // unit, in the plane, pointing from shadow to light
    glm::vec3 along;
};

EdgeScene makeEdgeScene() {
    EdgeScene edge;
    edge.along = glm::vec3(std::sin(kEdgeAngleRad), 0.0f, std::cos(kEdgeAngleRad));
    edge.across = glm::vec3(edge.along.z, 0.0f, -edge.along.x);
    edge.scene = bareScene();
    edge.scene.lights.push_back(sunFromAbove());
    edge.scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    edge.scene.characters.push_back(proceduralCharacter("blocker", "", "none"));
    return edge;
}

// The blocker: a big quad 5 cm above the plane over the shadowed side.
Model blockerModel(const EdgeScene& edge) {
    const glm::vec3 lift(0.0f, 0.05f, 0.0f);
    const glm::vec3 o = kEdgePointM + lift;
    const glm::vec3 a = o - edge.along * 0.6f;
    const glm::vec3 b = o + edge.along * 0.6f;
    const glm::vec3 c = b - edge.across * 0.6f;
    const glm::vec3 d = a - edge.across * 0.6f;
    return quadModel(a, d, c, b);
}

}  // namespace

TEST(ReferenceEdge, MatchesTheAnalyticEdgeResponse) {
    const EdgeScene edge = makeEdgeScene();
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    models.push_back(blockerModel(edge));
    reference::ReferenceOptions options;
    auto renderer = reference::ReferenceRenderer::create(edge.scene, std::move(models), options);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();

    const float xsMm[] = {-3.0f, -1.0f, -0.4f, -0.15f, -0.05f, 0.0f, 0.03f, 0.1f, 0.25f, 0.6f, 1.5f, 4.0f};
    std::vector<raytrace::Ray> rays;
    for (float xMm : xsMm) {
        // Two points per distance, along the edge, to meet the tessellation at different phases.
        for (float alongMm : {0.0f, 7.3f}) {
            const glm::vec3 p = kEdgePointM + edge.across * (xMm * 1e-3f) + edge.along * (alongMm * 1e-3f);
            rays.push_back(downAt(p.x, p.z));
        }
    }
    const std::vector<glm::vec4> values = renderer->diffuseAlongRays(rays, 0.0f, 0.02f);
    const DiffusionProfile& profile = skinProfile();
    float worst = 0.0f;
    for (size_t i = 0; i < rays.size(); ++i) {
        const float xMm = xsMm[i / 2];
        const glm::vec3 expected = profile.edgeResponse(xMm);
        for (int c = 0; c < 3; ++c) {
            const float error = std::fabs(values[i][c] - expected[c]);
            worst = std::max(worst, error);
            EXPECT_LT(error, 0.005f) << "x = " << xMm << " mm, channel " << c << ": reference " << values[i][c]
                                     << ", analytic " << expected[c];
        }
        EXPECT_EQ(values[i].a, 1.0f);
    }
    std::printf("edge: largest difference from sum w_i Phi(x / sqrt v_i): %.5f of the step\n", worst);
}
