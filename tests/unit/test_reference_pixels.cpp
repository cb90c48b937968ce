// The reference's pixel filtering (docs/reference.md): mip pyramids and the
// level of detail of the GPU, maps read at the pixel's footprint, and the
// stratified sub-samples converging on the exact coverage of a straight edge.
#include "ReferenceTestScenes.h"

#include "reference/MipPyramid.h"
#include "reference/ReferenceRenderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dermis;
using namespace dermis::test;

namespace {

// Mean of level-0 texels [x0, x0 + n) x [y0, y0 + m): the box filter, computed directly.
float boxMean(const Image& image, int x0, int y0, int n, int m) {
    float sum = 0.0f;
    for (int y = y0; y < y0 + m; ++y) {
        for (int x = x0; x < x0 + n; ++x) sum += image.at(x, y).r;
    }
    return sum / float(n * m);
}

// A camera straight down (-Y) from heightM above (x, z), image top towards -Z.
Camera cameraLookingDown(float heightM, float xM = 0.0f, float zM = 0.0f) {
    Camera camera;
    camera.positionM = glm::vec3(xM, heightM, zM);
    camera.targetM = glm::vec3(xM, 0.0f, zM);
    camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.verticalFovDeg = 30.0f;
    camera.nearM = 0.01f;
    camera.farM = 10.0f;
    return camera;
}

// Area of the unit pixel square at (px, py) inside the convex polygon (counter-clockwise
// in pixel coordinates): the square clipped by each edge (Sutherland-Hodgman), then the
// shoelace formula.
double coveredArea(const std::vector<glm::dvec2>& polygon, int px, int py) {
    std::vector<glm::dvec2> clip = {{px, py}, {px + 1, py}, {px + 1, py + 1}, {px, py + 1}};
    for (size_t e = 0; e < polygon.size(); ++e) {
        const glm::dvec2 a = polygon[e], b = polygon[(e + 1) % polygon.size()];
        auto side = [&](const glm::dvec2& p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
        std::vector<glm::dvec2> kept;
        for (size_t i = 0; i < clip.size(); ++i) {
            const glm::dvec2 p = clip[i], q = clip[(i + 1) % clip.size()];
            const double sp = side(p), sq = side(q);
            if (sp >= 0.0) kept.push_back(p);
            if ((sp >= 0.0) != (sq >= 0.0)) kept.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        clip = kept;
        if (clip.empty()) return 0.0;
    }
    double area = 0.0;
    for (size_t i = 0; i < clip.size(); ++i) {
        const glm::dvec2 p = clip[i], q = clip[(i + 1) % clip.size()];
        area += p.x * q.y - q.x * p.y;
    }
    return std::fabs(0.5 * area);
}

}  // namespace

TEST(ReferencePixels, MipPyramidIsTheBoxPyramidWithTheGpuLevelOfDetail) {
    Image image;
    image.width = 8;
    image.height = 4;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) image.texels.push_back(glm::vec4(float(x * x) + 10.0f * float(y), 0.0f, 0.0f, 1.0f));
    }
    const reference::MipPyramid pyramid(image);
    ASSERT_EQ(pyramid.levelCount(), 4u);  // 8x4, 4x2, 2x1, 1x1 (glTexStorage2D's count for 8x4)
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(pyramid.level(1).at(x, y).r, boxMean(image, 2 * x, 2 * y, 2, 2));
    }
    for (int x = 0; x < 2; ++x) EXPECT_FLOAT_EQ(pyramid.level(2).at(x, 0).r, boxMean(image, 4 * x, 0, 4, 4));
    EXPECT_FLOAT_EQ(pyramid.level(3).at(0, 0).r, boxMean(image, 0, 0, 8, 4));

    // lambda = log2 of the longer footprint axis in level-0 texels.
    const glm::vec2 uv(0.25f, 0.25f);
    reference::MapFootprint footprint{glm::vec2(2.0f / 8.0f, 0.0f), glm::vec2(0.0f, 1.0f / 4.0f)};
    EXPECT_FLOAT_EQ(pyramid.levelOfDetail(footprint), 1.0f);
    // At uv (0.25, 0.25) level 1 reads halfway between its texels (0,0) and (1,0); level 2
    // (one row, repeat) its texel (0,0).
    const float level1 = 0.5f * (boxMean(image, 0, 0, 2, 2) + boxMean(image, 2, 0, 2, 2));
    const float level2 = boxMean(image, 0, 0, 4, 4);
    EXPECT_FLOAT_EQ(pyramid.sample(uv, footprint, glm::vec4(0.0f)).r, level1);
    footprint.uvPerPixelY = glm::vec2(0.0f, std::sqrt(8.0f) / 4.0f);  // lambda 1.5: halfway to level 2
    EXPECT_NEAR(pyramid.sample(uv, footprint, glm::vec4(0.0f)).r, 0.5f * (level1 + level2), 1e-4f);
    footprint.uvPerPixelX = glm::vec2(1e3f, 0.0f);  // beyond the last level: the 1x1 mean
    EXPECT_FLOAT_EQ(pyramid.sample(uv, footprint, glm::vec4(0.0f)).r, boxMean(image, 0, 0, 8, 4));
    // A footprint under a texel (magnification) reads level 0.
    footprint = reference::MapFootprint{glm::vec2(0.01f, 0.0f), glm::vec2(0.0f, 0.01f)};
    EXPECT_FLOAT_EQ(pyramid.sample(glm::vec2(1.5f / 8.0f, 0.5f / 4.0f), footprint, glm::vec4(0.0f)).r, 1.0f);
}

