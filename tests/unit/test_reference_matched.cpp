// The matched-irradiance mode (docs/reference.md): with an engine texture made
// here from the exact lighting, "diffuse with SSS off + Delta" must equal the
// diffuse with SSS on up to the texture's resolution; a uniform texture on a
// flat plane gives Delta = 0 (furnace); a texture shifted by three texels or a
// profile 5 % wider must break the agreement (checked here, so the bound is
// known to be tight enough to see them).
#include "ReferenceTestScenes.h"

#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr float kPlaneScale = 0.04f;  // the procedural plane shrunk to 4 cm, so that texels are 0.08 mm
constexpr int kTexels = 512;
const glm::vec3 kAlbedo(0.8f, 0.6f, 0.5f);
constexpr float kMix = 0.5f;

// A spot 2 cm above the plane's centre: its cone's edge (25 to 30 degrees) is a
// smooth ring 9.3 to 11.5 mm from the centre, where the scattering changes the
// light most. No shadow rays, so both sources give the integrator the same cells.
Scene spotOnSmallPlane(bool sssEnabled, float widthScale) {
    Scene scene = bareScene();
    scene.settings.sss.mix = kMix;
    scene.settings.sss.enabled = sssEnabled;
    scene.settings.sss.widthScale = widthScale;
    scene.settings.ambient = glm::vec3(0.05f);
    Light spot;
    spot.type = LightType::Spot;
    spot.positionM = glm::vec3(0.0f, 0.02f, 0.0f);
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.intensity = 4e-4f;  // about 1 at the centre (1/r^2 with r = 2 cm)
    spot.spotInnerDeg = 25.0f;
    spot.spotOuterDeg = 30.0f;
    spot.castsShadow = false;
    scene.lights.push_back(spot);
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    scene.characters[0].transform.scale = kPlaneScale;
    scene.characters[0].material.albedo = kAlbedo;
    return scene;
}

std::vector<Model> planeModels() {
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    return models;
}

// The integrand E x albedo^mix at raw UV (u, v) of the plane, from the exact
// lighting: the plane maps (u, v) to ((u - 0.5), 0, (v - 0.5)) x scale.
glm::vec3 exactIntegrand(const reference::ReferenceLighting& lighting, float u, float v) {
    reference::SurfacePoint point;
    point.positionM = kPlaneScale * glm::vec3(u - 0.5f, 0.0f, v - 0.5f);
    point.geometricNormal = point.shadingNormal = glm::vec3(0.0f, 1.0f, 0.0f);
    point.albedo = kAlbedo;
    return lighting.irradiance(point) * glm::sqrt(kAlbedo);
}

// The engine's texture as ts_irradiance.frag lays it out: row y at v = (y + 0.5) / H.
Image textureFromExactLighting(const Scene& scene, int shiftTexels) {
    const raytrace::Bvh none = raytrace::Bvh::build({});
    const reference::ReferenceLighting lighting(scene, none);
    Image image;
    image.width = image.height = kTexels;
    for (int y = 0; y < kTexels; ++y) {
        for (int x = 0; x < kTexels; ++x) {
            const float u = (float(x - shiftTexels) + 0.5f) / kTexels;
            const float v = (float(y) + 0.5f) / kTexels;
            image.texels.push_back(glm::vec4(exactIntegrand(lighting, u, v), 1.0f));
        }
    }
    return image;
}

// The bilinear interpolant's largest error against the exact integrand, found at
// the midpoints between texel centres (where a smooth function's is largest),
// with a bilinear read written here.
float largestTexelError(const Scene& scene, const Image& texture) {
    const raytrace::Bvh none = raytrace::Bvh::build({});
    const reference::ReferenceLighting lighting(scene, none);
    float worst = 0.0f;
    for (int y = 0; y + 1 < kTexels; ++y) {
        for (int x = 0; x + 1 < kTexels; ++x) {
            for (const glm::vec2 f : {glm::vec2(0.5f, 0.5f), glm::vec2(0.5f, 0.0f), glm::vec2(0.0f, 0.5f)}) {
                const glm::vec3 a = glm::vec3(texture.at(x, y)), b = glm::vec3(texture.at(x + 1, y));
                const glm::vec3 c = glm::vec3(texture.at(x, y + 1)), d = glm::vec3(texture.at(x + 1, y + 1));
                const glm::vec3 bilinear = glm::mix(glm::mix(a, b, f.x), glm::mix(c, d, f.x), f.y);
                const glm::vec3 exact = exactIntegrand(lighting, (float(x) + 0.5f + f.x) / kTexels,
                                                       (float(y) + 0.5f + f.y) / kTexels);
                for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::fabs(bilinear[ch] - exact[ch]));
            }
        }
    }
    return worst;
}

