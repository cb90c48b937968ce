// SSAO (passes/SsaoPass.h) on a sphere resting on a plane
// (content/scenes/ssao_contact.json). The test builds its own small graph:
// the G-buffer pass, addSsaoPasses and a read-back pass, so it checks the AO
// texture itself, and which passes ran, without the rest of the frame.
//
// Set DERMIS_SSAO_DUMP_DIR to a folder to get the AO images as PNGs.
#include "GlTestEnvironment.h"
#include "TestSupport.h"

#include "core/Image.h"
#include "gl/GlGraphBackend.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderProgram.h"
#include "gl/TexturePool.h"
#include "passes/GBufferPass.h"
#include "passes/SsaoPass.h"
#include "render/FrameContext.h"
#include "plan/FramePlan.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"
#include "scene/SceneLoader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

using namespace dermis;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
constexpr float kSphereRadiusM = 0.1f;  // procedural "sphere", resting on the plane at the origin
const glm::vec3 kSphereCentreM{0.0f, kSphereRadiusM, 0.0f};

struct AoImage {
    int width = 0;
    int height = 0;
    std::vector<float> texels;  // row 0 at the bottom (GL convention)
    GLuint texture = 0;         // the texture the AO was read from
    std::vector<graph::PassReport> reports;

    float at(int x, int y) const { return texels[static_cast<size_t>(y * width + x)]; }
    const graph::PassReport* report(const std::string& name) const {
        for (const graph::PassReport& r : reports) {
            if (r.name == name) return &r;
        }
        return nullptr;
    }
};

struct PatchStats {
    double mean = 0.0;
    double maxDeviationFromOne = 0.0;
    size_t count = 0;
};

