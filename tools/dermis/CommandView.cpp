// dermis view: the interactive viewer (tools/viewer/).
#include "Args.h"
#include "Commands.h"
#include "measure/Session.h"

#include "core/Log.h"
#include "core/Suggest.h"
#include "plan/Aov.h"
#include "frame/Renderer.h"
#include "scene/SceneLoader.h"
#include "viewer/Viewer.h"

#include <cstdio>
#include <filesystem>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis view SCENE [options]\n"
    "\n"
    "Opens a window on SCENE (a JSON scene file, see content/scenes/README.md) with an orbit\n"
    "camera, panels for every setting, an A/B split or difference view of two variants of the\n"
    "scene, AOVs, a live per-pass GPU profiler, screenshots, saving the settings as a scene\n"
    "file, and shader hot reload. Press the \"Keys and mouse\" panel for the controls.\n"
    "Needs a display: X11, or a virtual one (xvfb-run -a dermis view ...).\n"
    "\n"
    "options:\n"
    "  --size WxH          window size in pixels (default 1280x800)\n"
    "  --set PATH=VALUE    override a scene value (both sides), checked like the file;\n"
    "                      repeatable: --set sss.taps=13 (see dermis render --help)\n"
    "  --set-b PATH=VALUE  override a value of the B side only: --set-b sss.blur=control\n"
    "  --view MODE         single, split (A|B with a divider) or diff (|A - B| in false\n"
    "                      colour) (default single)\n"
    "  --aov NAME          the component shown (default final), as for dermis render:\n"
    "%s"
    "                      stretch and irradiance-texture: the first SSS character on screen\n"
    "                      in its UV layout (the unit square, letterboxed, v up), either mode\n"
    "  --no-panels         start with the panels hidden (key Tab shows them)\n"
    "  --frames N          batch mode: render N frames, then exit\n"
    "  --screenshot FILE   batch mode: after the last frame, save the whole window (panels\n"
    "                      included) as a PNG; without --frames, 30 frames are rendered\n"
    "  --gl-debug          GL debug context; in batch mode any driver error fails the run\n"
    "  --quiet             no progress (warnings still print)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene, its content, the display or the GL context\n"
    "fails, 2 for bad command-line usage.\n";

constexpr int kDefaultScreenshotFrames = 30;

Result<viewer::ViewMode> parseViewMode(const std::string& name) {
    if (name == "single") return viewer::ViewMode::Single;
    if (name == "split") return viewer::ViewMode::Split;
    if (name == "diff") return viewer::ViewMode::Difference;
    return makeError("--view " + name, "expected single, split or diff" + didYouMean(name, {"single", "split", "diff"}));
}

// An error caused by one of the B side's overrides names it as the user wrote it.
Error nameBOverride(Error error, const std::vector<std::string>& bOverrides) {
    for (const std::string& text : bOverrides) {
        if (error.where == "--set " + text) error.where = "--set-b " + text;
    }
    return error;
}

}  // namespace

int runView(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"size", "set", "set-b", "view", "aov", "frames", "screenshot"},
                          {"no-panels", "gl-debug", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    log::setQuiet(args->flags.count("quiet") > 0);
    if (args->flags.count("help")) {
        std::printf(kHelp, kAovs.helpLines("                        ").c_str());
        return 0;
    }
    if (args->positional.size() != 1) return usageError(makeError("view", "expected exactly one SCENE file"));
    const std::string scenePath = args->positional[0];

    auto size = parseSize(args->get("size", "1280x800"), kMaxFrameDimension);
    if (!size.ok()) return usageError(size.error());
    auto mode = parseViewMode(args->get("view", "single"));
    if (!mode.ok()) return usageError(mode.error());
    auto aov = kAovs.parse(args->get("aov", "final"));
    if (!aov)
        return usageError(makeError("--aov " + args->get("aov", ""),
                                    "expected one of " + kAovs.list() + didYouMean(args->get("aov", ""), kAovs.names())));
    int frames = 0;
    if (args->has("frames")) {
        auto parsed = parsePositiveInt("--frames", args->get("frames", ""));
        if (!parsed.ok()) return usageError(parsed.error());
        frames = *parsed;
    }
    const std::string screenshot = args->get("screenshot", "");
    if (args->has("screenshot")) {
        if (std::filesystem::path(screenshot).extension() != ".png") {
            return usageError(makeError("--screenshot " + screenshot, "the file must end in .png"));
        }
        if (frames == 0) frames = kDefaultScreenshotFrames;
    }

    const std::vector<std::string> overrides = args->all("set");
    std::vector<std::string> overridesB = overrides;
    for (const std::string& text : args->all("set-b")) overridesB.push_back(text);
    auto sceneA = loadScene(scenePath, overrides);
    if (!sceneA.ok()) return failure(sceneA.error());
    auto sceneB = loadScene(scenePath, overridesB);
    if (!sceneB.ok()) return failure(nameBOverride(sceneB.error(), args->all("set-b")));

    viewer::ViewerOptions options;
    options.sceneA = std::move(*sceneA);
    options.sceneB = std::move(*sceneB);
    options.width = size->first;
    options.height = size->second;
    options.frames = frames;
    options.screenshotPath = screenshot;
    options.mode = *mode;
    options.aov = *aov;
    options.showPanels = args->flags.count("no-panels") == 0;
    options.glDebug = args->flags.count("gl-debug") > 0;
    if (const Status status = viewer::runViewer(std::move(options)); !status.ok()) return failure(status.error());
    if (!screenshot.empty()) log::info("wrote " + screenshot);
    return 0;
}

}  // namespace dermis::cli