TEST(ReferencePixels, MapsAreReadAtThePixelFootprint) {
    // A one-texel checker of 0.2 and 0.8 (linear) over the 1 m plane, 256 texels a side,
    // seen straight down so that a pixel spans 8 texels: level 3 and every level above 0
    // is 0.5 exactly, so every pixel is E x 0.5. Point samples of level 0 would give
    // values from 0.2 to 0.8.
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove());
    scene.characters.push_back(proceduralCharacter("plane", "plane", "none"));
    constexpr int kSize = 256, kWidth = 16, kHeight = 12;
    const float metresPerPixel = 8.0f / kSize;
    scene.camera = cameraLookingDown(kHeight * metresPerPixel / (2.0f * std::tan(glm::radians(15.0f))), 0.013f, 0.021f);
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    Image checker;
    checker.width = checker.height = kSize;
    for (int i = 0; i < kSize * kSize; ++i) {
        checker.texels.push_back(glm::vec4(glm::vec3((i % kSize + i / kSize) % 2 ? 0.8f : 0.2f), 1.0f));
    }
    models[0].materials[0].albedoMap = checker;
    for (int spp : {1, 4}) {
        reference::ReferenceOptions options;
        options.samplesPerPixel = spp;
        auto renderer = reference::ReferenceRenderer::create(scene, models, options);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message();
        const Image image = renderer->renderDiffuse(kWidth, kHeight);
        for (const glm::vec4& texel : image.texels) {
            ASSERT_EQ(texel.a, 1.0f);
            // Float rounding of lambda near 3 only moves between levels that all read 0.5.
            EXPECT_NEAR(texel.r, 0.5f, 1e-4f) << "spp " << spp;
        }
    }
}

