// Texture-space SSS (mode "ts") against closed forms and against the
// screen-space mode: the stretch map on the UV sphere, the furnace through
// the five blurs, the analytic edge, agreement on edge.json and on detail
// finer than a pixel, light through
// the ears, what runs, and the UV-space AOVs (stretch, irradiance-texture).
#include "AnalyticEdge.h"
#include "BumpMap.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "core/ImageMetrics.h"
#include "gl/GlGraphBackend.h"
#include "passes/TextureSpacePasses.h"
#include "plan/FramePlan.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"
#include "plan/ScreenFootprint.h"
#include "render/TsMeshes.h"
#include "brdf/EnergyTable.h"
#include "procedural/ProceduralShapes.h"
#include "reference/CharacterSurface.h"
#include "reference/ReferenceRenderer.h"
#include "reference/SurfaceInterior.h"
#include "procedural/Procedural.h"
#include "scene/SceneLoader.h"
#include "sss/DiffusionProfile.h"
#include "stress/StressCases.h"

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace dermis;

namespace {

class TextureSpace : public test::RenderFixture {};

gl::Buffer uniformBuffer(size_t bytes) {
    gl::Buffer buffer = gl::createBuffer("test: buffer");
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

int executedWithPrefix(const std::vector<PassSummary>& passes, const std::string& prefix) {
    int n = 0;
    for (const PassSummary& s : passes) n += s.name.rfind(prefix, 0) == 0 && s.executed ? 1 : 0;
    return n;
}

}  // namespace

TEST_F(TextureSpace, StretchMapOnTheUvSphereMatchesTheClosedForm) {
    // The stretch pass alone, on the procedural UV sphere (u = longitude / 2 pi,
    // v = polar angle / pi, radius r): |dP/du| = 2 pi r sin(theta), |dP/dv| = pi r.
    auto scene = parseScene(R"({"characters": [{"name": "ball", "mesh": {"procedural": "sphere"}}]})", "sphere.json");
    ASSERT_TRUE(scene.ok());
    auto models = loadSceneModels(*scene);
    ASSERT_TRUE(models.ok());
    SceneGeometry geometry(*models);
    auto gpuScene = GpuScene::create(*scene, *models);
    ASSERT_TRUE(gpuScene.ok());
    auto programs = Programs::build();
    ASSERT_TRUE(programs.ok()) << programs.error().message();
    gl::GpuProfiler profiler;
    gl::GlGraphBackend backend(profiler);
    const gl::Buffer objectUniforms = uniformBuffer(sizeof(gpu::ObjectBlock));
    const gl::Buffer passUniforms = uniformBuffer(kMaxPassBlockBytes);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_OBJECT, objectUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PASS, passUniforms.get());
    auto framePlan = planFrame(*scene, geometry, {512, 512, Aov::Stretch}, ShadowCache{});
    ASSERT_TRUE(framePlan.ok());
    TsMeshes meshes;
    meshes.prepare(0, gpuScene->characters()[0], geometry.uvLayout(0, 1.0f));
    FrameServices services;
    services.gpuScene = &*gpuScene;
    services.programs = &*programs;
    services.framebuffers = &backend.framebuffers();
    services.tsMeshes = &meshes;
    services.objectUniforms = objectUniforms.get();
    services.passUniforms = passUniforms.get();
    const FrameContext frame{*framePlan, &services};

    TsCharacterPlan plan;
    plan.label = "ball";
    plan.visible = true;
    plan.size = 512;
    plan.submeshes = {0};  // the sphere's one submesh
    graph::RenderGraph graph;
    const graph::TextureHandle stretch = addTsStretchPass(graph, frame, plan);
    std::vector<glm::vec2> texels(static_cast<size_t>(plan.size * plan.size));
    struct ReadData {
        graph::TextureHandle in;
    };
    graph.addPass<ReadData>(
        "read back",
        [&](graph::PassBuilder& builder, ReadData& d) {
            d.in = builder.read(stretch);
            builder.sideEffect();
        },
        [&](const graph::PassResources& resources, const ReadData& d) {
            glGetTextureImage(resources.texture(d.in), 0, GL_RG, GL_FLOAT,
                              static_cast<GLsizei>(texels.size() * sizeof(glm::vec2)), texels.data());
        });
    ASSERT_TRUE(graph.compile().ok());
    profiler.beginFrame(0);
    graph.execute(backend);

    const double rMm = 1000.0 * kSphereRadiusM;
    double worstU = 0.0;
    double worstV = 0.0;
    int checked = 0;
    int nonFinite = 0;
    for (int y = 0; y < plan.size; ++y) {
        for (int x = 0; x < plan.size; ++x) {
            const glm::vec2 s = texels[static_cast<size_t>(y * plan.size + x)];
            if (!std::isfinite(s.x) || !std::isfinite(s.y)) ++nonFinite;
            const double theta = glm::pi<double>() * (y + 0.5) / plan.size;
            if (theta < glm::radians(35.0) || theta > glm::radians(145.0)) continue;  // away from the poles
            worstU = std::max(worstU, std::abs(s.x / (2.0 * glm::pi<double>() * rMm * std::sin(theta)) - 1.0));
            worstV = std::max(worstV, std::abs(s.y / (glm::pi<double>() * rMm) - 1.0));
            ++checked;
        }
    }
    std::printf("stretch map, %d texels between 35 and 145 deg: worst error %.2f%% along u, %.2f%% along v\n", checked,
                100.0 * worstU, 100.0 * worstV);
    EXPECT_EQ(nonFinite, 0);
    EXPECT_GT(checked, 100000);
    EXPECT_LT(worstU, 0.05);
    EXPECT_LT(worstV, 0.05);
}

TEST_F(TextureSpace, FurnaceStaysUniformThroughTheFiveBlurs) {
    // A 5 cm skin plane under one light fills the view; at 512 texels (0.1 mm
    // each) every one of skin's Gaussians 1-5 is wide enough to be blurred.
    const std::vector<std::string> common = {"characters.0.transform.scale=0.05", "camera.position_m=[0,0.03,0]",
                                             "ts.min_size=512"};
    std::vector<std::string> ts = common;
    ts.push_back("mode=ts");
    load("furnace.json", ts);
    const Image image = render(Aov::Diffuse, 160, 90);
    int blurs = 0;
    for (const PassSummary& s : summary()) {
        const bool blur = s.name.rfind("ts plane g", 0) == 0 && (s.name.back() == 'u' || s.name.back() == 'v');
        blurs += blur && s.executed ? 1 : 0;
    }
    EXPECT_GE(blurs, 10) << "at least Gaussians 1-5, U and V";
    EXPECT_TRUE(pass("ts plane g1 u")->executed);
    EXPECT_TRUE(pass("ts plane g5 v")->executed);
    std::vector<std::string> unblurred = common;
    unblurred.push_back("sss.enabled=false");
    load("furnace.json", unblurred);
    const Image reference = render(Aov::Diffuse, 160, 90);
    ASSERT_EQ(test::countNonFinite(image), 0u);
    // The ratio to the unblurred light must be the same everywhere. Its level
    // may differ from 1 by the G-buffer's 8-bit sRGB albedo, which the
    // screen-space pre-scatter albedo^mix goes through and the texture-space
    // one does not (up to 0.7% on llvmpipe, whose sRGB encoding rounds down).
    glm::dvec3 lowest(INFINITY);
    glm::dvec3 highest(-INFINITY);
    for (size_t i = 0; i < image.texels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_GT(reference.texels[i][c], 0.05f);
            const double ratio = double(image.texels[i][c]) / reference.texels[i][c];
            lowest[c] = std::min(lowest[c], ratio);
            highest[c] = std::max(highest[c], ratio);
        }
    }
    double spread = 0.0;
    for (int c = 0; c < 3; ++c) {
        spread = std::max(spread, highest[c] / lowest[c] - 1.0);
        EXPECT_NEAR(lowest[c], 1.0, 0.01) << "channel " << c;
    }
    std::printf("texture-space furnace: ratio to the unblurred light %.4f..%.4f (R) %.4f..%.4f (G) %.4f..%.4f (B); "
                "largest spread %.5f\n",
                lowest.r, highest.r, lowest.g, highest.g, lowest.b, highest.b, spread);
    EXPECT_LT(spread, 0.005);
}

