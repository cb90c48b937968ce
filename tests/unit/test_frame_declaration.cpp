// The real frame on the test backend, without GL: content scenes are loaded
// and planned (plan/FramePlan.h), the frame is declared
// (frame/FrameDeclaration.h) with 0 for every imported texture, and the
// graph is compiled but never executed. The tests read which passes run and
// why the others are culled, in the words of the timings JSON
// (describeCull), so what they assert is what `dermis render --timings`
// reports.
#include "TestSupport.h"

#include "graph/RenderGraph.h"
#include "frame/FrameDeclaration.h"
#include "plan/FramePlan.h"
#include "render/FrameTimings.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"
#include "scene/SceneLoader.h"
#include "scene/SssTechniques.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace dermis;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 90;

// Overrides that move the camera so that it sees none of the default scene.
const std::vector<std::string> kLookAway = {"camera.target_m=[0,0,5]"};
// The default head from 4.5 m: every Gaussian is under half a pixel.
const std::string kFarCamera = "camera.position_m=[1.6,0.3,4.2]";
// The default scene's back light moved to the camera's side.
const std::vector<std::string> kNoBackLight = {"lights.1.position_m=[0.25,0.12,0.6]",
                                               "lights.1.direction=[-0.4,-0.2,-0.9]"};

// The CPU meshes of a content scene, as the renderer loads them (the
// procedural head takes about a second): made once per scene file and process.
// Overrides in these tests move cameras, lights and settings, never meshes.
SceneGeometry geometryOf(const std::string& sceneFile, const Scene& scene) {
    static std::map<std::string, SceneGeometry> cache;
    auto found = cache.find(sceneFile);
    if (found == cache.end()) {
        auto models = loadSceneModels(scene);
        EXPECT_TRUE(models.ok()) << models.error().message();
        found = cache.emplace(sceneFile, models.ok() ? SceneGeometry(*models) : SceneGeometry{}).first;
    }
    return found->second;
}

// One scene, planned and declared frame after frame like the renderer does,
// with the shadow cache carried across frames.
class DeclaredFrames {
public:
    DeclaredFrames(const std::string& sceneFile, const std::vector<std::string>& overrides = {}) {
        auto scene = loadScene(test::contentScene(sceneFile), overrides);
        EXPECT_TRUE(scene.ok()) << scene.error().message();
        if (!scene.ok()) return;
        mScene = std::make_unique<Scene>(std::move(*scene));
        mGeometry = geometryOf(sceneFile, *mScene);
    }
    DeclaredFrames(Scene scene, SceneGeometry geometry)
        : mScene(std::make_unique<Scene>(std::move(scene))), mGeometry(std::move(geometry)) {}

    Scene& scene() { return *mScene; }
    // The last frame's plan.
    const FramePlan& plan() const { return mPlan; }

    // Plans, declares and compiles one frame; false (with a test failure) on an error.
    bool declare(Aov aov = Aov::Final) {
        mReports.clear();
        if (!mScene) return false;
        if (const Status loaded = loadEnvironment(*mScene, mGeometry); !loaded.ok()) {
            ADD_FAILURE() << loaded.error().message();
            return false;
        }
        auto plan = planFrame(*mScene, mGeometry, {kWidth, kHeight, aov}, mShadowCache);
        EXPECT_TRUE(plan.ok()) << plan.error().message();
        if (!plan.ok()) return false;
        graph::RenderGraph graph;
        declareFrame(graph, *plan, FrameInputs{});
        const Status compiled = graph.compile();
        EXPECT_TRUE(compiled.ok()) << compiled.error().message();
        if (!compiled.ok()) return false;
        // As the renderer does after running the graph.
        recordShadowMaps(*plan, graph, mShadowCache);
        mReports = graph.passReports();
        mPlan = std::move(*plan);
        return true;
    }