TEST(ReferencePixels, SubSamplesConvergeOnTheEdgeCoverage) {
    // The plane turned 17 degrees about Y, its border through the view at a generic
    // angle, seen straight down; textured (a 16 x 16 checker) and lit (SSS off: the
    // sub-samples do not depend on the shading). Coverage alpha against the exact area
    // of each pixel inside the projected plane; RGB against 64 samples per pixel.
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove());
    scene.settings.ambient = glm::vec3(0.1f);
    scene.characters.push_back(proceduralCharacter("plane", "plane", "none"));
    Transform& transform = scene.characters[0].transform;
    transform.rotationDeg = glm::vec3(0.0f, 17.0f, 0.0f);
    transform.translationM = glm::vec3(0.0123f, 0.0f, 0.0071f) -
                             glm::vec3(glm::mat3(transform.worldFromObject(1.0f)) * glm::vec3(0.5f, 0.0f, 0.0f));
    scene.camera = cameraLookingDown(0.3f);
    constexpr int kWidth = 32, kHeight = 24;
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    Image checker;
    checker.width = checker.height = 16;
    for (int i = 0; i < 256; ++i) {
        checker.texels.push_back((i % 16 + i / 16) % 2 ? glm::vec4(0.9f, 0.5f, 0.3f, 1.0f) : glm::vec4(0.3f, 0.6f, 0.9f, 1.0f));
    }
    models[0].materials[0].albedoMap = checker;

    // The plane's corners projected to pixel coordinates (y down), counter-clockwise there.
    const glm::mat4 clipFromWorld =
        glm::perspective(glm::radians(scene.camera.verticalFovDeg), float(kWidth) / kHeight, scene.camera.nearM,
                         scene.camera.farM) *
        glm::lookAt(scene.camera.positionM, scene.camera.targetM, scene.camera.up);
    std::vector<glm::dvec2> polygon;
    for (const glm::vec2 corner : {glm::vec2(-0.5f, -0.5f), glm::vec2(-0.5f, 0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(0.5f, -0.5f)}) {
        const glm::vec4 clip = clipFromWorld * transform.worldFromObject(1.0f) * glm::vec4(corner.x, 0.0f, corner.y, 1.0f);
        polygon.push_back(glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * kWidth, (1.0 - clip.y / clip.w) * 0.5 * kHeight));
    }
    {
        double signedArea = 0.0;
        for (size_t i = 0; i < 4; ++i) signedArea += polygon[i].x * polygon[(i + 1) % 4].y - polygon[(i + 1) % 4].x * polygon[i].y;
        if (signedArea < 0.0) std::reverse(polygon.begin(), polygon.end());
    }

    auto render = [&](int spp) {
        reference::ReferenceOptions options;
        options.samplesPerPixel = spp;
        auto renderer = reference::ReferenceRenderer::create(scene, models, options);
        EXPECT_TRUE(renderer.ok());
        return renderer->renderDiffuse(kWidth, kHeight);
    };
    const Image best = render(64);
    std::printf("| samples per pixel | coverage RMSE (edge pixels) | relative RGB RMSE against 64 |\n|---|---|---|\n");
    double previous = INFINITY, previousRgb = INFINITY;
    for (int spp : {1, 4, 16, 64}) {
        const Image image = render(spp);
        double coverageError = 0.0, rgbError = 0.0, rgbReference = 0.0;
        int edgePixels = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const double exact = coveredArea(polygon, x, y);
                const glm::vec4& value = image.at(x, y);
                if (exact > 1e-6 && exact < 1.0 - 1e-6) {
                    coverageError += (value.a - exact) * (value.a - exact);
                    ++edgePixels;
                } else {
                    EXPECT_NEAR(value.a, exact, 1e-6) << "pixel " << x << ", " << y;  // wholly in or out
                }
                for (int c = 0; c < 3; ++c) {
                    rgbError += std::pow(double(value[c]) - double(best.at(x, y)[c]), 2.0);
                    rgbReference += std::pow(double(best.at(x, y)[c]), 2.0);
                }
            }
        }
        ASSERT_GT(edgePixels, 20);  // the border crosses the image
        const double coverageRmse = std::sqrt(coverageError / edgePixels);
        const double rgbRmse = std::sqrt(rgbError / rgbReference);
        std::printf("| %d | %.4f | %.4f |\n", spp, coverageRmse, rgbRmse);
        if (spp < 64) EXPECT_LT(rgbRmse, 0.6 * previousRgb) << spp << " samples per pixel (RGB)";
        previousRgb = rgbRmse;
        // Stratified samples of an edge: the error falls about as N^-3/4, by 2.8 per 4x the
        // samples; 0.6 leaves room for the
        // ~40 pixels' statistics. All sub-samples at the centre would not fall; a jitter
        // spread over more than its stratum would stop at the blur it adds.
        EXPECT_LT(coverageRmse, 0.6 * previous) << spp << " samples per pixel";
        previous = coverageRmse;
    }
    EXPECT_LT(previous, 0.03);  // 64 samples: a 1/64-area grid cell per sample, ~0.015 expected
}

// The three wrap modes against their definitions (OpenGL 4.5 §8.14.2): a row of
// four texels 0, 1, 2, 3 read at texel centres beyond [0, 1]. Repeat starts
// again at 0, clamp stays at the last texel, mirrored repeat runs back 3, 2, 1, 0.
TEST(ReferencePixels, MapsWrapAsTheirSamplersSay) {
    Image row;
    row.width = 4;
    row.height = 1;
    for (int i = 0; i < 4; ++i) row.texels.push_back(glm::vec4(float(i)));
    const float centreBeyond[] = {1.125f, 1.375f, 1.625f, 1.875f, -0.125f};  // texels 4, 5, 6, 7 and -1
    const float repeat[] = {0, 1, 2, 3, 3}, clamp[] = {3, 3, 3, 3, 0}, mirrored[] = {3, 2, 1, 0, 0};
    for (auto [wrap, expected] : {std::pair{TextureWrap::Repeat, repeat}, std::pair{TextureWrap::ClampToEdge, clamp},
                                  std::pair{TextureWrap::MirroredRepeat, mirrored}}) {
        const reference::MipPyramid map(row, TextureWraps{wrap, TextureWrap::Repeat});
        for (int k = 0; k < 5; ++k)
            EXPECT_NEAR(map.sample(glm::vec2(centreBeyond[k], 0.5f), glm::vec4(-1.0f)).r, expected[k], 1e-5f)
                << int(wrap) << " at u " << centreBeyond[k];
    }
}