TEST_F(TextureSpace, AnalyticEdgeMatchesSumOfGaussianCdfsInBothModes) {
    test::TempDir dir;
    const std::string scene = test::writeEdgeScene(dir);
    const int width = 640;
    const int height = 360;
    load(scene, {"sss.min_width_px=0"});
    const Image ss = render(Aov::Diffuse, width, height);
    load(scene, {"mode=ts"});
    const Image ts = render(Aov::Diffuse, width, height);
    const test::EdgeError ssError = test::edgeError(ss, width, height);
    const test::EdgeError tsError = test::edgeError(ts, width, height);
    auto agreement = compareImages(ss, ts);
    ASSERT_TRUE(agreement.ok());
    std::printf("analytic edge: ss max %.4f RMS %.4f; ts max %.4f RMS %.4f; ts against ss: max %.4f, relative RMSE %.4f\n",
                ssError.max, ssError.rms, tsError.max, tsError.rms, agreement->maxAbsDifference,
                agreement->relativeRmse);
    EXPECT_LT(tsError.max, 0.1);
    EXPECT_LT(tsError.rms, 0.01);
    EXPECT_LT(agreement->maxAbsDifference, 0.1);
    EXPECT_LT(agreement->relativeRmse, 0.02);
}

// Detail finer than a pixel: the edge scene's plane 100 mm wide, seen from
// five times as high (about 0.5 mm per pixel), its albedo stripes of period
// kStripePeriodTexels texels of a 2048-texel map (0.29 mm), the irradiance
// texture forced to 2048^2 (0.05 mm texels). With mix 1 the blur's input is
// the stripes, which the narrowest Gaussian (0.08 mm) keeps a quarter of
// (exp(-2 pi^2 v / P^2)) and the wider ones almost none of. No pixel can
// show them: screen space blurs the G-buffer's irradiance, whose albedo was
// read at the pixel's footprint (what remains of the stripes there is the
// footprint filter's, and the same in both modes). Texture space must give
// the same light pixel by pixel. Bound 3% of the row's mean: measured 0.96%
// with the Gaussians under a pixel taking the pixel's own irradiance
// (ts_gather.frag); 33% when they read the texture at the pixel's centre,
// which picks one texel's share of the stripes.
constexpr int kStripePeriodTexels = 6;
constexpr double kUnresolvedDetailMaxDifference = 0.03;

TEST_F(TextureSpace, DetailFinerThanAPixelGivesTheScreenSpaceLight) {
    test::TempDir dir;
    const std::string scene = test::writeEdgeScene(dir);
    Image stripes;
    stripes.width = 2048;
    stripes.height = 4;
    stripes.colourSpace = ColourSpace::Linear;
    for (int y = 0; y < stripes.height; ++y)
        for (int x = 0; x < stripes.width; ++x) {
            const float v = (x / (kStripePeriodTexels / 2)) % 2 == 0 ? 0.3f : 1.0f;
            stripes.texels.push_back(glm::vec4(v, v, v, 1.0f));
        }
    ASSERT_TRUE(saveImage(dir.file("stripes.png"), stripes).ok());
    const int width = 320, height = 180;
    const std::vector<std::string> far = {
        "ts.min_size=2048", "ts.max_size=2048", "characters.0.transform.scale=0.1",
        "characters.0.material.albedo_map=" + dir.file("stripes.png"),
        "camera.position_m=[0," + std::to_string(5.0 * test::kEdgeHeightM) + ",0]"};
    std::vector<std::string> ts = far, ss = far;
    ts.push_back("mode=ts");
    ss.push_back("mode=ss");
    load(scene, ss);
    const Image screen = render(Aov::Diffuse, width, height);
    load(scene, ts);
    const Image texture = render(Aov::Diffuse, width, height);
    const int row = height / 2;
    const int first = width / 2 - 80, last = width / 2 + 80;  // the plane covers about 200 px; its borders stay out
    glm::dvec3 mean(0.0);
    for (int x = first; x < last; ++x) mean += glm::dvec3(screen.at(x, row));
    mean /= double(last - first);
    double largest = 0.0;
    for (int x = first; x < last; ++x)
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(double(texture.at(x, row)[c]) - screen.at(x, row)[c]) / mean[c]);
    std::printf("stripes under a pixel: screen-space row mean %.4f %.4f %.4f; texture space departs by %.4f of it at most\n",
                mean.r, mean.g, mean.b, largest);
    ASSERT_GT(mean.b, 0.3);
    EXPECT_LT(largest, kUnresolvedDetailMaxDifference);
}

TEST_F(TextureSpace, EdgeSceneAgreesWithScreenSpace) {
    // content/scenes/edge.json: a skin plane with a shadow edge across it.
    const int width = 320;
    const int height = 180;
    load("edge.json");
    const Image ss = render(Aov::Diffuse, width, height);
    load("edge.json", {"mode=ts"});
    const Image ts = render(Aov::Diffuse, width, height);
    const Image ids = render(Aov::Object, width, height);
    std::vector<uint8_t> skin(ids.texels.size());
    for (size_t i = 0; i < skin.size(); ++i) skin[i] = std::lround(ids.texels[i].r) == 1 ? 1 : 0;
    auto d = compareImages(ss, ts, skin);
    ASSERT_TRUE(d.ok()) << d.error().message();
    std::printf("edge.json, %zu skin pixels: ts against ss relative RMSE %.4f, max difference %.4f (peak %.3f), PSNR %.1f dB\n",
                d->pixels, d->relativeRmse, d->maxAbsDifference, d->peak, d->psnrDb);
    EXPECT_GT(d->pixels, 10000u);
    EXPECT_LT(d->relativeRmse, 0.03);
    EXPECT_LT(d->maxAbsDifference, 0.1 * d->peak);
}