    bool declared(const std::string& name) const { return find(name) != nullptr; }
    bool executed(const std::string& name) const {
        const graph::PassReport* report = find(name);
        EXPECT_NE(report, nullptr) << "no pass named '" << name << "' in\n" << listing();
        return report && report->executed;
    }
    // The timings JSON's culled_because of the named pass ("" when it ran).
    std::string culledBecause(const std::string& name) const {
        const graph::PassReport* report = find(name);
        EXPECT_NE(report, nullptr) << "no pass named '" << name << "' in\n" << listing();
        return report ? describeCull(*report) : "(not declared)";
    }
    int executedWithPrefix(const std::string& prefix) const {
        int n = 0;
        for (const graph::PassReport& r : mReports) n += r.name.rfind(prefix, 0) == 0 && r.executed ? 1 : 0;
        return n;
    }
    int declaredWithPrefix(const std::string& prefix) const {
        int n = 0;
        for (const graph::PassReport& r : mReports) n += r.name.rfind(prefix, 0) == 0 ? 1 : 0;
        return n;
    }
    // The timings JSON's culled_because of every pass whose name starts with `prefix`.
    std::map<std::string, std::string> culledWithPrefix(const std::string& prefix) const {
        std::map<std::string, std::string> out;
        for (const graph::PassReport& r : mReports) {
            if (r.name.rfind(prefix, 0) == 0) out[r.name] = describeCull(r);
        }
        return out;
    }
    // Every pass and why it was culled, for failure messages.
    std::string listing() const {
        std::ostringstream out;
        for (const graph::PassReport& r : mReports) out << "  " << r.name << ": " << (r.executed ? "ran" : describeCull(r)) << "\n";
        return out.str();
    }

private:
    const graph::PassReport* find(const std::string& name) const {
        for (const graph::PassReport& r : mReports) {
            if (r.name == name) return &r;
        }
        return nullptr;
    }

    std::unique_ptr<Scene> mScene;
    SceneGeometry mGeometry;
    FramePlan mPlan;
    ShadowCache mShadowCache;
    std::vector<graph::PassReport> mReports;
};

// content/scenes/crowd.json's first `count` characters: the default head on
// screen, then heads behind the camera and beside the view. Every one is the
// procedural head, so default.json's CPU mesh stands in for each.
DeclaredFrames crowd(size_t count, const std::vector<std::string>& overrides = {}) {
    auto scene = loadScene(test::contentScene("crowd.json"), overrides);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    if (!scene.ok()) return DeclaredFrames(Scene{}, SceneGeometry{});
    scene->characters.resize(count);
    // Every character shares the one head, as the renderer's loader shares a model that characters
    // repeat (render/SceneLoading.h): copying its maps 32 times took most of these tests' time.
    static const std::shared_ptr<const Model> head = [] {
        auto models = loadSceneModels(*loadScene(test::contentScene("default.json")));
        EXPECT_TRUE(models.ok());
        return models.ok() ? std::make_shared<const Model>(std::move(models->front())) : nullptr;
    }();
    const SceneModels models(head ? count : 0, head);
    return DeclaredFrames(std::move(*scene), SceneGeometry(models));
}

}  // namespace

TEST(FrameDeclaration, DefaultSceneRunsTheWholeScreenSpaceChain) {
    DeclaredFrames frames("default.json");
    ASSERT_TRUE(frames.declare());
    for (const char* pass : {"gbuffer", "ssao", "ssao blur", "lighting", "back depth", "thin edges", "transmittance", "sss init",
                             "composite", "tonemap"}) {
        EXPECT_TRUE(frames.executed(pass)) << pass << "\n" << frames.listing();
    }
    EXPECT_EQ(frames.executedWithPrefix("shadow:light"), 2) << frames.listing();
    EXPECT_EQ(frames.declaredWithPrefix("ts "), 0);
    EXPECT_FALSE(frames.declared("aov"));
}

TEST(FrameDeclaration, NoSssOnScreenRunsNoSssPass) {
    DeclaredFrames frames("no_sss.json");
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.executedWithPrefix("sss"), 0) << frames.listing();
    EXPECT_EQ(frames.culledBecause("sss init"), "predicate: no SSS pixel on screen");
    EXPECT_EQ(frames.culledBecause("transmittance"), "predicate: no SSS pixel on screen");
    EXPECT_EQ(frames.culledBecause("thin edges"), "predicate: no SSS pixel on screen");
    EXPECT_TRUE(frames.executed("lighting"));
    EXPECT_TRUE(frames.executed("composite"));
}

