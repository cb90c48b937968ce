// dermis render: headless render of a scene file.
#include "Args.h"
#include "Commands.h"
#include "measure/Session.h"

#include "core/Image.h"
#include "core/Limits.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/Suggest.h"
#include "plan/Aov.h"
#include "frame/Renderer.h"
#include "render/TraceEvents.h"
#include "scene/SceneEnums.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis render SCENE [options]\n"
    "\n"
    "Renders SCENE (a JSON scene file, see content/scenes/README.md) without a window\n"
    "and prints a table of per-pass GPU and CPU milliseconds (medians and 5th-95th\n"
    "percentiles over the frames after the warm-up).\n"
    "\n"
    "options:\n"
    "  --size WxH          frame size in pixels (default 640x360)\n"
    "  --frames N          frames to render and time (default 10)\n"
    "  --warm-up N         frames to render first: in the per-frame timings and the trace,\n"
    "                      marked warm_up, but not in the medians (default 0)\n"
    "  --out FILE          output image: .png is tone-mapped 8-bit sRGB, .exr is linear\n"
    "                      32-bit float; for the final image an .exr holds the frame before\n"
    "                      exposure and tone mapping (--aov radiance) (default out/<scene name>.png)\n"
    "  --aov NAME          write one linear component before tone mapping instead of the\n"
    "                      final image (default final):\n"
    "%s"
    "                      stretch and irradiance-texture show the first SSS character on\n"
    "                      screen in its UV layout (the unit square, letterboxed, v up), in\n"
    "                      either mode: in ss mode only their own texture-space passes run;\n"
    "                      black when SSS is off or no SSS character is on screen\n"
    "  --aov all           every AOV above but final as a layer of one .exr (--out FILE.exr):\n"
    "                      the radiance as its default layer (R, G, B, A), the others as\n"
    "                      NAME.R, NAME.G, NAME.B, NAME.A; each rendered once after the\n"
    "                      timed frames\n"
    "  --timings FILE      also write the timings: FILE.json, the summary and every frame's\n"
    "                      passes (docs/profiling.md), or FILE.csv, one row per pass per frame\n"
    "  --trace FILE        also write a trace of every frame, FILE.json in the Trace Event\n"
    "                      format (open it in ui.perfetto.dev or chrome://tracing): a CPU\n"
    "                      and a GPU thread, a slice per pass per frame, the graph's culled\n"
    "                      passes as instant events (docs/profiling.md)\n"
    "  --time T            render at time T seconds: each animated character plays its\n"
    "                      clip at animation.time_s + animation.speed x T (default 0)\n"
    "  --sequence S:E:FPS  render an image sequence: one frame at each time S, S + 1/FPS,\n"
    "                      ... up to E, written as --out with a 4-digit frame number\n"
    "                      before the extension (out/walk_0000.png, ...); not with --time\n"
    "                      or --frames (at most %d frames)\n"
    "  --mode MODE         the subsurface-scattering technique, the same as --set mode=MODE\n"
    "                      given after every --set (it wins over a --set mode=...):\n"
    "%s"
    "  --variant V         Vila Verde 2015's variants of the screen-space frame, the same as\n"
    "                      --set sss.variant=V --set sss.blur=variant after every --set:\n"
    "%s"
    "  --set PATH=VALUE    override a scene value, checked like the file; repeatable.\n"
    "                      PATH is dot-separated from the root, or from \"settings\" when\n"
    "                      it does not start with a root key: --set sss.taps=13\n"
    "                      --set ssao.enabled=false --set camera.position_m=[0,0.1,0.5]\n"
    "  --backend NAME      egl (GPU through EGL devices, else Mesa surfaceless) or osmesa\n"
    "                      (default: egl, falling back to osmesa)\n"
    "  --gl-debug          GL debug context; driver errors are printed and fail the run\n"
    "  --quiet             no progress messages and no table (warnings stay)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene, its content or the GL context fails,\n"
    "2 for bad command-line usage. On failure no output file is written.\n";

constexpr int kMaxSequenceFrames = 100000;

// out/walk.png, 7 -> out/walk_0007.png
std::string sequenceFramePath(const std::string& outPath, size_t frame) {
    const std::filesystem::path path(outPath);
    char number[16];
    std::snprintf(number, sizeof number, "_%04zu", frame);
    return (path.parent_path() / (path.stem().string() + number + path.extension().string())).string();
}