TEST_F(TextureSpace, EarsTransmitABackLight) {
    // The default head seen from its left, with the default's spot light
    // behind the left ear: the ear's outer face is in the light's shadow, and
    // only the transmittance brings light through: the one both modes share
    // (the default) or the translucent shadow map (ts.tsm).
    const std::vector<std::string> view = {"mode=ts", "camera.position_m=[-0.36,0.02,0.34]", "camera.target_m=[-0.06,0,0]",
                                           "ts.max_size=512"};
    const auto renderWith = [&](const std::string& setting) {
        std::vector<std::string> overrides = view;
        overrides.push_back(setting);
        load("default.json", overrides);
        return render(Aov::Diffuse, 320, 180);
    };
    // A pass that was not declared did not run either.
    const auto ran = [&](const char* name) { return pass(name) != nullptr && pass(name)->executed; };
    const Image withTsm = renderWith("ts.tsm=true");
    EXPECT_TRUE(ran("ts head tsm"));
    EXPECT_FALSE(ran("transmittance"));
    const Image shared = renderWith("ts.tsm=false");
    EXPECT_TRUE(ran("transmittance"));
    EXPECT_FALSE(ran("ts head tsm"));
    const Image unlit = renderWith("transmittance.enabled=false");
    ASSERT_EQ(test::countNonFinite(withTsm), 0u);
    ASSERT_EQ(test::countNonFinite(shared), 0u);

    // The ear's screen box: the left ear plate's centre, projected.
    const glm::vec3 earM(-0.087f, 0.002f, -0.016f);
    const ViewParams v = makeViewParams(mScene->camera, 320, 180);
    const glm::vec4 clip = v.clipFromView * v.viewFromWorld * glm::vec4(earM, 1.0f);
    const int cx = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * 320.0f);
    const int cy = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * 180.0f);
    for (const auto& [name, lit] : {std::pair<const char*, const Image*>{"the TSM", &withTsm}, {"the shared model", &shared}}) {
        double earWith = 0.0;
        double earWithout = 0.0;
        double elsewhereChange = 0.0;
        int earPixels = 0;
        for (int y = 0; y < 180; ++y) {
            for (int x = 0; x < 320; ++x) {
                const double with = lit->at(x, y).r;
                const double without = unlit.at(x, y).r;
                if (std::abs(x - cx) <= 12 && std::abs(y - cy) <= 16) {
                    earWith += with;
                    earWithout += without;
                    ++earPixels;
                } else if (std::abs(x - cx) > 40) {
                    elsewhereChange = std::max(elsewhereChange, with - without);
                }
            }
        }
        std::printf("ear box (%d px around %d,%d): red %.4f with %s, %.4f without (x%.2f); elsewhere at most +%.4f\n",
                    earPixels, cx, cy, earWith / earPixels, name, earWithout / earPixels,
                    earWith / std::max(earWithout, 1e-9), elsewhereChange);
        EXPECT_GT(earWith, 1.5 * earWithout) << name;
    }
}

TEST_F(TextureSpace, OffScreenCharacterRunsNoTextureSpacePass) {
    load("default.json", {"mode=ts", "camera.target_m=[0,0,5]"});
    render(Aov::Final, 160, 90);
    int declared = 0;
    for (const PassSummary& s : summary()) {
        if (s.name.rfind("ts ", 0) != 0) continue;
        ++declared;
        EXPECT_FALSE(s.executed) << s.name;
        if (s.name.rfind("ts head", 0) == 0) EXPECT_EQ(s.culledBecause, "predicate: character off screen") << s.name;
    }
    EXPECT_GT(declared, 10);
}

TEST_F(TextureSpace, ScreenSpaceModeRunsNoTextureSpacePassAndViceVersa) {
    load("default.json");
    render(Aov::Final, 160, 90);
    EXPECT_EQ(executedWithPrefix(summary(), "ts "), 0);
    EXPECT_GT(executedWithPrefix(summary(), "sss "), 0);
    load("default.json", {"mode=ts"});
    render(Aov::Final, 160, 90);
    EXPECT_EQ(executedWithPrefix(summary(), "sss "), 0);
    EXPECT_GT(executedWithPrefix(summary(), "ts head"), 8);
    // Both modes share the transmittance (include/Transmittance.glsl); the TSM takes its place when asked for.
    EXPECT_EQ(executedWithPrefix(summary(), "transmittance"), 1) << "texture space adds the shared transmittance";
    EXPECT_EQ(executedWithPrefix(summary(), "ts head tsm"), 0);
    load("default.json", {"mode=ts", "ts.tsm=true"});
    render(Aov::Final, 160, 90);
    EXPECT_EQ(executedWithPrefix(summary(), "transmittance"), 0) << "the TSM replaces the shared transmittance";
    EXPECT_EQ(executedWithPrefix(summary(), "ts head tsm"), 1);
}

namespace {

// The UV sphere in front of the camera, lit from the camera's side, its UV
// textures 256 texels wide in every view.
std::string writeUvSphereScene(const test::TempDir& dir) {
    test::writeTextFile(dir.file("ball.json"), R"({
      "camera": {"position_m": [0, 0, 0.5], "target_m": [0, 0, 0], "vertical_fov_deg": 30},
      "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1, "shadow": false}],
      "characters": [{"name": "ball", "mesh": {"procedural": "sphere"}, "material": {"profile": "skin"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0.05, 0.05, 0.05], "ts": {"min_size": 256, "max_size": 256}}
    })");
    return dir.file("ball.json");
}

constexpr int kUvAovWidth = 320;
constexpr int kUvAovHeight = 180;
constexpr int kUvAovTexels = 256;
// Texel rows of the procedural sphere's first and last ring of quads (32 rings).
constexpr int kUvSpherePoleTexels = kUvAovTexels / 32;

// Where a UV-space AOV shows uv: the unit square letterboxed in the frame, v up.
// Returns false for a pixel outside it; else the texel it shows.
bool uvLayoutTexelAt(int x, int row, glm::ivec2& texel) {
    const double side = std::min(kUvAovWidth, kUvAovHeight);
    const double u = (x + 0.5 - 0.5 * (kUvAovWidth - side)) / side;
    const double v = (kUvAovHeight - 1 - row + 0.5 - 0.5 * (kUvAovHeight - side)) / side;
    if (u < 0.0 || u >= 1.0 || v < 0.0 || v >= 1.0) return false;
    texel = glm::ivec2(static_cast<int>(u * kUvAovTexels), static_cast<int>(v * kUvAovTexels));
    return true;
}

double maxAbsDifference(const Image& a, const Image& b) {
    double most = a.texels.size() == b.texels.size() ? 0.0 : INFINITY;
    for (size_t i = 0; i < a.texels.size() && i < b.texels.size(); ++i) {
        for (int c = 0; c < 4; ++c) most = std::max(most, double(std::abs(a.texels[i][c] - b.texels[i][c])));
    }
    return most;
}

}  // namespace

TEST_F(TextureSpace, StretchAovShowsTheUvSpheresStretchMapInBothModes) {
    test::TempDir dir;
    const std::string scene = writeUvSphereScene(dir);
    load(scene, {"mode=ts"});
    const Image ts = render(Aov::Stretch, kUvAovWidth, kUvAovHeight);
    EXPECT_TRUE(pass("ts ball stretch")->executed);
    EXPECT_EQ(executedWithPrefix(summary(), "ts "), 1) << "only the stretch pass runs for this AOV";

    const double rMm = 1000.0 * kSphereRadiusM;
    double worstU = 0.0;
    double worstV = 0.0;
    double sumV = 0.0;
    int checked = 0;
    int inside = 0;
    int outsideNonZero = 0;
    int insideBad = 0;
    for (int row = 0; row < kUvAovHeight; ++row) {
        for (int x = 0; x < kUvAovWidth; ++x) {
            const glm::vec4 value = ts.at(x, row);
            glm::ivec2 texel;
            if (!uvLayoutTexelAt(x, row, texel)) {
                outsideNonZero += value != glm::vec4(0.0f) ? 1 : 0;
                continue;
            }
            ++inside;
            // The sphere's quads touching the poles are triangles in UV, so half
            // of their strips holds no chart: zero there, positive elsewhere.
            const bool poleStrip = texel.y < kUvSpherePoleTexels || texel.y >= kUvAovTexels - kUvSpherePoleTexels;
            const bool finite = std::isfinite(value.r) && std::isfinite(value.g);
            const bool positive = value.r > 0.0f && value.g > 0.0f;
            insideBad += !finite || value.r < 0.0f || value.g < 0.0f || value.b != 0.0f || value.a != 1.0f ? 1 : 0;
            insideBad += !poleStrip && !positive ? 1 : 0;
            const double theta = glm::pi<double>() * (texel.y + 0.5) / kUvAovTexels;
            if (theta < glm::radians(35.0) || theta > glm::radians(145.0)) continue;
            worstU = std::max(worstU, std::abs(value.r / (2.0 * glm::pi<double>() * rMm * std::sin(theta)) - 1.0));
            worstV = std::max(worstV, std::abs(value.g / (glm::pi<double>() * rMm) - 1.0));
            sumV += value.g;
            ++checked;
        }
    }
    std::printf("stretch AOV, %d pixels in the UV square, %d between 35 and 145 deg: worst error %.2f%% along u, "
                "%.2f%% along v; mean v %.1f mm per UV unit (pi r = %.1f)\n",
                inside, checked, 100.0 * worstU, 100.0 * worstV, sumV / std::max(checked, 1), glm::pi<double>() * rMm);
    EXPECT_EQ(inside, kUvAovHeight * kUvAovHeight);
    EXPECT_EQ(outsideNonZero, 0) << "the letterbox bars are empty";
    EXPECT_EQ(insideBad, 0) << "every texel is finite, >= 0, and positive away from the poles";
    EXPECT_GT(checked, inside / 2);
    EXPECT_LT(worstU, 0.05);
    EXPECT_LT(worstV, 0.05);

    // Screen-space mode shows the same map and runs no other texture-space pass.
    load(scene, {"mode=ss"});
    const Image ss = render(Aov::Stretch, kUvAovWidth, kUvAovHeight);
    EXPECT_EQ(maxAbsDifference(ss, ts), 0.0);
    EXPECT_EQ(executedWithPrefix(summary(), "ts "), 1);
    EXPECT_EQ(executedWithPrefix(summary(), "sss "), 0);
}

