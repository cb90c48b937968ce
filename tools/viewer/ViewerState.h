#pragma once
// What the viewer's panels and keys change besides the scenes: the view mode,
// the AOV and its display range, the effect switches, and requests (save,
// reload, copy) that the frame loop carries out at the right moment.

#include "plan/Aov.h"
#include "viewer/AovDisplay.h"
#include "viewer/EffectSwitches.h"
#include "viewer/SplitView.h"

#include <chrono>
#include <string>

namespace dermis::viewer {

enum class EditTarget { A, B, Both };

struct ViewerRequests {
    bool screenshot = false;
    bool saveScene = false;
    bool reloadShaders = false;
    bool resetCamera = false;
    bool copyAToB = false;
    bool copyBToA = false;
    bool clearTimings = false;
    bool quit = false;
};

// The Environment panel's own fields: the map file being typed, and why the
// latest source was not loaded.
struct EnvironmentEdit {
    bool fileChosen = false;  // "file..." picked in the source combo: the source changes on Enter
    std::string file;         // as typed; a relative path is from the current directory
    std::string error;        // the latest refused source; cleared by the next one applied
};

struct ViewerState {
    ViewMode mode = ViewMode::Single;
    EditTarget editTarget = EditTarget::A;
    Aov aov = Aov::Final;
    AovMapping aovMapping;
    float dividerFraction = 0.5f;  // of the scene area's width
    float differenceScale = 10.0f;
    EffectSwitches switches;
    bool showPanels = true;
    bool showProfiler = true;
    bool watchShaders = true;
    // The frame time both sides render at (FrameRequest::timeS), and playback.
    float timeS = 0.0f;
    bool playing = false;
    float playbackSpeed = 1.0f;

    std::string screenshotPath = "out/viewer.png";
    std::string sceneJsonPath = "out/viewer_scene.json";
    std::string message;  // the latest outcome of a save, a reload or a refused edit
    bool messageIsError = false;
    std::chrono::steady_clock::time_point messageTime;
    std::string shaderError;  // the latest failed shader reload; empty once they compile again
    std::string renderError;  // the latest failed frame
    EnvironmentEdit environment;

    ViewerRequests requests;

    bool comparing() const { return mode != ViewMode::Single; }
    void setAov(Aov aov, float cameraDistanceM);
    void report(std::string text, bool isError);
};

}  // namespace dermis::viewer