// Points across the cone's edge ring, in several directions.
std::vector<raytrace::Ray> raysAcrossTheRing() {
    std::vector<raytrace::Ray> rays;
    for (int i = 0; i < 24; ++i) {
        const float radiusM = 0.001f * (7.0f + 0.25f * float(i));
        const float angle = 0.7f + 2.4f * float(i);
        rays.push_back(downAt(radiusM * std::cos(angle), radiusM * std::sin(angle)));
    }
    return rays;
}

std::vector<glm::vec4> diffuse(const Scene& scene) {
    auto renderer = reference::ReferenceRenderer::create(scene, planeModels(), reference::ReferenceOptions{});
    EXPECT_TRUE(renderer.ok());
    return renderer->diffuseAlongRays(raysAcrossTheRing(), 0.0f, 0.02f);
}

std::vector<glm::vec4> scatterChange(const Scene& scene, Image texture) {
    reference::ReferenceOptions options;
    options.engineIrradiance.push_back(std::move(texture));
    auto renderer = reference::ReferenceRenderer::create(scene, planeModels(), options);
    EXPECT_TRUE(renderer.ok());
    const std::vector<glm::vec4> delta = renderer->scatterChangeAlongRays(raysAcrossTheRing(), 0.0f, 0.02f);
    EXPECT_EQ(renderer->stats().emptyIrradianceReads, 0u);
    return delta;
}

// The largest |(SSS off + Delta) - SSS on| over the points and channels, and the
// largest |SSS on - SSS off| (how much the scattering changes the light there).
float largestMismatch(const std::vector<glm::vec4>& off, const std::vector<glm::vec4>& delta,
                      const std::vector<glm::vec4>& on, float* largestScatter = nullptr) {
    float worst = 0.0f, scatter = 0.0f;
    for (size_t i = 0; i < on.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::fabs(off[i][c] + delta[i][c] - on[i][c]));
            scatter = std::max(scatter, std::fabs(on[i][c] - off[i][c]));
        }
    }
    if (largestScatter) *largestScatter = scatter;
    return worst;
}

}  // namespace

TEST(ReferenceMatched, EngineTextureOfTheExactLightingGivesTheSssOnImage) {
    const Scene sssOn = spotOnSmallPlane(true, 1.0f);
    const Image texture = textureFromExactLighting(sssOn, 0);
    const std::vector<glm::vec4> off = diffuse(spotOnSmallPlane(false, 1.0f));
    const std::vector<glm::vec4> on = diffuse(sssOn);
    const std::vector<glm::vec4> delta = scatterChange(sssOn, texture);
    // Both sides use the same quadrature cells, so they differ only by E~ - E: by at
    // most e (the bilinear error) under the integral, whose weights sum to 1 within the
    // furnace's 0.3 %, and by at most e at x_o; each is scaled by albedo^(1-mix) <= 1.
    const float e = largestTexelError(sssOn, texture);
    const float bound = (1.003f + 1.0f) * e;
    float scatter = 0.0f;
    const float mismatch = largestMismatch(off, delta, on, &scatter);
    std::printf("matched: largest |off + Delta - on| %.2e, bound %.2e (texel error %.2e); scattering changes the light by up to %.3f\n",
                double(mismatch), double(bound), double(e), double(scatter));
    EXPECT_LT(mismatch, bound);
    EXPECT_GT(scatter, 20.0f * bound);  // the points see real scattering, not just the local term
    for (size_t i = 0; i < on.size(); ++i) EXPECT_EQ(delta[i].a, 1.0f);

    // A texture three texels (0.23 mm) off, or a profile 5 % wider, is caught.
    const float shifted = largestMismatch(off, scatterChange(sssOn, textureFromExactLighting(sssOn, 3)), on);
    const float wider = largestMismatch(off, delta, diffuse(spotOnSmallPlane(true, 1.05f)));
    std::printf("matched: shifted by 3 texels %.2e, profile 5 %% wider %.2e\n", double(shifted), double(wider));
    EXPECT_GT(shifted, bound);
    EXPECT_GT(wider, bound);
}