TEST_F(TextureSpace, IrradianceTextureAovIsLitOnTheChartInBothModes) {
    test::TempDir dir;
    const std::string scene = writeUvSphereScene(dir);
    load(scene, {"mode=ts"});
    const Image stretch = render(Aov::Stretch, kUvAovWidth, kUvAovHeight);
    const Image ts = render(Aov::IrradianceTexture, kUvAovWidth, kUvAovHeight);
    EXPECT_TRUE(pass("ts ball irradiance")->executed);
    EXPECT_FALSE(pass("ts ball gather")) << "the AOV declares only the passes it shows";

    // Chart texels (a positive stretch) have at least the ambient light, the
    // half facing the light much more; the others are empty.
    int chart = 0;
    int dark = 0;
    int lit = 0;
    int emptyLit = 0;
    double brightest = 0.0;
    for (int row = 0; row < kUvAovHeight; ++row) {
        for (int x = 0; x < kUvAovWidth; ++x) {
            glm::ivec2 texel;
            if (!uvLayoutTexelAt(x, row, texel)) continue;
            const glm::vec4 value = ts.at(x, row);
            const float lowest = std::min({value.r, value.g, value.b});
            if (stretch.at(x, row).g <= 0.0f) {
                emptyLit += lowest != 0.0f || std::max({value.r, value.g, value.b}) != 0.0f ? 1 : 0;
                continue;
            }
            ++chart;
            dark += !std::isfinite(lowest) || lowest <= 0.0f ? 1 : 0;
            lit += value.r > 0.2f ? 1 : 0;
            brightest = std::max(brightest, double(value.r));
        }
    }
    std::printf("irradiance-texture AOV: %d chart pixels, %d not positive, %d (%.0f%%) lit above 0.2 "
                "(red at most %.3f); %d lit pixels off the chart\n",
                chart, dark, lit, 100.0 * lit / std::max(chart, 1), brightest, emptyLit);
    EXPECT_GT(chart, kUvAovHeight * kUvAovHeight * 9 / 10);
    EXPECT_EQ(dark, 0);
    EXPECT_EQ(emptyLit, 0);
    EXPECT_GT(lit, chart / 4);
    EXPECT_LT(lit, 3 * chart / 4);
    EXPECT_GT(brightest, 0.5);

    load(scene, {"mode=ss"});
    const Image ss = render(Aov::IrradianceTexture, kUvAovWidth, kUvAovHeight);
    EXPECT_EQ(maxAbsDifference(ss, ts), 0.0);
    EXPECT_TRUE(pass("ts ball irradiance")->executed);
    EXPECT_EQ(executedWithPrefix(summary(), "sss "), 0);
}

TEST_F(TextureSpace, UvLayoutAovsAreBlackWithNoCharacterOnScreen) {
    test::TempDir dir;
    load(writeUvSphereScene(dir), {"mode=ts", "camera.target_m=[0,0,5]"});
    for (Aov aov : {Aov::Stretch, Aov::IrradianceTexture}) {
        const Image image = render(aov, 64, 36);
        float most = 0.0f;
        for (const glm::vec4& t : image.texels) most = std::max({most, std::abs(t.r), std::abs(t.g), std::abs(t.b)});
        EXPECT_EQ(most, 0.0f) << kAovs.name(aov);
    }
    EXPECT_EQ(executedWithPrefix(summary(), "ts "), 0);
}

namespace {

// Side by side in one frame: a 5 cm skin plane (character 0), the UV sphere
// (character 1, skin) and an opaque plane (character 2), under one
// directional light 45 degrees off the plane's normal, no shadows.
std::string writeCaptureScene(const test::TempDir& dir) {
    test::writeTextFile(dir.file("capture.json"), R"({
      "camera": {"position_m": [0, 0.6, 0.3], "target_m": [0, 0, 0], "vertical_fov_deg": 40},
      "lights": [{"type": "directional", "direction": [0, -0.70710678, -0.70710678], "intensity": 1.5, "shadow": false}],
      "characters": [
        {"name": "plane", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.05},
         "material": {"albedo": [0.8, 0.5, 0.3], "roughness": 0.3, "rho_s": 0.18, "profile": "skin"}},
        {"name": "ball", "mesh": {"procedural": "sphere"}, "transform": {"translation_m": [0.2, 0.1, 0]},
         "material": {"profile": "skin"}},
        {"name": "board", "mesh": {"procedural": "plane"}, "transform": {"translation_m": [-0.2, 0, 0], "scale": 0.05},
         "material": {"profile": "none"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0.05, 0.04, 0.03], "energy_conservation": true, "ssao": {"enabled": false},
                   "sss": {"mix": 0.5}}
    })");
    return dir.file("capture.json");
}

// Texels of a side x side UV square whose centre lies inside one of the mesh's
// UV triangles (1), outside all (0), or within `margin` texels of an edge (-1:
// the rasteriser's tie rules decide those).
std::vector<int> uvCoverage(const MeshData& mesh, int side, double margin) {
    std::vector<int> covered(static_cast<size_t>(side) * static_cast<size_t>(side), 0);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec2 p[3];
        for (int k = 0; k < 3; ++k) p[k] = glm::dvec2(mesh.vertices[mesh.indices[t + static_cast<size_t>(k)]].uv) * double(side);
        const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
        if (std::abs(area) < 1e-12) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].x, p[1].x, p[2].x}) - 1)));
        const int x1 = std::min(side - 1, static_cast<int>(std::ceil(std::max({p[0].x, p[1].x, p[2].x}) + 1)));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].y, p[1].y, p[2].y}) - 1)));
        const int y1 = std::min(side - 1, static_cast<int>(std::ceil(std::max({p[0].y, p[1].y, p[2].y}) + 1)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 c(x + 0.5, y + 0.5);
                double nearest = INFINITY;  // signed distance (texels) inside each edge
                for (int k = 0; k < 3; ++k) {
                    const glm::dvec2 a = p[k];
                    const glm::dvec2 b = p[(k + 1) % 3];
                    const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                    nearest = std::min(nearest, (area > 0 ? cross : -cross) / glm::length(b - a));
                }
                int& cell = covered[static_cast<size_t>(y) * static_cast<size_t>(side) + static_cast<size_t>(x)];
                if (nearest > margin) cell = 1;
                else if (nearest > -margin && cell == 0) cell = -1;
            }
        }
    }
    return covered;
}

}  // namespace