class SsaoTest : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (HasFatalFailure()) return;
        load("ssao_contact.json");
        if (HasFatalFailure()) return;
        auto gbuffer = gl::buildProgram({"gbuffer.vert", "gbuffer.frag", {}, {}});
        ASSERT_TRUE(gbuffer.ok()) << gbuffer.error().message();
        mPrograms.gbuffer.withColours = std::move(*gbuffer);
        for (auto [member, vertex, fragment] :
             {std::tuple{&Programs::ssao, "fullscreen.vert", "ssao.frag"},
              std::tuple{&Programs::ssaoBlur, "fullscreen.vert", "ssao_blur.frag"}}) {
            auto program = gl::buildProgram({vertex, fragment, {}, {}});
            ASSERT_TRUE(program.ok()) << program.error().message();
            mPrograms.*member = std::move(*program);
        }
        mFrameUniforms = makeBuffer(sizeof(gpu::FrameBlock));
        mObjectUniforms = makeBuffer(sizeof(gpu::ObjectBlock));
        mCharacterUniforms = makeBuffer(sizeof(gpu::CharactersBlock));
        mPassUniforms = makeBuffer(kMaxPassBlockBytes);
        mEmptyVertexArray = gl::createVertexArray("test: empty vertex array");
        mWhite = gl::createTexture2D({1, 1, graph::TextureFormat::Rgba8}, "test: white");
        const unsigned char white[4] = {255, 255, 255, 255};
        glTextureSubImage2D(mWhite.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
        mBackend = std::make_unique<gl::GlGraphBackend>(mProfiler);
    }

    void load(const std::string& sceneFile) {
        auto scene = loadScene(test::contentScene(sceneFile));
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        mScene = std::make_unique<Scene>(std::move(*scene));
        auto models = loadSceneModels(*mScene);
        ASSERT_TRUE(models.ok()) << models.error().message();
        mGeometry = SceneGeometry(*models);
        auto gpuScene = GpuScene::create(*mScene, *models);
        ASSERT_TRUE(gpuScene.ok()) << gpuScene.error().message();
        mGpuScene = std::make_unique<GpuScene>(std::move(*gpuScene));
    }

    void TearDown() override {
        mBackend.reset();
        GlTest::TearDown();
    }

    static gl::Buffer makeBuffer(size_t bytes) {
        gl::Buffer buffer = gl::createBuffer("test: uniforms");
        glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
        return buffer;
    }

    glm::mat4 viewFromWorld() const { return glm::lookAt(mScene->camera.positionM, mScene->camera.targetM, mScene->camera.up); }
    glm::mat4 clipFromView() const {
        const Camera& camera = mScene->camera;
        return glm::perspective(glm::radians(camera.verticalFovDeg), float(kWidth) / float(kHeight), camera.nearM,
                                camera.farM);
    }

    void uploadUniforms() {
        gpu::FrameBlock frame{};
        frame.viewFromWorld = viewFromWorld();
        frame.worldFromView = glm::inverse(frame.viewFromWorld);
        frame.clipFromView = clipFromView();
        frame.viewFromClip = glm::inverse(frame.clipFromView);
        frame.clipFromWorld = frame.clipFromView * frame.viewFromWorld;
        frame.cameraPositionM = glm::vec4(mScene->camera.positionM, 1.0f);
        frame.viewportPx = glm::vec2(kWidth, kHeight);
        frame.pixelSizeUv = 1.0f / frame.viewportPx;
        frame.nearM = mScene->camera.nearM;
        frame.farM = mScene->camera.farM;
        frame.energyConservation = 1;
        frame.ssaoStrength = mScene->settings.ssao.strength;
        glNamedBufferSubData(mFrameUniforms.get(), 0, sizeof frame, &frame);

        // Per-character overrides go up as the scene has them (0 = the
        // shader's fallback to settings.ssao), so both paths are exercised.
        auto characters = std::make_unique<gpu::CharactersBlock>();
        for (size_t i = 0; i < mScene->characters.size(); ++i) {
            const CharacterSsao& ssao = mScene->characters[i].ssao;
            characters->characters[i + 1].ssaoRadiusM = ssao.radiusM;
            characters->characters[i + 1].ssaoSamples = float(ssao.samples);
        }
        glNamedBufferSubData(mCharacterUniforms.get(), 0, sizeof *characters, characters.get());

        glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_FRAME, mFrameUniforms.get());
        glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_OBJECT, mObjectUniforms.get());
        glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_CHARACTERS, mCharacterUniforms.get());
    }

    // The frame's plan (profile "none" everywhere: no SSS slot) and the GL
    // objects the G-buffer and SSAO passes draw with.
    void planTestFrame() {
        auto plan = planFrame(*mScene, mGeometry, {kWidth, kHeight, Aov::Final}, ShadowCache{});
        ASSERT_TRUE(plan.ok()) << plan.error().message();
        mPlan = std::make_unique<FramePlan>(std::move(*plan));
        mPlan->lean = false;  // the test builds the plain G-buffer program only
        mServices.gpuScene = mGpuScene.get();
        mServices.programs = &mPrograms;
        mServices.framebuffers = &mBackend->framebuffers();
        mServices.objectUniforms = mObjectUniforms.get();
        mServices.passUniforms = mPassUniforms.get();
        mServices.emptyVertexArray = mEmptyVertexArray.get();
        mServices.whiteTexture = mWhite.get();
    }

    // Renders the G-buffer and SSAO and reads back what addSsaoPasses returned.
    AoImage renderAo() {
        planTestFrame();
        uploadUniforms();
        const FrameContext frame{*mPlan, &mServices};
        mProfiler.beginFrame(mFrame++);

        AoImage image;
        graph::RenderGraph graph;
        const graph::TextureHandle white =
            graph.importTexture("white", {1, 1, graph::TextureFormat::Rgba8}, mServices.whiteTexture);
        const GBuffer gbuffer = addGBufferPass(graph, frame);
        const graph::TextureHandle ao = addSsaoPasses(graph, frame, gbuffer, white);
        struct ReadbackData {
            graph::TextureHandle ao;
        };
        graph.addPass<ReadbackData>(
            "read back",
            [&](graph::PassBuilder& builder, ReadbackData& d) {
                d.ao = builder.read(ao);
                builder.sideEffect();
            },
            [&image](const graph::PassResources& resources, const ReadbackData& d) {
                const graph::TextureDesc& desc = resources.desc(d.ao);
                image.width = static_cast<int>(desc.width);
                image.height = static_cast<int>(desc.height);
                image.texture = resources.texture(d.ao);
                image.texels.resize(static_cast<size_t>(image.width * image.height));
                glGetTextureImage(image.texture, 0, GL_RED, GL_FLOAT,
                                  static_cast<GLsizei>(image.texels.size() * sizeof(float)), image.texels.data());
            });
        const Status compiled = graph.compile();
        EXPECT_TRUE(compiled.ok()) << (compiled.ok() ? "" : compiled.error().message());
        if (!compiled.ok()) return image;
        graph.execute(*mBackend);
        mBackend->endFrame();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        mProfiler.drain();
        mProfiler.takeCompleted();
        image.reports = graph.passReports();
        return image;
    }

    // Pixel (x right, y up) where a world point lands.
    glm::ivec2 pixelOf(const glm::vec3& worldM) const {
        const glm::vec4 clip = clipFromView() * viewFromWorld() * glm::vec4(worldM, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return glm::ivec2((ndc * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight));
    }

    // Whether the camera sees this point on the plane, or the sphere hides it.
    bool sphereHides(const glm::vec3& pointM) const {
        const glm::vec3 eye = mScene->camera.positionM;
        const glm::vec3 direction = glm::normalize(pointM - eye);
        const glm::vec3 toCentre = kSphereCentreM - eye;
        const float along = glm::dot(toCentre, direction);
        const float missSquared = glm::dot(toCentre, toCentre) - along * along;
        return along > 0.0f && missSquared < kSphereRadiusM * kSphereRadiusM &&
               along < glm::length(pointM - eye);
    }

    // Plane points on an arc of `radiusM` around the contact point, on the
    // camera's side, that the sphere does not hide.
    std::vector<glm::ivec2> contactRingPixels(float radiusM) const {
        std::vector<glm::ivec2> pixels;
        for (int degrees = -80; degrees <= 80; degrees += 5) {
            const float a = glm::radians(float(degrees));
            const glm::vec3 point{radiusM * std::sin(a), 0.0f, radiusM * std::cos(a)};
            if (sphereHides(point)) continue;
            pixels.push_back(pixelOf(point));
        }
        return pixels;
    }

    static PatchStats patchStats(const AoImage& image, glm::ivec2 centre, int halfSize) {
        PatchStats stats;
        for (int y = centre.y - halfSize; y <= centre.y + halfSize; ++y) {
            for (int x = centre.x - halfSize; x <= centre.x + halfSize; ++x) {
                const float ao = image.at(x, y);
                stats.mean += ao;
                stats.maxDeviationFromOne = std::max(stats.maxDeviationFromOne, std::abs(1.0 - ao));
                ++stats.count;
            }
        }
        if (stats.count > 0) stats.mean /= double(stats.count);
        return stats;
    }

    static double meanAt(const AoImage& image, const std::vector<glm::ivec2>& pixels) {
        double sum = 0.0;
        for (const glm::ivec2& p : pixels) sum += image.at(p.x, p.y);
        return pixels.empty() ? 1.0 : sum / double(pixels.size());
    }

    static void dump(const AoImage& image, const std::string& name) {
        const char* dir = std::getenv("DERMIS_SSAO_DUMP_DIR");
        if (dir == nullptr || image.texels.empty()) return;
        Image png;
        png.width = image.width;
        png.height = image.height;
        png.colourSpace = ColourSpace::Srgb;
        png.texels.resize(image.texels.size());
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const float ao = image.at(x, image.height - 1 - y);
                png.at(x, y) = glm::vec4(ao, ao, ao, 1.0f);
            }
        }
        const Status saved = saveImage(std::string(dir) + "/" + name + ".png", png);
        EXPECT_TRUE(saved.ok()) << (saved.ok() ? "" : saved.error().message());
    }

    std::unique_ptr<Scene> mScene;
    SceneGeometry mGeometry;
    std::unique_ptr<GpuScene> mGpuScene;
    std::unique_ptr<FramePlan> mPlan;
    FrameServices mServices;
    Programs mPrograms;
    gl::GpuProfiler mProfiler;
    std::unique_ptr<gl::GlGraphBackend> mBackend;
    gl::Buffer mFrameUniforms;
    gl::Buffer mObjectUniforms;
    gl::Buffer mCharacterUniforms;
    gl::Buffer mPassUniforms;
    gl::VertexArray mEmptyVertexArray;
    gl::Texture mWhite;
    uint64_t mFrame = 0;
};