// Pre-integrated skin shading scatters in the lighting pass: no SSS pass has
// work, and the lighting pass reads the G-buffer's scatter target (its slot
// and curvature), which it does not otherwise.
TEST(FrameDeclaration, PreintegratedSkinRunsNoSssPass) {
    DeclaredFrames frames("default.json", {"sss.technique=preintegrated"});
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.executedWithPrefix("sss"), 0) << frames.listing();
    EXPECT_EQ(frames.declaredWithPrefix("sss skin"), 0) << frames.listing();
    EXPECT_EQ(frames.culledBecause("sss init"),
              "predicate: no SSS slot on screen blurs (each scatters in the lighting pass or has every Gaussian under "
              "min_width_px)");
    EXPECT_TRUE(frames.executed("lighting"));
    EXPECT_TRUE(frames.executed("composite"));
}

// The registry's two halves agree (scene/SssTechniques.h and
// passes/SssTechniquePasses.cpp): every technique either runs SSS passes of
// its own after `sss init` or scatters in the lighting pass, never neither
// (a technique missing from the passes' list would leave its skin unblurred)
// and never both.
TEST(FrameDeclaration, EveryTechniqueBlursOrScattersInLighting) {
    for (const dermis::EnumEntry<dermis::SssTechnique>& technique : dermis::kSssTechniques) {
        DeclaredFrames frames("default.json", {"sss.technique=" + std::string(technique.name)});
        ASSERT_TRUE(frames.declare()) << technique.name;
        const int techniquePasses = frames.executedWithPrefix("sss") - (frames.executed("sss init") ? 1 : 0);
        if (dermis::sssTechniqueInfo(technique.value).scattersInLighting()) {
            EXPECT_EQ(techniquePasses, 0) << technique.name << "\n" << frames.listing();
        } else {
            EXPECT_GT(techniquePasses, 0) << technique.name << "\n" << frames.listing();
        }
    }
}

TEST(FrameDeclaration, OffScreenScreenSpaceCharacterRunsNoBlur) {
    DeclaredFrames frames("default.json", kLookAway);
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.executedWithPrefix("sss"), 0) << frames.listing();
    EXPECT_EQ(frames.culledBecause("sss init"), "predicate: no SSS pixel on screen");
    int horizontalBlurs = 0;
    for (const auto& [name, why] : frames.culledWithPrefix("sss skin g")) {
        if (name.back() != 'h') continue;  // a vertical pass is culled by its horizontal one
        ++horizontalBlurs;
        EXPECT_EQ(why, "predicate: no pixel of this profile on screen") << name;
    }
    EXPECT_EQ(horizontalBlurs, 6);
    EXPECT_EQ(frames.culledBecause("transmittance"), "predicate: no SSS pixel on screen");
}

TEST(FrameDeclaration, OffScreenTextureSpaceCharacterRunsNoTextureSpacePass) {
    std::vector<std::string> overrides = kLookAway;
    overrides.push_back("mode=ts");
    DeclaredFrames frames("default.json", overrides);
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.declaredWithPrefix("sss"), 0) << frames.listing();
    EXPECT_EQ(frames.culledBecause("ts init"), "predicate: no texture-space character on screen");
    const std::map<std::string, std::string> headPasses = frames.culledWithPrefix("ts head ");
    for (const auto& [name, why] : headPasses) EXPECT_EQ(why, "predicate: character off screen") << name;
    EXPECT_GT(headPasses.size(), 10u) << frames.listing();

    // The same view on the head: its passes run.
    DeclaredFrames onScreen("default.json", {"mode=ts"});
    ASSERT_TRUE(onScreen.declare());
    EXPECT_TRUE(onScreen.executed("ts init"));
    for (const char* step : {"stretch", "irradiance", "dilate", "gather"}) {
        EXPECT_TRUE(onScreen.executed(std::string("ts head ") + step)) << step << "\n" << onScreen.listing();
    }
    // Texture space adds the transmittance both modes share to its gathered light, unless the TSM carries it.
    EXPECT_TRUE(onScreen.executed("transmittance")) << onScreen.listing();
    DeclaredFrames withTsm("default.json", {"mode=ts", "ts.tsm=true"});
    ASSERT_TRUE(withTsm.declare());
    EXPECT_TRUE(withTsm.executed("ts head tsm")) << withTsm.listing();
    EXPECT_EQ(withTsm.declaredWithPrefix("transmittance"), 0) << withTsm.listing();
}