TEST_F(TextureSpace, CapturedIrradianceTexturesAreEachCharactersLightInItsLayout) {
    test::TempDir dir;
    const std::string scene = writeCaptureScene(dir);
    constexpr int kSide = 128;
    std::vector<Image> byMode[2];
    for (int m = 0; m < 2; ++m) {
        load(scene, {m == 0 ? "mode=ss" : "mode=ts"});
        const Image before = render(Aov::Diffuse, 160, 90);
        auto captured = mRenderer->captureIrradianceTextures(kSide);
        ASSERT_TRUE(captured.ok()) << captured.error().message();
        byMode[m] = std::move(*captured);
        // The next frame is the one it would have been.
        ASSERT_TRUE(mRenderer->renderFrame({160, 90, Aov::Diffuse}).ok());
        auto after = mRenderer->readOutput();
        ASSERT_TRUE(after.ok());
        EXPECT_EQ(maxAbsDifference(before, *after), 0.0) << "mode " << m;
    }
    const std::vector<Image>& images = byMode[1];
    ASSERT_EQ(images.size(), 3u);
    EXPECT_EQ(maxAbsDifference(byMode[0][0], images[0]), 0.0) << "the same texture in either mode";
    EXPECT_EQ(maxAbsDifference(byMode[0][1], images[1]), 0.0);
    EXPECT_TRUE(images[2].empty()) << "an opaque character has none";
    ASSERT_EQ(images[0].width, kSide);
    ASSERT_EQ(images[0].height, kSide);
    ASSERT_EQ(images[1].width, kSide);

    // The plane: E x albedo^mix, with E = ambient + radiance N.L (1 - rho_s
    // rho_dt(N.L, m)) (Chappuis 2011 §2.6), rho_dt by a quadrature four times
    // finer than the table the shader reads.
    const double nDotL = std::sqrt(0.5);
    const double rhoDt = ksDirectionalAlbedo(float(nDotL), 0.3f, RhoDtQuadrature{48, 32, 8});
    const glm::dvec3 ambient(0.05, 0.04, 0.03);
    const glm::dvec3 albedo(0.8, 0.5, 0.3);
    const glm::dvec3 expected = (ambient + 1.5 * nDotL * (1.0 - 0.18 * rhoDt)) * glm::sqrt(albedo);
    double worst = 0.0;
    int empty = 0;
    for (const glm::vec4& t : images[0].texels) {
        empty += t.a > 0.0f ? 0 : 1;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(t[c] / expected[c] - 1.0));
    }
    std::printf("captured plane, %d^2 texels: rho_dt %.5f, expected (%.4f %.4f %.4f), worst relative error %.5f, "
                "%d empty texels\n",
                kSide, rhoDt, expected.r, expected.g, expected.b, worst, empty);
    // The texture is RGBA16F (relative rounding 2^-11 = 4.9e-4); the shader's
    // energy table is 64^2 from a quadrature within 5e-4 of the integral,
    // read bilinearly (under 1e-3 of rho_dt here), times rho_s = 0.18. Without
    // the energy factor the plane would be 0.9% brighter, with the wrong
    // albedo power 20% or more off.
    EXPECT_LT(worst, 1.5e-3);
    EXPECT_EQ(empty, 0) << "the plane's layout covers the whole square";

    // The sphere: alpha > 0 exactly where its UV triangles cover a texel
    // centre (its pole quads are triangles in UV, so half of their strip is
    // empty); the light is its own, not the plane's.
    const std::vector<int> coverage = uvCoverage(makeSphereMesh(), kSide, 1e-3);
    int mismatched = 0;
    int emptySphere = 0;
    int checked = 0;
    for (size_t i = 0; i < coverage.size(); ++i) {
        if (coverage[i] < 0) continue;
        ++checked;
        const bool covered = images[1].texels[i].a > 0.0f;
        mismatched += covered != (coverage[i] == 1) ? 1 : 0;
        emptySphere += covered ? 0 : 1;
    }
    std::printf("captured sphere: %d of %d texels empty, %d differ from the UV triangles' coverage\n", emptySphere,
                checked, mismatched);
    EXPECT_GT(emptySphere, kSide);
    EXPECT_EQ(mismatched, 0);
    EXPECT_GT(maxAbsDifference(images[0], images[1]), 0.1);
}

namespace {

// The texel of a captured irradiance texture at UV `uv`, read bilinearly
// (texel (x, y) holds u = (x + 0.5) / side, v = (y + 0.5) / side).
glm::dvec3 bilinearTexel(const Image& image, glm::dvec2 uv) {
    const glm::dvec2 st = uv * glm::dvec2(image.width, image.height) - 0.5;
    const glm::ivec2 base = glm::ivec2(glm::floor(st));
    const glm::dvec2 f = st - glm::dvec2(base);
    glm::dvec3 sum(0.0);
    for (int k = 0; k < 4; ++k) {
        const glm::ivec2 texel = glm::clamp(base + glm::ivec2(k & 1, k >> 1), glm::ivec2(0),
                                            glm::ivec2(image.width - 1, image.height - 1));
        const double weight = ((k & 1) ? f.x : 1.0 - f.x) * ((k >> 1) ? f.y : 1.0 - f.y);
        sum += weight * glm::dvec3(glm::vec3(image.at(texel.x, texel.y)));
    }
    return sum;
}

}  // namespace

// The matched reference scatters the captured irradiance texture as the
// engine's own light (docs/reference.md), so a texel must hold the light the
// lighting pass gives the pixel that shows its point. On a bumpy plane seen
// with about 32 map texels per pixel, the pixel reads the normal map at a
// coarse mip level (the bumps average out) while the UV raster, 1024^2 over
// the 2048^2 map, would read it at level 1 (every bump lit on its own).
TEST_F(TextureSpace, CapturedIrradianceReadsTheMapsAsThePixelDoes) {
    test::TempDir dir;
    ASSERT_TRUE(saveImage(dir.file("bumps.png"), test::bumpNormalMap(2048, 32, 8.0f, 16.0f, 0.3f, 7u)).ok());
    test::writeTextFile(dir.file("bumpy.json"), R"({
      "camera": {"position_m": [0, 0.75, 1.05], "target_m": [0, 0, 0], "vertical_fov_deg": 30, "near_m": 0.1, "far_m": 5},
      "lights": [{"type": "directional", "direction": [0.6, -0.5, -0.62], "intensity": 1, "shadow": false}],
      "characters": [{"name": "bumpy", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.5},
                      "material": {"albedo": [1, 1, 1], "normal_map": "bumps.png", "roughness": 0.3, "rho_s": 0.18,
                                   "profile": "skin"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "ssao": {"enabled": false}, "transmittance": {"enabled": false}}
    })");
    constexpr int kWidth = 160;
    constexpr int kHeight = 90;
    load(dir.file("bumpy.json"));
    const Image pixels = render(Aov::Irradiance, kWidth, kHeight);
    auto captured = mRenderer->captureIrradianceTextures(1024);
    ASSERT_TRUE(captured.ok()) << captured.error().message();
    ASSERT_EQ(captured->size(), 1u);
    const Image& texture = (*captured)[0];

    // Each pixel's centre on the plane y = 0, and its UV: the procedural plane
    // puts (u - 0.5, 0, v - 0.5) x scale at UV (u, v).
    double squaredDifference = 0.0;
    double squaredPixel = 0.0;
    int compared = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const raytrace::Ray ray = reference::ReferenceRenderer::cameraRay(mScene->camera, kWidth, kHeight, x, y);
            if (!(ray.direction.y < 0.0f)) continue;
            const glm::dvec3 hit = glm::dvec3(ray.origin) - glm::dvec3(ray.direction) * (double(ray.origin.y) / ray.direction.y);
            const glm::dvec2 uv(hit.x / 0.5 + 0.5, hit.z / 0.5 + 0.5);
            if (glm::any(glm::lessThan(uv, glm::dvec2(0.05))) || glm::any(glm::greaterThan(uv, glm::dvec2(0.95)))) continue;
            const glm::dvec3 pixel = glm::dvec3(glm::vec3(pixels.at(x, y)));
            const glm::dvec3 texel = bilinearTexel(texture, uv);
            squaredDifference += glm::dot(texel - pixel, texel - pixel);
            squaredPixel += glm::dot(pixel, pixel);
            ++compared;
        }
    }
    ASSERT_GT(compared, 1000);
    const double relativeRmse = std::sqrt(squaredDifference / squaredPixel);
    std::printf("[ measured ] captured texel against the lighting pass's pixel, %d pixels: relative RMSE %.4f\n",
                compared, relativeRmse);
    // 0.07% measured (fp16, bilinear reads between the capture's texels, and
    // the G-buffer's quad derivatives against the projection's). Broken on
    // purpose: the texel's own gradients (level 1 of the map) give 39.8%; the
    // projection's gradients twice as long (one level coarser) 0.60%, half as
    // long 1.66%; the normal map's normal where the G-buffer (LEAN variants,
    // the default) takes the LEAN map's mean normal 0.48%. The bound sits
    // well under all four.
    EXPECT_LT(relativeRmse, 0.0025);
}