struct RenderOptions {
    std::string scenePath;
    FrameRequest request;           // the frame's size and AOV (Radiance for a final EXR), the time
    int frames = 10;                // timed frames, when there is no sequence
    std::vector<float> sequence;    // --sequence: one frame per time, each written
    std::string outPath;
    int warmUpFrames = 0;           // --warm-up, rendered before `frames`
    bool allAovs = false;           // --aov all: every AOV a layer of one EXR
    std::optional<std::string> timingsPath;  // --timings
    std::optional<std::string> tracePath;    // --trace
    std::vector<std::string> overrides;
    gl::Backend backend = gl::Backend::Auto;
    bool glDebug = false;
};

// --mode and --variant as the scene overrides they stand for.
Status addModeOverrides(const ParsedArgs& args, std::vector<std::string>& overrides) {
    if (args.has("mode")) {
        const std::string mode = args.get("mode", "");
        if (!kSssModes.parse(mode))
            return makeError("--mode " + mode, "expected " + expectedNames(kSssModes) + didYouMean(mode, kSssModes.names()));
        overrides.push_back("mode=" + mode);
    }
    if (args.has("variant")) {
        const std::string variant = args.get("variant", "");
        if (!kSssVariants.parse(variant))
            return makeError("--variant " + variant,
                             "expected " + expectedNames(kSssVariants) + didYouMean(variant, kSssVariants.names()));
        if (args.get("mode", "") == "ts")
            log::warn("--variant " + variant + ": texture space draws the control variant (c) whatever the variant; "
                      "it applies to screen space (docs/texture-space.md)");
        // The variant's blur too, whatever the scene file names.
        overrides.push_back("sss.variant=" + variant);
        overrides.push_back("sss.blur=variant");
    }
    return success();
}

Result<RenderOptions> parseRenderOptions(const ParsedArgs& args) {
    if (args.positional.size() != 1) return makeError("render", "expected exactly one SCENE file");
    RenderOptions options;
    options.scenePath = args.positional[0];
    auto size = parseSize(args.get("size", "640x360"), kMaxFrameDimension);
    if (!size.ok()) return size.error();
    auto frames = parsePositiveInt("--frames", args.get("frames", "10"));
    if (!frames.ok()) return frames.error();
    options.allAovs = args.get("aov", "") == "all";
    auto aov = options.allAovs ? std::optional<Aov>(Aov::Radiance) : kAovs.parse(args.get("aov", "final"));
    if (!aov) {
        std::vector<std::string> names = kAovs.names();
        names.push_back("all");
        return makeError("--aov " + args.get("aov", ""),
                         "expected one of " + kAovs.list() + " or all" + didYouMean(args.get("aov", ""), names));
    }
    const std::string defaultOut = "out/" + std::filesystem::path(options.scenePath).stem().string() + ".png";
    options.outPath = args.get("out", defaultOut);
    const std::string extension = std::filesystem::path(options.outPath).extension().string();
    if (extension != ".png" && extension != ".exr") return makeError("--out " + options.outPath, "the file must end in .png or .exr");
    if (options.allAovs && extension != ".exr")
        return makeError("--aov all", "writes a multi-layer .exr: give --out FILE.exr, not " + options.outPath);
    if (options.allAovs && args.has("sequence")) return makeError("--aov all", "not with --sequence");
    auto backend = parseBackend(args.get("backend", "auto"));
    if (!backend.ok()) return backend.error();
    auto time = parseFloatIn("--time", args.get("time", "0"), -kMaxAnimationTimeS, kMaxAnimationTimeS);
    if (!time.ok()) return time.error();
    if (args.has("sequence")) {
        if (args.has("time") || args.has("frames"))
            return makeError("--sequence", "renders each time once: give it without --time and --frames");
        auto parsed = parseSequence("--sequence", args.get("sequence", ""), kMaxSequenceFrames);
        if (!parsed.ok()) return parsed.error();
        options.sequence = std::move(*parsed);
    }
    options.overrides = args.all("set");
    if (Status modes = addModeOverrides(args, options.overrides); !modes.ok()) return modes.error();
    // An EXR of the final image is linear: the frame before exposure and tone mapping.
    options.request = FrameRequest{size->first, size->second, (*aov == Aov::Final && extension == ".exr") ? Aov::Radiance : *aov};
    options.request.timeS = *time;
    options.frames = options.sequence.empty() ? *frames : static_cast<int>(options.sequence.size());
    if (args.has("warm-up")) {
        if (!options.sequence.empty()) return makeError("--warm-up", "not with --sequence, whose frames are each written");
        auto warmUp = parseNonNegativeInt("--warm-up", args.get("warm-up", "0"));
        if (!warmUp.ok()) return warmUp.error();
        options.warmUpFrames = *warmUp;
    }
    if (args.has("timings")) {
        options.timingsPath = args.get("timings", "");
        const std::string timingsExtension = std::filesystem::path(*options.timingsPath).extension().string();
        if (timingsExtension != ".json" && timingsExtension != ".csv")
            return makeError("--timings " + *options.timingsPath, "the file must end in .json or .csv");
    }
    if (args.has("trace")) {
        options.tracePath = args.get("trace", "");
        if (std::filesystem::path(*options.tracePath).extension() != ".json")
            return makeError("--trace " + *options.tracePath, "the file must end in .json (Trace Event format)");
    }
    options.backend = *backend;
    options.glDebug = args.flags.count("gl-debug") > 0;
    return options;
}

