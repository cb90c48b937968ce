#pragma once
// The viewer's window: GLFW with an OpenGL 4.5 core context (GL entry points
// loaded through the engine's glad loader) and Dear ImGui on top (its GLFW
// and OpenGL 3 backends, which load GL by themselves).

#include "core/Result.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace dermis::viewer {

struct KeyPress {
    int key;      // GLFW_KEY_*
    bool repeat;  // an auto-repeat of a held key
};

class ViewerWindow {
public:
    // Errors: no display ("run under X11/Wayland or xvfb-run"), or no 4.5 core context.
    static Result<std::unique_ptr<ViewerWindow>> open(int width, int height, const std::string& title, bool glDebug,
                                                      bool vsync);
    ~ViewerWindow();
    ViewerWindow(const ViewerWindow&) = delete;
    ViewerWindow& operator=(const ViewerWindow&) = delete;

    bool closeRequested() const;
    void beginFrame();  // polls events and starts an ImGui frame
    void drawUi();      // renders ImGui's draw data into the back buffer
    void present();     // swaps the buffers

    // Every key pressed since the last call. Kept here rather than read from
    // ImGui's key state, which (in 1.86) loses a press and release that fall
    // between two frames: at a few frames per second on llvmpipe, most do.
    std::vector<KeyPress> takeKeyPresses();

    glm::ivec2 framebufferSize() const;
    float uiScale() const;  // framebuffer pixels per ImGui unit (HiDPI)
    double time() const;    // seconds since GLFW started

private:
    ViewerWindow() = default;
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

    GLFWwindow* mWindow = nullptr;
    std::vector<KeyPress> mKeyPresses;
    bool mImGuiGlfw = false;
    bool mImGuiGl = false;
};

}  // namespace dermis::viewer