namespace {

// The analytic edge seen from half the height of AnalyticEdge.h's: 0.05 mm
// pixels at 320 x 180, so the planner picks 1024 texels for the 40 mm plane
// (0.039 mm each, Gaussian 0 two texels wide).
constexpr double kHalfEdgeHeightM = 0.5 * test::kEdgeHeightM;

// sum_i w_i Phi(x / (s sigma_i)) of the skin profile, per channel.
glm::dvec3 skinEdge(double xMm, double widthScale) {
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : skinProfile().gaussians()) {
        const double sigmaMm = widthScale * std::sqrt(double(g.varianceMm2));
        sum += glm::dvec3(g.weight) * (0.5 * std::erfc(-xMm / (sigmaMm * std::sqrt(2.0))));
    }
    return sum;
}

struct EdgeFit {
    double maxError = 0.0;              // largest |rendered - closed form| over the middle row, channels
    glm::dvec3 widthScale{0.0};         // per channel, the s of least squares, in steps of 0.001
};

EdgeFit fitEdge(const Image& diffuse) {
    const int row = diffuse.height / 2;
    const double mmPerPixel = 2.0 * kHalfEdgeHeightM * 1000.0 * std::tan(test::kEdgeFovDeg * M_PI / 360.0) / diffuse.height;
    std::vector<double> xMm;
    for (int x = 0; x < diffuse.width; ++x) xMm.push_back((x + 0.5 - diffuse.width / 2.0) * mmPerPixel);
    EdgeFit fit;
    glm::dvec3 bestSquares(INFINITY);
    for (int step = -100; step <= 100; ++step) {
        const double s = 1.0 + 0.001 * step;
        glm::dvec3 squares(0.0);
        for (int x = 0; x < diffuse.width; ++x) {
            const glm::dvec3 e = glm::dvec3(glm::vec3(diffuse.at(x, row))) - skinEdge(xMm[static_cast<size_t>(x)], s);
            squares += e * e;
            if (step == 0) fit.maxError = std::max({fit.maxError, std::abs(e.r), std::abs(e.g), std::abs(e.b)});
        }
        for (int c = 0; c < 3; ++c) {
            if (squares[c] < bestSquares[c]) {
                bestSquares[c] = squares[c];
                fit.widthScale[c] = s;
            }
        }
    }
    return fit;
}

}  // namespace

TEST_F(TextureSpace, FlatSkinEdgeIsTheExactDiffusionOfItsIrradiance) {
    // A black|white albedo step under straight light, mix 1: the irradiance
    // texture is an exact step, and texture space must give the closed form
    // sum_i w_i Phi(x / sigma_i). Rendered again with every width 5% off
    // (sss.width_scale), the same checks must fail.
    test::TempDir dir;
    const std::string scene = test::writeEdgeScene(dir);
    char camera[64];
    std::snprintf(camera, sizeof camera, "camera.position_m=[0,%.6f,0]", kHalfEdgeHeightM);
    EdgeFit fits[3];
    const double scales[3] = {1.0, 0.95, 1.05};
    for (int k = 0; k < 3; ++k) {
        load(scene, {"mode=ts", camera, "sss.width_scale=" + std::to_string(scales[k])});
        // The albedo map at level 0 (mip bias -16): the irradiance texture
        // reads it at the pixel's level, which would smooth the step over
        // a pixel's footprint (0.025 mm here, 1-1.7% of Gaussian 0's
        // variance) before the blurs this test measures.
        ASSERT_TRUE(mRenderer->renderFrame({320, 180, Aov::Diffuse, -16.0f}).ok());
        auto diffuse = mRenderer->readOutput();
        ASSERT_TRUE(diffuse.ok());
        fits[k] = fitEdge(*diffuse);
        std::printf("flat skin edge, widths x%.2f: max error %.4f of the step, fitted width scale %.3f %.3f %.3f (RGB)\n",
                    scales[k], fits[k].maxError, fits[k].widthScale.r, fits[k].widthScale.g, fits[k].widthScale.b);
    }
    // Texture space came to 0.0023 and 1.004-1.005 (docs/texture-space.md);
    // with every width 5% off, 0.0088 and 0.954-0.955 (narrow) or 0.0106 and 1.051-1.055 (wide).
    // The bounds sit between: a max error of 0.5% of the step (the goal is
    // 1%), a fitted width within 2%.
    const auto passes = [](const EdgeFit& f) {
        bool ok = f.maxError < 0.005;
        for (int c = 0; c < 3; ++c) ok = ok && std::abs(f.widthScale[c] - 1.0) < 0.02;
        return ok;
    };
    EXPECT_LT(fits[0].maxError, 0.005);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fits[0].widthScale[c], 1.0, 0.02) << "channel " << c;
    EXPECT_TRUE(passes(fits[0]));
    EXPECT_FALSE(passes(fits[1])) << "widths 5% narrow";
    EXPECT_FALSE(passes(fits[2])) << "widths 5% wide";
    EXPECT_LT(fits[1].widthScale.g, 0.98);
    EXPECT_GT(fits[2].widthScale.g, 1.02);
}