// A frame that shows nothing says why, rather than leaving a blank file to
// puzzle over: every character off screen or smaller than a pixel, or every
// pixel black or white.
void warnIfNothingShows(const RenderOptions& options, const Image& image, const std::vector<CharacterReport>& characters) {
    const auto shown = std::find_if(characters.begin(), characters.end(), [](const CharacterReport& c) { return c.visible; });
    if (!characters.empty() && shown == characters.end()) {
        log::warn(options.scenePath + ": no character is on screen ('" + characters.front().name + "': " +
                  characters.front().culledBecause + "); check the camera");
    }
    const auto large = std::find_if(characters.begin(), characters.end(),
                                    [](const CharacterReport& c) { return c.visible && !(c.footprintPixels < 1.0f); });
    if (shown != characters.end() && large == characters.end()) {
        char pixels[32];
        std::snprintf(pixels, sizeof pixels, "%.2g", double(shown->footprintPixels));
        log::warn(options.scenePath + ": every character on screen spans less than a pixel ('" + shown->name + "': " +
                  pixels + " pixels); it may cover none (check the camera and the characters' scale)");
    }
    if (options.request.aov != Aov::Final && options.request.aov != Aov::Radiance) return;  // a black AOV (no transmittance, no AO) can be right
    const auto every = [&](auto predicate) { return std::all_of(image.texels.begin(), image.texels.end(), predicate); };
    const std::string why = " (settings.exposure, the lights and the background colour decide what shows)";
    if (every([](const glm::vec4& t) { return t.r == 0.0f && t.g == 0.0f && t.b == 0.0f; }))
        log::warn(options.outPath + ": every pixel is black" + why);
    // White: the tone-mapped frame's 8-bit 255 (its target is RGBA8), the radiance's largest half float
    // (where the sanitisers clamp).
    const float white = options.request.aov == Aov::Final ? 1.0f : 65504.0f;
    if (every([white](const glm::vec4& t) { return t.r >= white && t.g >= white && t.b >= white; }))
        log::warn(options.outPath + ": every pixel is white, saturated" + why);
}

// Renders every frame; a sequence's frames are written as they come, each
// whole (its own commit: an interrupted sequence keeps the frames it
// finished), else the last one is staged.
// Returns the wall milliseconds per frame.
Result<double> renderFrames(const RenderOptions& options, Session& session, OutputFiles& outputs) {
    Renderer& renderer = *session.renderer;
    FrameRequest request = options.request;
    // A bar once the frames have taken kQuietRunS (a sequence logs each frame instead).
    constexpr double kQuietRunS = 2.0;
    const auto runStart = std::chrono::steady_clock::now();
    const size_t totalFrames = size_t(options.warmUpFrames) + size_t(options.frames);
    std::unique_ptr<log::Progress> progress;
    size_t framesDone = 0;
    const auto frameDone = [&] {
        ++framesDone;
        if (!options.sequence.empty()) return;
        if (!progress && framesDone < totalFrames && std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count() > kQuietRunS) {
            progress = std::make_unique<log::Progress>("frames", totalFrames, framesDone);
        } else if (progress) {
            progress->advance();
        }
    };
    renderer.setWarmUpFrames(size_t(options.warmUpFrames));
    for (int i = 0; i < options.warmUpFrames; ++i) {
        if (const Status status = renderer.renderFrame(request); !status.ok()) return status.error();
        frameDone();
    }
    if (options.warmUpFrames > 0) glFinish();  // the wall clock counts the timed frames only
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < options.frames; ++i) {
        if (!options.sequence.empty()) request.timeS = options.sequence[static_cast<size_t>(i)];
        if (const Status status = renderer.renderFrame(request); !status.ok()) return status.error();
        frameDone();
        if (options.sequence.empty()) continue;
        auto image = renderer.readOutput();
        if (!image.ok()) return image.error();
        const std::string framePath = sequenceFramePath(options.outPath, static_cast<size_t>(i));
        OutputFiles frameOutput;
        if (const Status saved = frameOutput.stageImage(framePath, *image); !saved.ok()) return saved.error();
        if (const Status committed = frameOutput.commit(); !committed.ok()) return committed.error();
        log::info("frame " + std::to_string(i + 1) + "/" + std::to_string(options.frames) + " at " +
                  formatNumberForMessage(request.timeS) + " s: " + framePath);
    }
    glFinish();
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    renderer.finishTimings();
    if (const Status gl = session.checkGlErrors(); !gl.ok()) return gl.error();
    if (options.sequence.empty() && !options.allAovs) {
        auto image = renderer.readOutput();
        if (!image.ok()) return image.error();
        warnIfNothingShows(options, *image, renderer.characterReports());
        if (const Status saved = outputs.stageImage(options.outPath, *image); !saved.ok()) return saved.error();
    }
    return wallMs / options.frames;
}