bool allFiniteInUnitRange(const AoImage& image, size_t* bad = nullptr) {
    size_t count = 0;
    for (float ao : image.texels) {
        if (!std::isfinite(ao) || ao < 0.0f || ao > 1.0f) ++count;
    }
    if (bad) *bad = count;
    return count == 0;
}

// Where the open plane is: far from the sphere (0.3 m beside it, more than
// 2x the AO radius from anything), well inside the plane's edges.
const glm::vec3 kOpenPlaneLeftM{-0.3f, 0.0f, 0.15f};
const glm::vec3 kOpenPlaneRightM{0.3f, 0.0f, 0.15f};
constexpr int kPatchHalfSizePx = 4;
constexpr float kContactRingRadiusM = 0.035f;
// Mean AO on that arc, measured at 320x180 with radius 0.05 m: 0.542 with 32
// samples, 0.547 with 8, 0.541 with 128 (blurred). The bounds leave margin
// both ways: clearly darker than the open plane, yet not black.
constexpr double kContactRingMaxAo = 0.70;
constexpr double kContactRingMinAo = 0.35;

}  // namespace

TEST_F(SsaoTest, OpenPlaneIsUnoccludedAndTheContactRingIsDark) {
    const AoImage image = renderAo();
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    dump(image, "ssao_blurred");
    size_t bad = 0;
    EXPECT_TRUE(allFiniteInUnitRange(image, &bad)) << bad << " texels are non-finite or outside [0, 1]";

    for (const glm::vec3& point : {kOpenPlaneLeftM, kOpenPlaneRightM}) {
        const PatchStats open = patchStats(image, pixelOf(point), kPatchHalfSizePx);
        std::printf("[ measured ] open plane at x = %.2f m: mean AO %.4f, max |1 - AO| %.4f\n", point.x, open.mean,
                    open.maxDeviationFromOne);
        EXPECT_NEAR(open.mean, 1.0, 0.02) << "open plane at x = " << point.x;
        EXPECT_LE(open.maxDeviationFromOne, 0.02) << "open plane at x = " << point.x;
    }

    const std::vector<glm::ivec2> ring = contactRingPixels(kContactRingRadiusM);
    ASSERT_GE(ring.size(), 10u);
    const double ringAo = meanAt(image, ring);
    std::printf("[ measured ] contact ring (r = %.3f m) mean AO %.3f over %zu pixels\n", kContactRingRadiusM, ringAo,
                ring.size());
    EXPECT_LT(ringAo, kContactRingMaxAo);
    EXPECT_GT(ringAo, kContactRingMinAo);
}