TEST(ReferenceMatched, UniformTextureOnAFlatPlaneChangesNothing) {
    // Delta = albedo^(1-mix) x E~ x (integral of R - 1): 0 up to the quadrature's
    // mass error, which the furnace test bounds by 0.3 % and measures at 0.04 to 0.08 %.
    Scene scene = bareScene();
    scene.settings.sss.mix = kMix;
    scene.lights.push_back(sunFromAbove());
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    scene.characters[0].material.albedo = kAlbedo;
    const glm::vec3 integrand(0.9f, 0.7f, 0.4f);
    Image texture;
    texture.width = 8;
    texture.height = 4;
    texture.texels.assign(32, glm::vec4(integrand, 1.0f));
    // Empty texels (alpha 0, RGB garbage) next to covered ones take a neighbour's value.
    texture.texels[9] = texture.texels[20] = glm::vec4(100.0f, -5.0f, 7.0f, 0.0f);
    reference::ReferenceOptions options;
    options.engineIrradiance.push_back(texture);
    auto renderer = reference::ReferenceRenderer::create(scene, planeModels(), options);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    std::vector<raytrace::Ray> rays;
    for (int i = 0; i < 24; ++i) rays.push_back(downAt(0.3f * std::sin(1.7f * float(i)), 0.3f * std::cos(2.3f * float(i))));
    const std::vector<glm::vec4> delta = renderer->scatterChangeAlongRays(rays, 0.0f, 0.02f);
    const glm::vec3 scale = glm::sqrt(kAlbedo) * integrand;
    for (const glm::vec4& d : delta) {
        ASSERT_EQ(d.a, 1.0f);
        for (int c = 0; c < 3; ++c) EXPECT_LT(std::fabs(d[c]) / scale[c], 0.002f) << "channel " << c;
    }
    EXPECT_EQ(renderer->stats().emptyIrradianceReads, 0u);
}

TEST(ReferenceMatched, NoScatterChangeWithoutSssOrTexture) {
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove());
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    Image texture;
    texture.width = texture.height = 2;
    texture.texels.assign(4, glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));  // the light "moved": Delta would be non-zero
    const std::vector<raytrace::Ray> rays = {downAt(0.0f, 0.0f), downAt(0.2f, 0.1f),
                                              raytrace::Ray{glm::vec3(0.0f, 0.1f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)}};
    for (bool sss : {false, true}) {
        for (bool withTexture : {false, true}) {
            if (sss && withTexture) continue;
            scene.settings.sss.enabled = sss;
            reference::ReferenceOptions options;
            if (withTexture) options.engineIrradiance.push_back(texture);
            auto renderer = reference::ReferenceRenderer::create(scene, planeModels(), options);
            ASSERT_TRUE(renderer.ok());
            const std::vector<glm::vec4> delta = renderer->scatterChangeAlongRays(rays, 0.0f, 0.02f);
            EXPECT_EQ(delta[0], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
            EXPECT_EQ(delta[1], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
            EXPECT_EQ(delta[2], glm::vec4(0.0f));  // the background
        }
    }
}

TEST(ReferenceMatched, BadTexturesAreRefused) {
    Scene scene = bareScene();
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    reference::ReferenceOptions options;
    options.engineIrradiance.resize(2);
    auto wrongCount = reference::ReferenceRenderer::create(scene, planeModels(), options);
    ASSERT_FALSE(wrongCount.ok());
    EXPECT_NE(wrongCount.error().message().find("one engine irradiance image per character"), std::string::npos);
    Image nan;
    nan.width = nan.height = 1;
    nan.texels.push_back(glm::vec4(NAN, 0.0f, 0.0f, 1.0f));
    options.engineIrradiance = {nan};
    auto notFinite = reference::ReferenceRenderer::create(scene, planeModels(), options);
    ASSERT_FALSE(notFinite.ok());
    EXPECT_NE(notFinite.error().message().find("'plane'"), std::string::npos);
}

TEST(ReferenceMatched, EmptyTexelsTakeTheNearestCoveredOneWithinReach) {
    const Character character = proceduralCharacter("plane", "plane", "skin");
    auto surface = reference::CharacterSurface::create(character, proceduralModelWithoutMaps("plane"));
    ASSERT_TRUE(surface.ok());
    // One row: covered texels 0 (value 1) and 4 (value 5); 5 to 11 empty, beyond reach
    // (3 texels) of texel 4 from texel 8 on.
    Image texture;
    texture.width = 12;
    texture.height = 1;
    texture.texels.assign(12, glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f));
    texture.texels[0] = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    texture.texels[4] = glm::vec4(5.0f, 0.0f, 0.0f, 1.0f);
    auto engine = reference::EngineIrradiance::create(*surface, texture);
    ASSERT_TRUE(engine.ok());
    EXPECT_EQ((*engine)->unfilledTexels(), 4u);  // 8, 9, 10, 11
    auto at = [&](float x) { return (*engine)->sampleAt(glm::vec2((x + 0.5f) / 12.0f, 0.5f)).r; };
    EXPECT_FLOAT_EQ(at(1.0f), 1.0f);  // nearest: texel 0
    EXPECT_FLOAT_EQ(at(2.0f), 1.0f);  // a tie between 0 and 4: the first in row order
    EXPECT_FLOAT_EQ(at(3.0f), 5.0f);
    EXPECT_FLOAT_EQ(at(7.0f), 5.0f);  // three texels from texel 4
    EXPECT_FLOAT_EQ(at(7.5f), 5.0f);  // half on texel 8, which has no value: the covered tap alone
    EXPECT_EQ((*engine)->emptyReads(), 0u);
    EXPECT_FLOAT_EQ(at(9.5f), 0.0f);  // no tap has a value: 0, and counted
    EXPECT_EQ((*engine)->emptyReads(), 1u);
    // v is not flipped: row 0 is v near 0.
    Image twoRows;
    twoRows.width = 1;
    twoRows.height = 2;
    twoRows.texels = {glm::vec4(1.0f, 0.0f, 0.0f, 1.0f), glm::vec4(3.0f, 0.0f, 0.0f, 1.0f)};
    auto rows = reference::EngineIrradiance::create(*surface, twoRows);
    ASSERT_TRUE(rows.ok());
    EXPECT_FLOAT_EQ((*rows)->sampleAt(glm::vec2(0.5f, 0.25f)).r, 1.0f);
    EXPECT_FLOAT_EQ((*rows)->sampleAt(glm::vec2(0.5f, 0.75f)).r, 3.0f);
}