// --aov all: one frame per AOV (but the final image), after the timed ones, as the layers of one EXR.
Status stageAllAovs(const RenderOptions& options, Renderer& renderer, OutputFiles& outputs) {
    std::vector<ImageLayer> layers;
    FrameRequest request = options.request;
    for (const EnumEntry<Aov>& aov : kAovs) {
        if (aov.value == Aov::Final) continue;
        request.aov = aov.value;
        if (const Status status = renderer.renderFrame(request); !status.ok()) return status;
        auto image = renderer.readOutput();
        if (!image.ok()) return image.error();
        ImageLayer layer{aov.value == Aov::Radiance ? "" : std::string(aov.name), std::move(*image)};
        // The radiance first: viewers show the first, unnamed layer.
        layers.insert(aov.value == Aov::Radiance ? layers.begin() : layers.end(), std::move(layer));
    }
    log::info("--aov all: " + std::to_string(layers.size()) + " layers in " + options.outPath);
    return outputs.stageLayeredExr(options.outPath, layers);
}

}  // namespace

int runRender(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"size", "frames", "warm-up", "out", "aov", "timings", "trace", "backend", "set", "mode",
                                    "variant", "time", "sequence"},
                          {"gl-debug", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        const char* indent = "                        ";
        std::printf(kHelp, kAovs.helpLines(indent).c_str(), kMaxSequenceFrames, kSssModes.helpLines(indent).c_str(),
                    kSssVariants.helpLines(indent).c_str());
        return 0;
    }
    auto options = parseRenderOptions(*args);
    if (!options.ok()) return usageError(options.error());
    log::setQuiet(args->flags.count("quiet") > 0);
    auto session = Session::open(options->scenePath, options->overrides, options->backend, options->glDebug);
    if (!session.ok()) return failure(session.error());
    log::info("rendering " + options->scenePath + " at " + std::to_string(options->request.width) + "x" +
              std::to_string(options->request.height) + ", " + std::to_string(options->frames) + " frames on " +
              session->context->renderer());
    OutputFiles outputs;  // every file of the command, or none (docs/cli.md, "Outputs")
    if (options->sequence.empty()) {  // a sequence's frames are checked as each is written
        if (Status writable = outputs.checkWritable(options->outPath); !writable.ok()) return failure(writable.error());
    }
    auto wallMsPerFrame = renderFrames(*options, *session, outputs);
    if (!wallMsPerFrame.ok()) return failure(wallMsPerFrame.error());
    Renderer& renderer = *session->renderer;
    RunInfo info = session->runInfo(options->scenePath, options->request.width, options->request.height,
                                    options->warmUpFrames + options->frames);
    info.wallMsPerFrame = *wallMsPerFrame;
    info.characters = renderer.characterReports();
    const FrameTimings& timings = renderer.timings();
    if (options->timingsPath) {
        const bool csv = std::filesystem::path(*options->timingsPath).extension() == ".csv";
        if (const Status staged = outputs.stageText(*options->timingsPath, csv ? timings.toCsv() : timings.toJson(info)); !staged.ok())
            return failure(staged.error());
    }
    if (options->tracePath) {
        if (const Status staged = outputs.stageText(*options->tracePath, traceEventsJson(timings, info)); !staged.ok())
            return failure(staged.error());
    }
    const std::string table = timings.toTable(info);  // before --aov all's frames join the timings
    if (options->allAovs) {
        if (const Status staged = stageAllAovs(*options, renderer, outputs); !staged.ok()) return failure(staged.error());
    }
    if (const Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    if (!log::quiet()) std::printf("%s", table.c_str());
    if (options->sequence.empty()) log::info("wrote " + options->outPath);
    return 0;
}

}  // namespace dermis::cli