TEST_F(SsaoTest, RawAoWithoutBlurIsAlsoBoundedAndTheBlurPassIsSkipped) {
    mScene->settings.ssao.blur = false;
    const AoImage image = renderAo();
    dump(image, "ssao_raw");
    const graph::PassReport* blur = image.report("ssao blur");
    ASSERT_NE(blur, nullptr);
    EXPECT_FALSE(blur->executed);
    EXPECT_EQ(blur->reason, graph::CullReason::Predicate);
    const graph::PassReport* ssao = image.report("ssao");
    ASSERT_NE(ssao, nullptr);
    EXPECT_TRUE(ssao->executed);
    ASSERT_EQ(image.width, kWidth);
    EXPECT_TRUE(allFiniteInUnitRange(image));
    const PatchStats open = patchStats(image, pixelOf(kOpenPlaneLeftM), kPatchHalfSizePx);
    EXPECT_LE(open.maxDeviationFromOne, 0.02);
    EXPECT_LT(meanAt(image, contactRingPixels(kContactRingRadiusM)), kContactRingMaxAo);
}

TEST_F(SsaoTest, DisabledSsaoRunsNoPassAndYieldsWhite) {
    mScene->settings.ssao.enabled = false;
    const AoImage image = renderAo();
    for (const char* name : {"ssao", "ssao blur"}) {
        const graph::PassReport* report = image.report(name);
        ASSERT_NE(report, nullptr) << name;
        EXPECT_FALSE(report->executed) << name;
        EXPECT_EQ(report->reason, graph::CullReason::Predicate) << name;
    }
    EXPECT_EQ(image.texture, mWhite.get()) << "the AO handle should resolve to the imported white texture";
    ASSERT_EQ(image.texels.size(), 1u);
    EXPECT_EQ(image.texels[0], 1.0f);
}