TEST(FrameDeclaration, GaussiansUnderTheMinimumWidthAreSkipped) {
    DeclaredFrames near("default.json");
    ASSERT_TRUE(near.declare());
    const int nearBlurs = near.executedWithPrefix("sss skin g");
    EXPECT_GT(nearBlurs, 0) << near.listing();
    EXPECT_LT(nearBlurs, 12) << near.listing();
    // Gaussian 0 (0.0064 mm^2) is under half a pixel at any ordinary distance.
    EXPECT_EQ(near.culledBecause("sss skin g0 h").rfind("predicate: ", 0), 0u);
    EXPECT_NE(near.culledBecause("sss skin g0 h").find("px wide at the nearest SSS pixel (< 0.5 px)"), std::string::npos);
    EXPECT_EQ(near.culledBecause("sss skin g0 v"), "input 'sss skin g0 h' not produced");
    EXPECT_TRUE(near.executed("sss skin g5 h"));
    EXPECT_TRUE(near.executed("sss skin g5 v"));

    DeclaredFrames far("default.json", {kFarCamera});
    ASSERT_TRUE(far.declare());
    EXPECT_EQ(far.executedWithPrefix("sss skin g"), 0) << far.listing();
    EXPECT_NE(far.culledBecause("sss skin g5 h").find("px wide at the nearest SSS pixel (< 0.5 px)"), std::string::npos);
    // Nothing blurs and the identity weight is the whole irradiance: the copy would change nothing.
    EXPECT_EQ(far.culledBecause("sss init"),
              "predicate: no SSS slot on screen blurs (each scatters in the lighting pass or has every Gaussian under "
              "min_width_px)");
}

// Both modes read the thin-edge passes; switched off, they are culled with
// their reason and the SSS passes read the 1x1 black stand-in.
TEST(FrameDeclaration, ThinEdgesRunInBothModesAndAreCulledWhenOff) {
    for (const char* mode : {"mode=ss", "mode=ts"}) {
        DeclaredFrames on("default.json", {mode});
        ASSERT_TRUE(on.declare());
        EXPECT_TRUE(on.executed("back depth")) << mode;
        EXPECT_TRUE(on.executed("thin edges")) << mode;
        DeclaredFrames off("default.json", {mode, "transmittance.thin_edges=false"});
        ASSERT_TRUE(off.declare());
        EXPECT_EQ(off.culledBecause("thin edges"), "predicate: thin edges disabled (settings.transmittance.thin_edges = false)")
            << mode;
        EXPECT_EQ(off.culledBecause("back depth"), "predicate: thin edges disabled (settings.transmittance.thin_edges = false)")
            << mode;
        EXPECT_GT(off.executedWithPrefix(std::string(mode) == "mode=ss" ? "sss skin" : "ts "), 0) << off.listing();
    }
}

TEST(FrameDeclaration, NoBackLightRunsNoTransmittance) {
    DeclaredFrames frames("default.json", kNoBackLight);
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.culledBecause("transmittance"), "predicate: no shadowed light behind an SSS character");
    EXPECT_GT(frames.executedWithPrefix("sss skin"), 0) << frames.listing();
}

TEST(FrameDeclaration, DisabledEffectsAreCulledWithTheirReason) {
    DeclaredFrames frames("default.json", {"ssao.enabled=false", "sss.enabled=false", "transmittance.enabled=false"});
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.culledBecause("thin edges"), "predicate: SSS disabled");
    EXPECT_EQ(frames.culledBecause("back depth"), "predicate: SSS disabled");
    EXPECT_EQ(frames.culledBecause("ssao"), "predicate: SSAO is disabled (settings.ssao.enabled = false)");
    EXPECT_EQ(frames.culledBecause("ssao blur"), "predicate: SSAO is disabled (settings.ssao.enabled = false)");
    EXPECT_EQ(frames.culledBecause("sss init"), "predicate: SSS disabled");
    EXPECT_EQ(frames.culledBecause("transmittance"), "predicate: transmittance disabled");
    EXPECT_EQ(frames.executedWithPrefix("sss"), 0) << frames.listing();
    EXPECT_TRUE(frames.executed("lighting"));

    // SSS off with the transmittance on, and in texture space: the passes say SSS is off, not that
    // nothing is on screen (a probe read "character off screen" with the head filling the frame).
    DeclaredFrames screen("default.json", {"sss.enabled=false"});
    ASSERT_TRUE(screen.declare());
    EXPECT_EQ(screen.culledBecause("transmittance"), "predicate: SSS disabled");
    DeclaredFrames texture("default.json", {"sss.enabled=false", "mode=ts"});
    ASSERT_TRUE(texture.declare());
    const std::map<std::string, std::string> headPasses = texture.culledWithPrefix("ts head ");
    EXPECT_GT(headPasses.size(), 10u) << texture.listing();
    for (const auto& [name, why] : headPasses) EXPECT_EQ(why, "predicate: SSS disabled") << name;
}