namespace {

// One character of two layers: a 4 cm quad facing the camera (+Z, u in
// [0, 0.45]) and, 3-8 mm behind it, front-facing fins turned almost edge-on
// to the camera (u in [0.55, 1], drawn after the quad). The fins are hidden,
// but their depth slope is so steep that the gather's slope-scaled depth
// margin reaches them: how lit pixels of the head scan showed the light of
// another part of the layout (docs/texture-space.md).
std::string writeHiddenFinsScene(const test::TempDir& dir) {
    std::vector<float> positions, normals, uvs;
    std::vector<uint16_t> indices;
    const auto quad = [&](const glm::vec3 corner[4], const glm::vec3& normal, float u0, float u1, float v0, float v1) {
        const auto base = static_cast<uint16_t>(positions.size() / 3);
        const glm::vec2 uv[4] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
        for (int k = 0; k < 4; ++k) {
            positions.insert(positions.end(), {corner[k].x, corner[k].y, corner[k].z});
            normals.insert(normals.end(), {normal.x, normal.y, normal.z});
            uvs.insert(uvs.end(), {uv[k].x, uv[k].y});
        }
        indices.insert(indices.end(), {base, uint16_t(base + 1), uint16_t(base + 2), base, uint16_t(base + 2), uint16_t(base + 3)});
    };
    const glm::vec3 front[4] = {{-0.02f, -0.02f, 0.0f}, {0.02f, -0.02f, 0.0f}, {0.02f, 0.02f, 0.0f}, {-0.02f, 0.02f, 0.0f}};
    quad(front, glm::vec3(0, 0, 1), 0.0f, 0.45f, 0.0f, 1.0f);
    const int kFins = 8;
    for (int f = 0; f < kFins; ++f) {
        // Tilted 4-11 degrees from edge-on, towards the camera.
        const float tilt = glm::radians(4.0f + float(f));
        const float y = -0.016f + 0.004f * float(f);
        const float rise = 0.005f * std::tan(tilt);
        const glm::vec3 fin[4] = {{-0.018f, y, -0.008f}, {0.018f, y, -0.008f}, {0.018f, y + rise, -0.003f},
                                  {-0.018f, y + rise, -0.003f}};
        const glm::vec3 normal = glm::normalize(glm::cross(fin[1] - fin[0], fin[3] - fin[0]));
        quad(fin, normal, 0.55f, 1.0f, float(f) / kFins, (float(f) + 0.8f) / kFins);
    }
    std::vector<unsigned char> bin;
    nlohmann::json doc;
    const auto view = [&](const void* data, size_t bytes) {
        const size_t offset = bin.size();
        bin.resize(offset + bytes + (4 - bytes % 4) % 4, 0);
        std::memcpy(bin.data() + offset, data, bytes);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        return doc["bufferViews"].size() - 1;
    };
    const auto accessor = [&](const std::vector<float>& v, int components, const char* type) {
        doc["accessors"].push_back({{"bufferView", view(v.data(), v.size() * 4)},
                                    {"componentType", 5126},
                                    {"count", v.size() / size_t(components)},
                                    {"type", type}});
        return doc["accessors"].size() - 1;
    };
    const size_t position = accessor(positions, 3, "VEC3");
    const size_t normal = accessor(normals, 3, "VEC3");
    const size_t uv = accessor(uvs, 2, "VEC2");
    doc["accessors"].push_back({{"bufferView", view(indices.data(), indices.size() * 2)},
                                {"componentType", 5123},
                                {"count", indices.size()},
                                {"type", "SCALAR"}});
    doc["asset"] = {{"version", "2.0"}};
    nlohmann::json primitive;
    primitive["attributes"] = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}};
    primitive["indices"] = doc["accessors"].size() - 1;
    doc["meshes"] = nlohmann::json::array({{{"primitives", nlohmann::json::array({primitive})}}});
    doc["nodes"] = {{{"mesh", 0}}};
    doc["buffers"] = {{{"byteLength", bin.size()}, {"uri", "layers.bin"}}};
    std::ofstream(dir.file("layers.bin"), std::ios::binary).write(reinterpret_cast<const char*>(bin.data()),
                                                                   static_cast<std::streamsize>(bin.size()));
    test::writeTextFile(dir.file("layers.gltf"), doc.dump());
    test::writeTextFile(dir.file("fins.json"), R"({
      "camera": {"position_m": [0, 0, 0.3], "target_m": [0, 0, 0], "vertical_fov_deg": 10},
      "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1, "shadow": true}],
      "characters": [{"name": "layers", "mesh": {"gltf": "layers.gltf"}, "metres_per_unit": 1,
                      "material": {"albedo": [0.8, 0.6, 0.5], "profile": "skin"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0.02, 0.02, 0.02], "ssao": {"enabled": false}, "transmittance": {"enabled": false}}
    })");
    return dir.file("fins.json");
}

// Pixels shown dark: a texture-space diffuse under a quarter of the screen
// space one and of the lighting pass's irradiance (each summed over RGB). The
// second keeps out shadowed pixels that screen space lights by blurring
// across a depth edge (the lower lip's shadow on the head scan).
int darkPixels(const Image& ts, const Image& ss, const Image& irradiance) {
    int dark = 0;
    for (size_t i = 0; i < ts.texels.size(); ++i) {
        const auto sum = [](const glm::vec4& c) { return c.r + c.g + c.b; };
        const float value = sum(ts.texels[i]);
        const bool isDark =
            sum(ss.texels[i]) > 0.05f && value < 0.25f * sum(ss.texels[i]) && value < 0.25f * sum(irradiance.texels[i]);
        if (isDark) {
            std::printf("  dark pixel (%zu, %zu): ts %.4f, ss %.4f, irradiance %.4f (RGB sums)\n", i % size_t(ts.width),
                        i / size_t(ts.width), value, sum(ss.texels[i]), sum(irradiance.texels[i]));
        }
        dark += isDark ? 1 : 0;
    }
    return dark;
}

}  // namespace

TEST_F(TextureSpace, HiddenLayersBehindTheVisibleSurfaceDoNotDarkenIt) {
    test::TempDir dir;
    const std::string scene = writeHiddenFinsScene(dir);
    load(scene, {"mode=ss"});
    const Image ss = render(Aov::Diffuse, 320, 180);
    const Image irradiance = render(Aov::Irradiance, 320, 180);
    load(scene, {"mode=ts"});
    const Image ts = render(Aov::Diffuse, 320, 180);
    int front = 0;
    for (const glm::vec4& e : irradiance.texels) front += e.r > 0.3f ? 1 : 0;
    const int dark = darkPixels(ts, ss, irradiance);
    std::printf("hidden fins: %d lit pixels of the front quad, %d shown dark\n", front, dark);
    EXPECT_GT(front, 15000);
    EXPECT_EQ(dark, 0);
}