TEST_F(SsaoTest, ZeroStrengthIsSkippedLikeDisabled) {
    mScene->settings.ssao.strength = 0.0f;
    const AoImage image = renderAo();
    const graph::PassReport* report = image.report("ssao");
    ASSERT_NE(report, nullptr);
    EXPECT_FALSE(report->executed);
    EXPECT_EQ(image.texture, mWhite.get());
}

TEST_F(SsaoTest, EightAndOneHundredTwentyEightSamplesBothWork) {
    for (Character& character : mScene->characters) character.ssao = CharacterSsao{};  // use settings.ssao
    for (int samples : {8, 128}) {
        mScene->settings.ssao.samples = samples;
        const AoImage image = renderAo();
        dump(image, "ssao_samples_" + std::to_string(samples));
        ASSERT_EQ(image.width, kWidth) << samples;
        EXPECT_TRUE(allFiniteInUnitRange(image)) << samples;
        const PatchStats open = patchStats(image, pixelOf(kOpenPlaneRightM), kPatchHalfSizePx);
        EXPECT_LE(open.maxDeviationFromOne, 0.02) << samples;
        const double ringAo = meanAt(image, contactRingPixels(kContactRingRadiusM));
        std::printf("[ measured ] %d samples: contact ring mean AO %.3f\n", samples, ringAo);
        EXPECT_LT(ringAo, kContactRingMaxAo) << samples;
        EXPECT_GT(ringAo, kContactRingMinAo) << samples;
    }
}

TEST_F(SsaoTest, BackgroundIsWhite) {
    const AoImage image = renderAo();
    ASSERT_EQ(image.width, kWidth);
    // The top corners look past the plane's far edge at the background.
    EXPECT_EQ(image.at(1, kHeight - 2), 1.0f);
    EXPECT_EQ(image.at(kWidth - 2, kHeight - 2), 1.0f);
}

TEST_F(SsaoTest, HeadAoIsFiniteAndOccludesSomewhere) {
    load("default.json");
    const AoImage image = renderAo();
    dump(image, "ssao_head");
    ASSERT_EQ(image.width, kWidth);
    size_t bad = 0;
    EXPECT_TRUE(allFiniteInUnitRange(image, &bad)) << bad << " texels are non-finite or outside [0, 1]";
    const float darkest = *std::min_element(image.texels.begin(), image.texels.end());
    EXPECT_LT(darkest, 0.9f);
}

TEST(SsaoBlock, CarriesTheSceneSettings) {
    SsaoSettings settings;
    settings.radiusM = 0.04f;
    settings.samples = 48;
    const gpu::SsaoBlock block = makeSsaoBlock(settings);
    EXPECT_EQ(block.radiusM, 0.04f);
    EXPECT_EQ(block.samples, 48.0f);
    EXPECT_EQ(block.biasFraction, kSsaoBiasFractionOfRadius);
    EXPECT_EQ(block.fadeEndRadii, kSsaoRangeFadeEndRadii);
    EXPECT_EQ(block.blurHalfWidthPx, kSsaoBlurHalfWidthPx);
    EXPECT_EQ(block.blurDepthTolerance, kSsaoBlurDepthTolerance);
}