TEST(FrameDeclaration, CachedShadowMapIsCulledOnTheSecondFrame) {
    DeclaredFrames frames("default.json");
    ASSERT_TRUE(frames.declare());
    const std::vector<std::string> shadows = {"shadow:light0(dir)", "shadow:light1(spot)"};
    for (const std::string& pass : shadows) EXPECT_TRUE(frames.executed(pass)) << frames.listing();

    ASSERT_TRUE(frames.declare());
    for (const std::string& pass : shadows) {
        EXPECT_EQ(frames.culledBecause(pass), "predicate: light and casters unchanged since the cached map");
    }
    EXPECT_TRUE(frames.executed("lighting"));  // it reads the cached maps

    // A light that moves makes its own map stale, and only its own.
    frames.scene().lights[1].positionM += glm::vec3(0.01f, 0.0f, 0.0f);
    ASSERT_TRUE(frames.declare());
    EXPECT_FALSE(frames.executed("shadow:light0(dir)"));
    EXPECT_TRUE(frames.executed("shadow:light1(spot)"));
}

TEST(FrameDeclaration, PointLightShadowIsCachedLikeTheOthersAndAbsentWithoutShadow) {
    // edge.json's light as a shadowed point light: a cube-atlas shadow pass.
    DeclaredFrames frames("edge.json", {"lights.0.type=point", "lights.0.position_m=[-0.2,0.3,0]"});
    ASSERT_TRUE(frames.declare());
    EXPECT_TRUE(frames.executed("shadow:light0(point)")) << frames.listing();
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.culledBecause("shadow:light0(point)"), "predicate: light and casters unchanged since the cached map");
    // A point light without a shadow has no shadow pass at all.
    frames.scene().lights[0].castsShadow = false;
    ASSERT_TRUE(frames.declare());
    EXPECT_EQ(frames.declaredWithPrefix("shadow:"), 0) << frames.listing();
}

TEST(FrameDeclaration, AnAovCullsTheLightingChain) {
    DeclaredFrames frames("default.json");
    ASSERT_TRUE(frames.declare(Aov::Albedo));
    EXPECT_TRUE(frames.executed("gbuffer"));
    EXPECT_TRUE(frames.executed("aov"));
    for (const char* pass : {"lighting", "ssao", "ssao blur", "shadow:light0(dir)", "shadow:light1(spot)"}) {
        EXPECT_EQ(frames.culledBecause(pass), "nothing reads its output") << pass;
    }
    EXPECT_FALSE(frames.declared("composite"));
    EXPECT_EQ(frames.declaredWithPrefix("sss"), 0);

    // A shadow map that did not run is not cached: the final frame renders it.
    ASSERT_TRUE(frames.declare(Aov::Final));
    EXPECT_TRUE(frames.executed("shadow:light0(dir)")) << frames.listing();
}

