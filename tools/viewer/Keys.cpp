#include "viewer/Keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include <cmath>

namespace dermis::viewer {
namespace {

constexpr float kLightStepDeg = 5.0f;
constexpr float kCharacterStepDeg = 5.0f;

// How many times `key` went down (counting auto-repeats when `repeat`).
int pressed(const std::vector<KeyPress>& presses, int key, bool repeat = false) {
    int count = 0;
    for (const KeyPress& press : presses) {
        if (press.key == key && (repeat || !press.repeat)) ++count;
    }
    return count;
}

void rotateLight(Light& light, const glm::vec3& axis, float degrees, const glm::vec3& pivot) {
    const glm::mat3 rotation(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis));
    light.direction = rotation * light.direction;
    light.positionM = pivot + rotation * (light.positionM - pivot);
}

float wrapDegrees(float degrees) { return std::remainder(degrees, 360.0f); }

void cycleAov(ViewerState& state, int step, float cameraDistanceM) {
    const auto& choices = aovChoices();
    const int count = static_cast<int>(choices.size());
    int index = 0;
    for (int i = 0; i < count; ++i) {
        if (choices[static_cast<size_t>(i)].aov == state.aov) index = i;
    }
    state.setAov(choices[static_cast<size_t>(((index + step) % count + count) % count)].aov, cameraDistanceM);
}

}  // namespace

const std::vector<KeyHelp>& keyHelp() {
    static const std::vector<KeyHelp> kKeys = {
        {"0 - 9", "light N on/off"},
        {"a / d", "move light 0 left / right (about the vertical axis)"},
        {"w / s", "move light 0 up / down (about the horizontal axis)"},
        {"z", "specular on/off"},
        {"o", "shadows on/off"},
        {"b", "subsurface scattering on/off"},
        {"y", "transmittance on/off"},
        {"e", "ambient (environment) light on/off"},
        {"q", "SSAO on/off"},
        {"h / j", "turn the first character about the vertical / horizontal axis"},
        {"v", "view: single, A/B split, difference"},
        {"Space", "play / pause the animation (panel Animation)"},
        {"n / m", "previous / next AOV"},
        {"r", "reset the camera to the scene file's"},
        {"p", "screenshot (to the path in Save)"},
        {"F5", "reload the shaders"},
        {"Tab", "hide / show the panels"},
        {"Esc", "quit"},
    };
    return kKeys;
}

const std::vector<KeyHelp>& mouseHelp() {
    static const std::vector<KeyHelp> kMouse = {
        {"left drag", "orbit about the camera target"},
        {"right drag, shift + left drag", "pan"},
        {"wheel", "dolly towards / away from the target"},
        {"drag the divider", "move the A/B split"},
    };
    return kMouse;
}

void handleKeys(const std::vector<KeyPress>& presses, ViewerState& state, const Camera& camera,
                const std::vector<Scene*>& scenes) {
    if (ImGui::GetIO().WantTextInput) return;
    auto toggled = [&](int key) { return pressed(presses, key) % 2 == 1; };
    const float distance = glm::length(camera.positionM - camera.targetM);
    EffectSwitches& switches = state.switches;
    for (int digit = 0; digit <= 9; ++digit) {
        if (toggled(GLFW_KEY_0 + digit)) switches.toggleLight(static_cast<size_t>(digit));
    }
    if (toggled(GLFW_KEY_Z)) switches.specular = !switches.specular;
    if (toggled(GLFW_KEY_O)) switches.shadows = !switches.shadows;
    if (toggled(GLFW_KEY_B)) switches.sss = !switches.sss;
    if (toggled(GLFW_KEY_Y)) switches.transmittance = !switches.transmittance;
    if (toggled(GLFW_KEY_E)) switches.ambient = !switches.ambient;
    if (toggled(GLFW_KEY_Q)) switches.ssao = !switches.ssao;

    const glm::vec3 up = glm::normalize(camera.up);
    const glm::vec3 forward = glm::normalize(camera.targetM - camera.positionM);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const float lightYaw = kLightStepDeg * float(pressed(presses, GLFW_KEY_D, true) - pressed(presses, GLFW_KEY_A, true));
    const float lightPitch = kLightStepDeg * float(pressed(presses, GLFW_KEY_W, true) - pressed(presses, GLFW_KEY_S, true));
    const float turnY = kCharacterStepDeg * float(pressed(presses, GLFW_KEY_H, true));
    const float turnX = kCharacterStepDeg * float(pressed(presses, GLFW_KEY_J, true));
    for (Scene* scene : scenes) {
        if (!scene->lights.empty() && (lightYaw != 0.0f || lightPitch != 0.0f)) {
            Light& light = scene->lights[0];
            if (lightYaw != 0.0f) rotateLight(light, up, lightYaw, camera.targetM);
            if (lightPitch != 0.0f) rotateLight(light, right, lightPitch, camera.targetM);
        }
        if (!scene->characters.empty() && (turnX != 0.0f || turnY != 0.0f)) {
            glm::vec3& rotation = scene->characters[0].transform.rotationDeg;
            rotation = glm::vec3(wrapDegrees(rotation.x + turnX), wrapDegrees(rotation.y + turnY), rotation.z);
        }
    }

    if (toggled(GLFW_KEY_SPACE)) state.playing = !state.playing;
    for (int i = pressed(presses, GLFW_KEY_V); i > 0; --i) {
        state.mode = state.mode == ViewMode::Single  ? ViewMode::Split
                     : state.mode == ViewMode::Split ? ViewMode::Difference
                                                     : ViewMode::Single;
    }
    const int aovStep = pressed(presses, GLFW_KEY_M) - pressed(presses, GLFW_KEY_N);
    if (aovStep != 0) cycleAov(state, aovStep, distance);
    if (pressed(presses, GLFW_KEY_R)) state.requests.resetCamera = true;
    if (pressed(presses, GLFW_KEY_P)) state.requests.screenshot = true;
    if (pressed(presses, GLFW_KEY_F5)) state.requests.reloadShaders = true;
    if (toggled(GLFW_KEY_TAB)) state.showPanels = !state.showPanels;
    if (pressed(presses, GLFW_KEY_ESCAPE)) state.requests.quit = true;
}

}  // namespace dermis::viewer