// The procedural head's ears are closed plates whose roots are sunk into the
// skull: that surface lies inside the body, where no light enters, and the
// reference leaves it out as a donor. In a frame its texels of the
// irradiance texture must stay empty, so that the blurs leave them out too;
// the ear beside the junction took their dark light before (the default
// head's texture-space scatter error 1.11% -> 1.06%, docs/texture-space.md).
// The capture for the reference keeps them lit: a donor beside the junction
// reads texels within reach, and an empty one counts as no light (with them
// empty there too, the matched reference read 2.8 million empty texels and
// the default head's screen-space scatter error 0.97% -> 1.08%). Which
// vertices are inside comes from the reference's parity count
// (reference/SurfaceInterior.h), not from the engine's rays. A vertex whose
// triangles' corners are all inside must read empty in the frame's texture
// (the irradiance-texture AOV, 1024^2 as the texture) and lit in the
// capture; one whose corners are all outside covered in both, at the texel
// under its UV (junction vertices and those on a chart border either way).
// Measured: all 444 inside empty in the frame and 438 lit in the capture
// (6 texels their chart does not cover), 27,112 of 27,140 outside covered.
// Broken on purpose: without the shader's test 6 of 444 read empty in the
// frame; with the capture's texels empty too, 0 lit there. Both fail.
TEST_F(TextureSpace, SurfaceInsideTheBodyIsEmptyInTheFrameAndLitInTheCapture) {
    constexpr int kSide = 1024;
    load("default.json", {"mode=ts", "ts.min_size=1024", "ts.max_size=1024"});
    const Image frameTexture = render(Aov::IrradianceTexture, kSide, kSide);
    auto captured = mRenderer->captureIrradianceTextures(kSide);
    ASSERT_TRUE(captured.ok()) << captured.error().message();
    ASSERT_FALSE(captured->empty());
    const Image& capture = (*captured)[0];

    Result<Model> model = makeProceduralModel("head");
    ASSERT_TRUE(model) << model.error().message();
    const MeshData mesh = model->mesh;
    auto surface = reference::CharacterSurface::create(mScene->characters[0], std::move(*model));
    ASSERT_TRUE(surface.ok()) << surface.error().message();
    const reference::SurfaceInterior interior = reference::SurfaceInterior::build(*surface);
    // Per vertex: 1 all its triangles' corners inside, 0 all outside, -1 mixed.
    std::vector<int> inside(mesh.vertices.size(), -2);
    const float cornerWeights[3][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    for (size_t t = 0; t < mesh.indices.size() / 3; ++t) {
        int corners = 0;
        for (int k = 0; k < 3; ++k) corners += interior.buried(t, cornerWeights[k][0], cornerWeights[k][1]) ? 1 : 0;
        const int state = corners == 3 ? 1 : corners == 0 ? 0 : -1;
        for (int k = 0; k < 3; ++k) {
            int& v = inside[mesh.indices[3 * t + size_t(k)]];
            v = v == -2 ? state : v == state ? v : -1;
        }
    }
    // A vertex on a chart border may have its texel centre just outside its triangles.
    const UvLayout layout = analyseUvLayout(mesh, 1.0f);
    int buried = 0, buriedEmpty = 0, buriedCaptured = 0, outside = 0, outsideCovered = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (inside[v] < 0 || layout.borderDistance[v] == 0.0f) continue;
        const glm::vec2 uv = mesh.vertices[v].uv;
        const int x = std::clamp(int(uv.x * kSide), 0, kSide - 1);
        const int y = std::clamp(int(uv.y * kSide), 0, kSide - 1);
        const glm::vec4 shown = frameTexture.at(x, kSide - 1 - y);  // the AOV has v up
        const bool empty = std::max({shown.r, shown.g, shown.b}) == 0.0f;
        const bool captureCovered = capture.at(x, y).a > 0.0f;
        if (inside[v] == 1) {
            ++buried;
            buriedEmpty += empty ? 1 : 0;
            buriedCaptured += captureCovered ? 1 : 0;
        } else {
            ++outside;
            outsideCovered += !empty && captureCovered ? 1 : 0;
        }
    }
    std::printf("[ measured ] %d vertices inside the body: %d empty in the frame, %d lit in the capture; %d of %d "
                "outside covered in both\n",
                buried, buriedEmpty, buriedCaptured, outsideCovered, outside);
    EXPECT_GT(buried, 100);
    EXPECT_GE(buriedEmpty, buried * 95 / 100);
    EXPECT_GE(buriedCaptured, buried * 95 / 100);
    EXPECT_GE(outsideCovered, outside * 99 / 100);
}

// ctest: content
TEST_F(TextureSpace, HeadScanHasNoDarkPixels) {
    if (!std::filesystem::exists(test::sharedContentDir() + "/LeePerrySmith")) {
        GTEST_SKIP() << "../shared/content/LeePerrySmith is absent";
    }
    // The scene's framing at the head's real 0.045 m per unit (the scan's
    // README in ../shared/content) and at 0.025, where it looks smaller.
    for (const char* scale : {"characters.0.metres_per_unit=0.025", "characters.0.metres_per_unit=0.045"}) {
        load("lee_perry_smith.json", {"mode=ss", scale});
        const Image ss = render(Aov::Diffuse, 320, 180);
        const Image irradiance = render(Aov::Irradiance, 320, 180);
        load("lee_perry_smith.json", {"mode=ts", scale});
        const Image ts = render(Aov::Diffuse, 320, 180);
        const int dark = darkPixels(ts, ss, irradiance);
        std::printf("head scan, %s: %d pixels shown dark\n", scale, dark);
        EXPECT_EQ(dark, 0) << scale;
    }
}

namespace {

// A 10 cm skin bump without TEXCOORD_0 (the stress assets' no_uvs.gltf) beside
// the UV sphere, both lit from the camera's side.
std::string writeUvlessScene(const test::TempDir& dir) {
    EXPECT_TRUE(stress::writeStressAssets(dir.path().string()).ok());
    test::writeTextFile(dir.file("bare.json"), R"({
      "camera": {"position_m": [0, 0.25, 0.35], "target_m": [0, 0, 0], "vertical_fov_deg": 40},
      "lights": [{"type": "directional", "direction": [0, -0.6, -1], "intensity": 1, "shadow": true}],
      "characters": [
        {"name": "bare", "mesh": {"gltf": "no_uvs.gltf"}, "transform": {"translation_m": [-0.07, 0, 0]},
         "material": {"profile": "skin"}},
        {"name": "ball", "mesh": {"procedural": "sphere"}, "transform": {"translation_m": [0.08, 0.03, 0], "scale": 0.5},
         "material": {"profile": "skin"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0.05, 0.05, 0.05], "ssao": {"enabled": false}}
    })");
    return dir.file("bare.json");
}

}  // namespace

// plan/TsPlan.h: texture space cannot hold light for triangles without UV
// area, so a character without TEXCOORD_0 falls back to the screen-space
// chain in texture-space mode (issue: 26,413 of a UV-less sphere's 28,828
// pixels came out under a quarter of the screen-space value), while the other
// characters stay in texture space.
TEST_F(TextureSpace, CharacterWithoutUvsFallsBackToScreenSpace) {
    test::TempDir dir;
    const std::string scene = writeUvlessScene(dir);
    constexpr int kW = 160, kH = 90;
    // Variant c: LEAN runs in screen-space mode only, and its G-buffer's
    // roughness moves the diffuse's energy conservation by 3.5e-4.
    load(scene, {"sss.variant=c"});
    const Image ids = render(Aov::Object, kW, kH);
    const Image screen = render(Aov::Diffuse, kW, kH);
    load(scene, {"mode=ts", "sss.variant=c"});
    const Image texture = render(Aov::Diffuse, kW, kH);

    size_t bare = 0, ball = 0, dark = 0, ballDiffers = 0;
    double worst = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const int id = static_cast<int>(std::lround(ids.at(x, y).r));
            const glm::vec4 s = screen.at(x, y), t = texture.at(x, y);
            if (id == 2) {
                ++ball;
                if (std::abs(t.r - s.r) > 1e-3f * s.r) ++ballDiffers;
            }
            if (id != 1) continue;
            ++bare;
            if (t.r < 0.25f * s.r) ++dark;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(t[c] - s[c])) / std::max(double(s[c]), 1e-6));
        }
    }
    std::printf("[ measured ] %zu pixels of the UV-less bump: %zu under 1/4 of screen space, largest relative "
                "difference %.3g; the sphere (in texture space) differs at %zu of %zu\n",
                bare, dark, worst, ballDiffers, ball);
    ASSERT_GT(bare, 300u);
    ASSERT_GT(ball, 300u);
    EXPECT_EQ(dark, 0u);
    // Its pixels are the screen-space chain's, copied: the same passes on the
    // same inputs (measured: equal to the bit).
    EXPECT_LT(worst, 1e-6);
    // The sphere is still blurred in texture space, which differs from screen
    // space by more than 1e-3 over much of it.
    EXPECT_GT(ballDiffers, ball / 4);

    int bareSkipped = 0;
    for (const PassSummary& s : summary()) {
        if (s.name.rfind("ts bare", 0) == 0) {
            ++bareSkipped;
            EXPECT_FALSE(s.executed) << s.name;
            EXPECT_NE(s.culledBecause.find("falls back to screen space: 100% of its surface has no UV area"),
                      std::string::npos)
                << s.name << ": " << s.culledBecause;
        }
    }
    EXPECT_GE(bareSkipped, 4);
    EXPECT_TRUE(pass("ts ball gather") && pass("ts ball gather")->executed);
    EXPECT_GT(executedWithPrefix(summary(), "sss "), 0) << "the screen-space chain runs for the fall-back";
}
