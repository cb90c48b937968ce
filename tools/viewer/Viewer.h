#pragma once
// `dermis view`: an interactive window on a scene with live settings, an A/B
// split or difference view of two variants, AOVs, a live GPU profiler,
// screenshots, saving the settings as a scene file and shader hot reload.
// With `frames` > 0 it renders that many frames, optionally saves a
// screenshot of the whole window, and returns (for tests and docs).

#include "core/Result.h"
#include "plan/Aov.h"
#include "scene/Scene.h"
#include "viewer/SplitView.h"

#include <string>

namespace dermis::viewer {

struct ViewerOptions {
    Scene sceneA;
    Scene sceneB;  // the B side of the comparison; usually A with a few changes
    int width = 1280;
    int height = 800;
    int frames = 0;              // > 0: batch mode
    std::string screenshotPath;  // batch mode: the window after the last frame, as PNG
    ViewMode mode = ViewMode::Single;
    Aov aov = Aov::Final;
    bool showPanels = true;
    bool glDebug = false;  // a debug context; in batch mode any GL error fails the run
};

Status runViewer(ViewerOptions options);

}  // namespace dermis::viewer