// The change at an outline pixel box-filters the surface the engine's pixel shows, the one at
// its centre, over the sub-samples that meet it. The plane's edge (x = 0.5 m) runs down the
// frame 0.3 pixels left of a column's right side, so that column's centres lie on the plane and
// its right-hand sub-samples partly off it. Pixels are 0.01 mm: across the covered 0.7 of a
// pixel the exact change of a uniform texture, E (edge response - 1) near an edge, moves by
// about 1% of its value (the skin profile's steepest slope, w_0 phi(0) / sigma_0 = 1.2 per mm,
// over 0.007 mm, against |change| of about E / 2). Bound: each such pixel's change within 5% of
// its centre's (spp 1); measured 2.5%. Broken on purpose: averaging every sub-sample, the
// background's 0 included (the old rule), scales those pixels by their coverage: 25 of the 32
// rows are partly covered, and they are off by up to 51%.
TEST(ReferenceMatched, OutlinePixelsAverageTheSurfaceAtTheirCentre) {
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove());
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    constexpr int kSize = 32;
    constexpr float kPixelM = 1e-5f;
    constexpr float kFovDeg = 10.0f;
    const float heightM = 0.5f * kSize * kPixelM / std::tan(glm::radians(0.5f * kFovDeg));
    const float edgeColumn = 15.7f;  // where the edge crosses the frame, in pixels from the left
    scene.camera.positionM = glm::vec3(0.5f + (0.5f * kSize - edgeColumn) * kPixelM, heightM, 0.0f);
    scene.camera.targetM = glm::vec3(scene.camera.positionM.x, 0.0f, 0.0f);
    scene.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.verticalFovDeg = kFovDeg;
    scene.camera.nearM = 1e-4f;
    scene.camera.farM = 1.0f;
    Image texture;
    texture.width = 8;
    texture.height = 4;
    texture.texels.assign(32, glm::vec4(0.9f, 0.7f, 0.4f, 1.0f));
    auto changeAt = [&](int samplesPerPixel) {
        reference::ReferenceOptions options;
        options.engineIrradiance.push_back(texture);
        options.samplesPerPixel = samplesPerPixel;
        auto renderer = reference::ReferenceRenderer::create(scene, planeModels(), options);
        EXPECT_TRUE(renderer.ok());
        return renderer.ok() ? renderer->renderScatterChange(kSize, kSize) : Image{};
    };
    const Image centre = changeAt(1);
    const Image box = changeAt(4);
    ASSERT_EQ(box.texels.size(), centre.texels.size());
    const int column = int(edgeColumn);
    int compared = 0;
    float worst = 0.0f;
    for (int y = 0; y < kSize; ++y) {
        ASSERT_EQ(centre.at(column, y).a, 1.0f) << "the column's centres must lie on the plane";
        ASSERT_EQ(centre.at(column + 1, y).a, 0.0f) << "the next column's must not";
        for (int c = 0; c < 3; ++c) {
            ASSERT_LT(centre.at(column, y)[c], -0.1f * texture.texels[0][c]) << "the edge should take light";
            worst = std::max(worst, std::fabs(box.at(column, y)[c] / centre.at(column, y)[c] - 1.0f));
        }
        EXPECT_EQ(box.at(column, y).a, 1.0f);
        ++compared;
    }
    std::printf("outline column: largest |box / centre - 1| %.4f over %d pixels\n", double(worst), compared);
    EXPECT_LT(worst, 0.05f);
}
