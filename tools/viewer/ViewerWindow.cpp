#include "viewer/ViewerWindow.h"

#include "gl/Gl.h"
#include "gl/GlContext.h"
#include "gl/GlDebug.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <utility>

namespace dermis::viewer {
namespace {

std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = description ? description : "GLFW error " + std::to_string(code);
}

void* glfwLoader(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string glfwDetail() { return gLastGlfwError.empty() ? "" : " (GLFW: " + gLastGlfwError + ")"; }

}  // namespace

Result<std::unique_ptr<ViewerWindow>> ViewerWindow::open(int width, int height, const std::string& title, bool glDebug,
                                                         bool vsync) {
    glfwSetErrorCallback(onGlfwError);
    if (glfwInit() != GLFW_TRUE) {
        return makeError("no display", "run under X11/Wayland or xvfb-run" + glfwDetail());
    }
    std::unique_ptr<ViewerWindow> window(new ViewerWindow());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, glDebug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // the frame arrives already sRGB-encoded
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    window->mWindow = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window->mWindow) return makeError("window", "no OpenGL 4.5 core context" + glfwDetail());
    glfwMakeContextCurrent(window->mWindow);
    glfwSetWindowUserPointer(window->mWindow, window.get());
    glfwSetKeyCallback(window->mWindow, onKey);  // before ImGui's backend, which chains to it
    if (const Status loaded = gl::loadGlFunctions(glfwLoader, "glfw"); !loaded.ok()) return loaded.error();
    if (glDebug) gl::enableDebugOutput();
    glfwSwapInterval(vsync ? 1 : 0);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is fixed by the viewer; nothing is written to the working directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    window->mImGuiGlfw = ImGui_ImplGlfw_InitForOpenGL(window->mWindow, true);
    window->mImGuiGl = window->mImGuiGlfw && ImGui_ImplOpenGL3_Init("#version 450");
    if (!window->mImGuiGl) return makeError("window", "Dear ImGui could not initialise its GLFW/OpenGL backends");
    return window;
}

ViewerWindow::~ViewerWindow() {
    if (mImGuiGl) ImGui_ImplOpenGL3_Shutdown();
    if (mImGuiGlfw) ImGui_ImplGlfw_Shutdown();
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
    if (mWindow) glfwDestroyWindow(mWindow);
    glfwTerminate();
}

void ViewerWindow::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window));
    if (self && key != GLFW_KEY_UNKNOWN && (action == GLFW_PRESS || action == GLFW_REPEAT)) {
        self->mKeyPresses.push_back({key, action == GLFW_REPEAT});
    }
}

std::vector<KeyPress> ViewerWindow::takeKeyPresses() { return std::exchange(mKeyPresses, {}); }

bool ViewerWindow::closeRequested() const { return glfwWindowShouldClose(mWindow) == GLFW_TRUE; }

void ViewerWindow::beginFrame() {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ViewerWindow::drawUi() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ViewerWindow::present() { glfwSwapBuffers(mWindow); }

glm::ivec2 ViewerWindow::framebufferSize() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(mWindow, &size.x, &size.y);
    return size;
}

float ViewerWindow::uiScale() const {
    int windowWidth = 0;
    int windowHeight = 0;
    glfwGetWindowSize(mWindow, &windowWidth, &windowHeight);
    return windowWidth > 0 ? static_cast<float>(framebufferSize().x) / static_cast<float>(windowWidth) : 1.0f;
}

double ViewerWindow::time() const { return glfwGetTime(); }

}  // namespace dermis::viewer
