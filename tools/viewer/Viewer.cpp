#include "viewer/Viewer.h"

#include "core/Log.h"
#include "gl/Gl.h"
#include "gl/GlDebug.h"
#include "gl/ShaderProgram.h"
#include "viewer/Keys.h"
#include "viewer/OrbitCamera.h"
#include "viewer/Overlay.h"
#include "viewer/Panels.h"
#include "viewer/ProfilerPanel.h"
#include "viewer/SceneJson.h"
#include "viewer/ScreenLayout.h"
#include "viewer/Screenshot.h"
#include "viewer/ShaderWatcher.h"
#include "viewer/Variant.h"
#include "viewer/ViewerState.h"
#include "viewer/ViewerWindow.h"
#include "viewer/ViewportInput.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>

namespace dermis::viewer {
namespace {

class Viewer {
public:
    Viewer(ViewerOptions options, std::unique_ptr<ViewerWindow> window, SplitView splitView)
        : mWindow(std::move(window)),
          mSplitView(std::move(splitView)),
          mA(std::move(options.sceneA)),
          mB(std::move(options.sceneB)),
          mInitialCamera(mA.edited().camera),
          mView(mInitialCamera),
          mOrbit(mInitialCamera),
          mWatcher(gl::shaderDirectory()),
          mFrames(options.frames),
          mScreenshotPath(options.screenshotPath),
          mGlDebug(options.glDebug) {
        mState.mode = options.mode;
        mState.showPanels = options.showPanels;
        mState.setAov(options.aov, mOrbit.distance());
        mState.switches.lights.resize(mA.edited().lights.size());
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        mRendererName = renderer ? renderer : "unknown GL";
    }

    Status run();

private:
    bool batch() const { return mFrames > 0; }
    Scene& panelScene() { return mState.comparing() && mState.editTarget == EditTarget::B ? mB.edited() : mA.edited(); }
    ScreenLayout layout() const;
    void buildUi(const ScreenLayout& layout);
    void settingsWindow(const UiRect& column);
    void profilerWindow(const ScreenLayout& layout);
    void shaderErrorWindow(const UiRect& area);
    void carryOutRequests();
    void reloadShaders();
    Status renderScene(const UiRect& area);
    void reportRefusedEnvironments();
    void present(const UiRect& area);