TEST(FrameDeclaration, OffScreenCharactersAreCulledFromTheGBufferTextureSpaceAndShadowMaps) {
    DeclaredFrames frames = crowd(32, {"mode=ts"});
    ASSERT_TRUE(frames.declare());
    const FramePlan& plan = frames.plan();
    ASSERT_EQ(plan.characters.size(), 32u);
    EXPECT_TRUE(plan.characters[0].visible);
    EXPECT_EQ(plan.characters[0].culledBecause, "");
    for (size_t c = 1; c < plan.characters.size(); ++c) {
        const std::string& name = frames.scene().characters[c].name;
        EXPECT_FALSE(plan.characters[c].visible) << name;
        // The G-buffer draws only visible characters (passes/GBufferPass.cpp).
        EXPECT_EQ(plan.characters[c].culledBecause, name.rfind("behind", 0) == 0 ? "off screen: behind the camera or nearer than the near plane"
                                                                               : "off screen: left of the view")
            << name;
        EXPECT_EQ(frames.culledBecause("ts " + name + " irradiance"), "predicate: character off screen");
    }
    EXPECT_TRUE(frames.executed("ts head irradiance"));

    // Both maps hold the head alone: no other character can shade it.
    ASSERT_EQ(plan.shadows.size(), 2u);
    for (const ShadowSlotPlan& shadow : plan.shadows) {
        EXPECT_EQ(shadow.casters.kept, std::vector<int>{0}) << shadow.passName;
        ASSERT_EQ(shadow.casters.culledBecause.size(), 32u);
        EXPECT_EQ(shadow.casters.culledBecause[0], "");
        const std::string why = shadow.passName == "shadow:light0(dir)"
                                    ? "its light-space footprint meets no visible character's, or lies beyond them"
                                    : "it is outside every visible character's shadow volume from the light";
        for (size_t c = 1; c < 32; ++c) EXPECT_EQ(shadow.casters.culledBecause[c], why) << shadow.passName << " " << c;
    }
}

TEST(FrameDeclaration, ShadowMapsAreFittedToTheVisibleCharactersAlone) {
    // The head's lights are those of the head alone: its maps are the same maps.
    DeclaredFrames alone = crowd(1);
    DeclaredFrames withCrowd = crowd(32);
    ASSERT_TRUE(alone.declare());
    ASSERT_TRUE(withCrowd.declare());
    ASSERT_EQ(alone.plan().shadows.size(), withCrowd.plan().shadows.size());
    for (size_t slot = 0; slot < alone.plan().shadows.size(); ++slot) {
        EXPECT_EQ(alone.plan().shadows[slot].key, withCrowd.plan().shadows[slot].key) << slot;
    }

    // A head behind the visible one, towards the sun, shades it: it is kept,
    // and the directional map's depth range reaches back to it.
    const glm::vec3 towardsSun = -glm::normalize(withCrowd.scene().lights[0].direction);
    withCrowd.scene().characters[1].transform.translationM = 1.5f * towardsSun;
    ASSERT_TRUE(withCrowd.declare());
    EXPECT_EQ(withCrowd.plan().shadows[0].casters.kept, (std::vector<int>{0, 1}));
    EXPECT_FALSE(withCrowd.plan().characters[1].visible) << withCrowd.plan().characters[1].culledBecause;
    const gpu::GpuLight& sun = withCrowd.plan().lights.block.lights[0];
    const gpu::GpuLight& sunAlone = alone.plan().lights.block.lights[0];
    const Bounds& caster = withCrowd.plan().characters[1].worldBounds;
    for (const glm::vec3 corner : {caster.min, caster.max}) {
        EXPECT_GE(glm::dot(corner - sun.positionM, sun.direction), sun.shadowNearM);
    }
    EXPECT_EQ(sun.shadowTexelM, sunAlone.shadowTexelM);  // the same texels: the box is the head's
    // With nothing on screen, no map is drawn.
    DeclaredFrames away = crowd(1, kLookAway);
    ASSERT_TRUE(away.declare());
    EXPECT_EQ(away.culledBecause("shadow:light0(dir)"), "predicate: no character on screen to receive its shadow");
}

TEST(FrameDeclaration, AnOffScreenCharacterThatMovesKeepsTheCachedShadowMaps) {
    DeclaredFrames frames = crowd(8);
    const std::vector<std::string> shadows = {"shadow:light0(dir)", "shadow:light1(spot)"};
    ASSERT_TRUE(frames.declare());
    for (const std::string& pass : shadows) EXPECT_TRUE(frames.executed(pass)) << frames.listing();

    frames.scene().characters[3].transform.translationM += glm::vec3(0.1f, 0.05f, 0.2f);
    ASSERT_TRUE(frames.declare());
    for (const std::string& pass : shadows) {
        EXPECT_EQ(frames.culledBecause(pass), "predicate: light and casters unchanged since the cached map") << pass;
    }
    // The visible head moving makes both maps stale.
    frames.scene().characters[0].transform.translationM += glm::vec3(0.01f, 0.0f, 0.0f);
    ASSERT_TRUE(frames.declare());
    for (const std::string& pass : shadows) EXPECT_TRUE(frames.executed(pass)) << pass;
}