    // Declared first: destroyed last, after every GL object below.
    std::unique_ptr<ViewerWindow> mWindow;
    SplitView mSplitView;
    Variant mA;
    Variant mB;
    Camera mInitialCamera;
    Camera mView;  // the camera both sides render with: the orbit's eye and target, the lens from the panel
    OrbitCamera mOrbit;
    ViewportInput mInput;
    ShaderWatcher mWatcher;
    ViewerState mState;
    std::vector<SceneDifference> mDifferences;
    std::string mRendererName;
    glm::ivec2 mFrameSize{0};
    int mFrames = 0;
    std::string mScreenshotPath;
    bool mGlDebug = false;
    double mWallMs = 0.0;
    double mLastTime = 0.0;
    bool mProfilerDocked = false;  // last frame's layout (ScreenLayout.h)
};

ScreenLayout Viewer::layout() const {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    return layoutScreen(display.x, display.y, mState.showPanels, mState.showProfiler);
}

void Viewer::settingsWindow(const UiRect& column) {
    ImGui::SetNextWindowPos(ImVec2(column.x, column.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(column.width, column.height), ImGuiCond_Always);
    const std::string title = "Dermis  " + std::filesystem::path(mA.edited().path).filename().string() + "###settings";
    ImGui::Begin(title.c_str(), nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(ImGui::GetWindowWidth() * 0.52f);

    if (ImGui::CollapsingHeader("View and A/B", ImGuiTreeNodeFlags_DefaultOpen)) {
        viewPanel(mState, mA.edited(), mB.edited(), mDifferences, mOrbit.distance());
    }
    if (ImGui::CollapsingHeader("Effects (keys)", ImGuiTreeNodeFlags_DefaultOpen)) effectsPanel(mState, mA.edited());

    Scene& scene = panelScene();
    const bool mirror = mState.editTarget == EditTarget::Both;
    const Scene before = mirror ? scene : Scene{};
    if (mState.comparing()) {
        const char* side = mState.editTarget == EditTarget::A ? "A" : mState.editTarget == EditTarget::B ? "B" : "A and B";
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "The panels below edit %s.", side);
    }
    bool changed = false;
    std::string refused;
    if (hasOtherSettings(scene) && ImGui::CollapsingHeader("Mode and other settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= otherSettingsPanel(scene, refused);
    }
    if (ImGui::CollapsingHeader("Lights")) changed |= lightsPanel(scene);
    if (ImGui::CollapsingHeader("Environment")) changed |= environmentPanel(scene, mState.environment);
    if (ImGui::CollapsingHeader("Shadows")) changed |= shadowPanel(scene, refused);
    if (ImGui::CollapsingHeader("SSS", ImGuiTreeNodeFlags_DefaultOpen)) {
        const Variant& side = mState.comparing() && mState.editTarget == EditTarget::B ? mB : mA;
        changed |= sssPanel(scene, side.characterReports(), refused);
    }
    if (ImGui::CollapsingHeader("Transmittance")) changed |= transmittancePanel(scene.settings.transmittance);
    if (ImGui::CollapsingHeader("SSAO")) changed |= ssaoPanel(scene);
    if (ImGui::CollapsingHeader("Materials")) changed |= materialsPanel(scene);
    if (ImGui::CollapsingHeader("Characters")) changed |= charactersPanel(scene);
    if (ImGui::CollapsingHeader("Animation")) {
        const Variant& side = mState.comparing() && mState.editTarget == EditTarget::B ? mB : mA;
        changed |= animationPanel(mState, scene, side.geometry());
    }
    if (ImGui::CollapsingHeader("Frame")) changed |= framePanel(scene);
    if (!refused.empty()) mState.report("not applied: " + refused, true);
    if (mirror && changed) {
        if (const Status mirrored = mirrorEdit(before, scene, mB.edited()); !mirrored.ok()) {
            mState.report("B not updated: " + mirrored.error().message(), true);
        }
    }
    if (ImGui::CollapsingHeader("Camera")) cameraPanel(mView);
    if (ImGui::CollapsingHeader("Save")) savePanel(mState);
    if (ImGui::CollapsingHeader("Shaders", mState.shaderError.empty() ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        shaderPanel(mState, mWatcher.directory());
    }
    if (ImGui::CollapsingHeader("Keys and mouse")) keysPanel();
    ImGui::PopItemWidth();
    ImGui::End();
}

void Viewer::profilerWindow(const ScreenLayout& layout) {
    const UiRect& pane = layout.profiler;
    // Docked, it is a pane of the window (ScreenLayout.h); floating, the user
    // may move it, and it is placed again only when it stops being docked.
    const bool place = layout.profilerDocked || layout.profilerDocked != mProfilerDocked;
    mProfilerDocked = layout.profilerDocked;
    const ImGuiCond cond = place ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(ImVec2(pane.x, pane.y), cond);
    ImGui::SetNextWindowSize(ImVec2(pane.width, pane.height), cond);
    ImGui::SetNextWindowBgAlpha(layout.profilerDocked ? 1.0f : 0.8f);
    const ImGuiWindowFlags flags =
        layout.profilerDocked ? ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse : 0;
    if (ImGui::Begin("Profiler (GPU ms)", &mState.showProfiler, flags)) {
        std::vector<ProfiledSide> sides{{"A", &mA.history()}};
        if (mState.comparing() && mB.hasRenderer()) sides.push_back({"B", &mB.history()});
        profilerPanel(sides, mRendererName, mFrameSize.x, mFrameSize.y, mWallMs, mState.requests.clearTimings);
    }
    ImGui::End();
}

void Viewer::buildUi(const ScreenLayout& layout) {
    const UiRect& area = layout.scene;
    if (mState.showPanels) {
        settingsWindow(layout.settings);
        if (mState.showProfiler) profilerWindow(layout);
    }
    if (!mState.shaderError.empty()) shaderErrorWindow(area);
    drawOverlay(area, mState, mDifferences);
}

void Viewer::shaderErrorWindow(const UiRect& area) {
    // In front, at the bottom of the scene area, so whoever edits a shader sees why it failed.
    ImGui::SetNextWindowPos(ImVec2(area.x + kProfilerMargin, area.y + area.height - kProfilerMargin), ImGuiCond_Always,
                            ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(std::max(area.width - 2.0f * kProfilerMargin, 100.0f),
                                                                   std::max(area.height * 0.5f, 100.0f)));
    ImGui::SetNextWindowBgAlpha(0.9f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
    if (ImGui::Begin("Shader compile error: the previous programs stay in use", nullptr, flags)) {
        ImGui::PushTextWrapPos(std::max(area.width - 4.0f * kProfilerMargin, 100.0f));
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", mState.shaderError.c_str());
        ImGui::PopTextWrapPos();
        ImGui::TextDisabled("Fix the file and save: it reloads by itself (or F5).");
    }
    ImGui::End();
}

void Viewer::reloadShaders() {
    std::string error;
    for (Variant* variant : {&mA, &mB}) {
        if (const Status status = variant->reloadShaders(); !status.ok()) error = status.error().message();
    }
    mState.shaderError = error;
    mState.report(error.empty() ? "shaders reloaded" : "shader reload failed; the previous programs stay in use", !error.empty());
    if (!error.empty()) log::error(error);
}

void Viewer::carryOutRequests() {
    ViewerRequests& requests = mState.requests;
    if (requests.copyAToB) mB.edited() = mA.edited();
    if (requests.copyBToA) mA.edited() = mB.edited();
    if (requests.resetCamera) {
        mView = mInitialCamera;
        mOrbit = OrbitCamera(mInitialCamera);
    }
    if (requests.clearTimings) {
        mA.history().clear();
        mB.history().clear();
    }
    if (requests.saveScene) {
        const Status saved = saveSceneJson(panelScene(), mState.sceneJsonPath);
        mState.report(saved.ok() ? "wrote " + mState.sceneJsonPath : saved.error().message(), !saved.ok());
    }
    const bool watched = mState.watchShaders && mWatcher.poll();
    if (requests.reloadShaders || watched) reloadShaders();
    // The screenshot is taken later in the frame, once the UI is drawn.
    const bool screenshot = requests.screenshot;
    const bool quit = requests.quit;
    requests = ViewerRequests{};
    requests.screenshot = screenshot;
    requests.quit = quit;
}

Status Viewer::renderScene(const UiRect& area) {
    const float scale = mWindow->uiScale();
    mFrameSize = glm::ivec2(static_cast<int>(area.width * scale), static_cast<int>(area.height * scale));
    if (mFrameSize.x <= 0 || mFrameSize.y <= 0) return success();
    FrameRequest request{mFrameSize.x, mFrameSize.y, mState.aov};
    request.timeS = mState.timeS;
    if (const Status a = mA.render(request, mState.switches); !a.ok()) return a;
    if (mState.comparing()) {
        if (const Status b = mB.render(request, mState.switches); !b.ok()) return makeError("B", b.error().message());
    }
    return success();
}

void Viewer::reportRefusedEnvironments() {
    for (Variant* variant : {&mA, &mB}) {
        if (const std::optional<Error> refused = variant->takeRefusedEnvironment()) {
            mState.environment.error = refused->message();
            mState.report("render error: " + refused->message() + " (the previous environment stays)", true);
            log::error(refused->message());
        }
    }
}

void Viewer::present(const UiRect& area) {
    const glm::ivec2 framebuffer = mWindow->framebufferSize();
    const float scale = mWindow->uiScale();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebuffer.x, framebuffer.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (mState.renderError.empty() && mFrameSize.x > 0 && mFrameSize.y > 0) {
        const PixelRect pixels{static_cast<int>(area.x * scale), framebuffer.y - static_cast<int>((area.y + area.height) * scale),
                               mFrameSize.x, mFrameSize.y};
        DisplaySettings display;
        display.mode = mState.mode;
        display.dividerPx = mState.dividerFraction * static_cast<float>(mFrameSize.x);
        display.transform = mState.aovMapping.transform;
        display.range = mState.aovMapping.range;
        display.differenceScale = mState.differenceScale;
        mSplitView.draw(pixels, mA.outputTexture(), mState.comparing() ? mB.outputTexture() : 0, display);
    }
    mWindow->drawUi();
}

Status Viewer::run() {
    mLastTime = mWindow->time();
    for (int frame = 0; !mWindow->closeRequested() && !mState.requests.quit; ++frame) {
        mWindow->beginFrame();
        const ScreenLayout screen = layout();
        const UiRect& area = screen.scene;
        std::vector<Scene*> scenes{&mA.edited(), &mB.edited()};
        handleKeys(mWindow->takeKeyPresses(), mState, mView, scenes);
        mInput.update(area, mView.verticalFovDeg, mOrbit, mState);
        mDifferences = mState.comparing() ? diffScenes(mA.edited(), mB.edited()) : std::vector<SceneDifference>{};
        buildUi(screen);
        carryOutRequests();
        mOrbit.applyTo(mView);
        mA.edited().camera = mView;
        mB.edited().camera = mView;

        const Status rendered = renderScene(area);
        reportRefusedEnvironments();
        if (!rendered.ok() && batch()) return rendered;
        mState.renderError = rendered.ok() ? "" : rendered.error().message();
        present(area);

        const bool last = batch() && frame + 1 >= mFrames;
        if (last && mGlDebug) {
            gl::drainGlErrors();
            if (gl::debugErrorCount() > 0) {
                return makeError("OpenGL", std::to_string(gl::debugErrorCount()) + " error(s), last: " + gl::lastDebugError());
            }
        }
        const bool batchShot = last && !mScreenshotPath.empty();
        if (mState.requests.screenshot || batchShot) {
            const std::string path = batchShot ? mScreenshotPath : mState.screenshotPath;
            const glm::ivec2 size = mWindow->framebufferSize();
            const Status saved = saveScreenshot(path, size.x, size.y);
            if (batchShot && !saved.ok()) return saved;
            mState.report(saved.ok() ? "wrote " + path : saved.error().message(), !saved.ok());
            mState.requests.screenshot = false;
        }
        mWindow->present();
        const double now = mWindow->time();
        const double frameMs = (now - mLastTime) * 1000.0;
        mWallMs = mWallMs == 0.0 ? frameMs : 0.9 * mWallMs + 0.1 * frameMs;
        advanceAnimationTime(mState, static_cast<float>(now - mLastTime));
        mLastTime = now;
        if (last) break;
    }
    return success();
}

}  // namespace

Status runViewer(ViewerOptions options) {
    if (options.sceneA.characters.size() != options.sceneB.characters.size()) {
        return makeError("view", "the A and B scenes must have the same characters");
    }
    auto window = ViewerWindow::open(options.width, options.height, "Dermis: " + options.sceneA.path, options.glDebug,
                                     options.frames == 0);
    if (!window.ok()) return window.error();
    auto splitView = SplitView::create();
    if (!splitView.ok()) return splitView.error();
    Viewer viewer(std::move(options), std::move(*window), std::move(*splitView));
    return viewer.run();
}

}  // namespace dermis::viewer
