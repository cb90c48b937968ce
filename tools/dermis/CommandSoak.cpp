// dermis soak: memory over a long run with the scene changing (SoakMotion.h).
// Samples the resident memory and the render graph's texture pool and fails
// when either grows after the warm-up.
#include "Args.h"
#include "Commands.h"
#include "ProcessMemory.h"
#include "Python.h"
#include "measure/Session.h"
#include "SoakGrowth.h"
#include "SoakMotion.h"

#include "core/DataDirectory.h"
#include "core/Log.h"
#include "core/Suggest.h"
#include "core/TextFile.h"
#include "frame/Renderer.h"
#include "render/SceneLoading.h"
#include "gl/GlContext.h"
#include "gl/TexturePool.h"
#include "plan/SceneGeometry.h"
#include "scene/SceneEnums.h"
#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis soak [SCENE] [options]\n"
    "\n"
    "Renders N frames of SCENE (default content/scenes/default.json) with the scene\n"
    "changing: the camera orbits the target and the first light turns the other way,\n"
    "each once per 2K frames, and a copy of the first character stands beside it in\n"
    "the second half of each period (the renderer is re-created to add and remove\n"
    "it). Every S frames it samples the process's resident memory and the bytes of\n"
    "the render graph's texture pool, and prints a line. It writes DIR/soak.json\n"
    "(the samples) and DIR/soak.png (a plot; needs python3 with matplotlib).\n"
    "\n"
    "It fails when, after the warm-up, memory grows from the first half of the\n"
    "periods to the second (both hold the same frames of the cycle): the least\n"
    "resident figure of each by more than %.0f MiB, or the texture pool's peak at all.\n"
    "\n"
    "options:\n"
    "  --frames N          frames per mode (default 1000)\n"
    "  --size WxH          frame size in pixels (default 128x72)\n"
    "  --mode ss|ts|both   the SSS mode; both runs ss, then ts (default both)\n"
    "  --change-every K    frames between adding and removing the copy; the period\n"
    "                      is 2K (default 100)\n"
    "  --sample-every S    frames between samples; must divide 2K (default 10)\n"
    "  --warmup F          frames before the growth is measured (default 100);\n"
    "                      N must be at least F + 2 x 2K\n"
    "  --out DIR           where soak.json and soak.png go (default out/soak)\n"
    "  --set PATH=VALUE    override a scene value, as for render; repeatable\n"
    "  --plant-leak KIB    debug: every frame, create and keep a GL texture of KIB\n"
    "                      KiB (1..16384), to show that a leak fails the run\n"
    "  --no-plot           do not draw soak.png\n"
    "  --backend NAME      egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --quiet             no progress lines (warnings stay)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 when memory stayed flat in every mode, 1 when it grew (the error\n"
    "names the mode, the growth and the bound) or the run failed, 2 for bad usage.\n";

// The bound on the rise of the resident floor (SoakGrowth.h). Measured on
// llvmpipe (docs/stress.md, "Memory over 1,000 frames"), 1000 frames of
// default.json: in texture-space mode each re-created renderer leaves the
// one-character level at about 550 or 562-566 MiB, so the floor of a half can
// rise by up to 16 MiB without a leak if only the second half misses the low
// level (two runs: ss +0.05 and -0.004 MiB, ts +0.01 and -12.1 MiB from the
// first half to the second). 24 MiB is 1.5 times that level step; it catches a
// leak above 60 KiB a frame over the 400 frames between the default run's
// halves (a planted 64 KiB a frame over 100 frames grew by 6.6 MiB, as
// 6.25 MiB predicts: a leak shows in full).
constexpr double kMaxResidentGrowthMiB = 24.0;
constexpr double kMiB = 1024.0 * 1024.0;
constexpr int kMaxPlantedLeakKib = 16384;  // a texture of 64 x KIB RGBA32F texels: 16384 is GL's usual height limit

struct SoakOptions {
    std::string scenePath;
    std::vector<std::string> overrides;
    int width = 128, height = 72;
    int frames = 1000;
    int changeEvery = 100;
    int sampleEvery = 10;
    int warmup = 100;
    int plantLeakKib = 0;
    bool quiet = false;
    bool plot = true;
    std::vector<SssMode> modes;
    gl::Backend backend = gl::Backend::Auto;
    std::filesystem::path outDir;
    int period() const { return 2 * changeEvery; }
};

// A GL texture created, cleared (so that its pages are resident) and kept.
void plantLeak(int kib, std::vector<gl::Texture>& kept) {
    const graph::TextureDesc desc{64, static_cast<uint32_t>(kib), graph::TextureFormat::Rgba32F};
    kept.push_back(gl::createTexture2D(desc, "soak: planted leak"));
    const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearTexImage(kept.back().get(), 0, GL_RGBA, GL_FLOAT, one);
}

// The world-space width of the first character along x: how far its copy stands.
Result<float> copyOffsetM(const Scene& scene) {
    auto models = loadSceneModels(scene);
    if (!models.ok()) return models.error();
    const Character& first = scene.characters.front();
    const Bounds world = transformBounds(SceneGeometry(*models).objectBounds(0),
                                         first.transform.worldFromObject(first.metresPerUnit));
    return 1.1f * world.size().x;  // a tenth of its width apart
}

Result<std::vector<SoakSample>> soakMode(const SoakOptions& options, SssMode mode) {
    std::vector<std::string> overrides = options.overrides;
    overrides.push_back("mode=" + std::string(kSssModes.name(mode)));
    auto loaded = loadScene(options.scenePath, overrides);
    if (!loaded.ok()) return loaded.error();
    const Scene base = *loaded;
    if (base.characters.empty()) return makeError(options.scenePath, "soak needs a character to copy; the scene has none");
    auto offsetM = copyOffsetM(base);
    if (!offsetM.ok()) return offsetM.error();

    const std::string label = std::string(kSssModes.name(mode));
    Scene scene = base;  // the renderer keeps a reference: destroyed before the scene changes
    // Compiled once, as an application keeps its shaders when its scene
    // changes: re-creating the renderer then reloads the characters only.
    auto built = Programs::build();
    if (!built.ok()) return built.error();
    const auto programs = std::make_shared<Programs>(std::move(*built));
    std::unique_ptr<Renderer> renderer;
    std::vector<gl::Texture> leaked;
    std::vector<SoakSample> samples;
    const FrameRequest request{options.width, options.height, Aov::Final};
    for (int frame = 0; frame < options.frames; ++frame) {
        const bool copy = soakCopyPresent(frame, options.period());
        if (!renderer || copy != (scene.characters.size() > base.characters.size())) {
            renderer.reset();
            scene.characters = base.characters;
            if (copy) scene.characters.push_back(soakCopy(base.characters.front(), *offsetM));
            auto created = Renderer::create(scene, programs);
            if (!created.ok()) return created.error();
            renderer = std::move(*created);
        }
        applySoakMotion(base, frame, options.period(), scene);
        if (const Status status = renderer->renderFrame(request); !status.ok()) return status.error();
        renderer->resetTimings();  // as the viewer does: `render` keeps every frame's timings for its medians
        if (options.plantLeakKib > 0) plantLeak(options.plantLeakKib, leaked);
        if ((frame + 1) % options.sampleEvery != 0) continue;
        glFinish();  // llvmpipe renders on its own threads: sample after the frame's work is done
        auto resident = residentBytes();
        if (!resident.ok()) return resident.error();
        SoakSample sample{frame + 1, static_cast<int>(scene.characters.size()), *resident,
                          renderer->texturePoolBytes()};
        samples.push_back(sample);
        if (!options.quiet) {
            std::printf("soak %s frame %d/%d: resident %.1f MiB, texture pool %.2f MiB, %d character%s\n",
                        label.c_str(), sample.frame, options.frames, double(sample.residentBytes) / kMiB,
                        double(sample.poolBytes) / kMiB, sample.characters, sample.characters == 1 ? "" : "s");
            std::fflush(stdout);
        }
    }
    return samples;
}

// Why a mode's growth fails the run; empty when it does not.
std::string growthFailure(const std::string& mode, const SoakGrowth& g) {
    char text[512];
    if (double(g.residentBytes()) > kMaxResidentGrowthMiB * kMiB) {
        std::snprintf(text, sizeof text,
                      "resident memory grew by %.1f MiB (floor %.1f MiB over frames %d-%d, %.1f MiB over frames %d-%d); "
                      "the bound is %.0f MiB",
                      double(g.residentBytes()) / kMiB, double(g.firstResidentFloor) / kMiB, g.firstWindowStart + 1,
                      g.firstWindowEnd, double(g.lastResidentFloor) / kMiB, g.lastWindowStart + 1, g.lastWindowEnd,
                      kMaxResidentGrowthMiB);
        return "soak " + mode + ": " + text;
    }
    if (g.poolBytes() > 0) {
        std::snprintf(text, sizeof text,
                      "the texture pool grew by %lld bytes (peak %llu over frames %d-%d, %llu over frames %d-%d); "
                      "the bound is 0: the same frames of the cycle need the same targets",
                      static_cast<long long>(g.poolBytes()), static_cast<unsigned long long>(g.firstPoolPeak),
                      g.firstWindowStart + 1, g.firstWindowEnd, static_cast<unsigned long long>(g.lastPoolPeak),
                      g.lastWindowStart + 1, g.lastWindowEnd);
        return "soak " + mode + ": " + text;
    }
    return {};
}

Status drawPlot(const std::filesystem::path& outDir) {
    const std::string script = toolScript("plot_soak.py");
    const std::string command = pythonInterpreter() + " '" + script + "' '" + outDir.string() + "'";
    if (std::system(command.c_str()) != 0) {
        return makeError(script, "plotting failed (it needs python3 with matplotlib: apt-get install python3-matplotlib)");
    }
    return success();
}

Result<SoakOptions> parseSoakOptions(const ParsedArgs& args) {
    SoakOptions o;
    if (args.positional.size() > 1) return makeError("soak", "expected at most one SCENE file");
    o.scenePath = args.positional.empty() ? dataDirectory(DataKind::Content) + "/scenes/default.json"
                                          : args.positional[0];
    o.overrides = args.all("set");
    auto size = parseSize(args.get("size", "128x72"), kMaxFrameDimension);
    if (!size.ok()) return size.error();
    o.width = size->first;
    o.height = size->second;
    const std::pair<const char*, int*> counts[] = {{"frames", &o.frames},
                                                   {"change-every", &o.changeEvery},
                                                   {"sample-every", &o.sampleEvery},
                                                   {"warmup", &o.warmup}};
    for (const auto& [name, value] : counts) {
        if (!args.has(name)) continue;
        auto parsed = parsePositiveInt(std::string("--") + name, args.get(name, ""));
        if (!parsed.ok()) return parsed.error();
        *value = *parsed;
    }
    if (args.has("plant-leak")) {
        auto kib = parsePositiveInt("--plant-leak", args.get("plant-leak", ""));
        if (!kib.ok()) return kib.error();
        if (*kib > kMaxPlantedLeakKib) {
            return makeError("--plant-leak " + std::to_string(*kib), "at most " + std::to_string(kMaxPlantedLeakKib) + " KiB");
        }
        o.plantLeakKib = *kib;
    }
    if (o.period() % o.sampleEvery != 0) {
        return makeError("--sample-every " + std::to_string(o.sampleEvery),
                         "must divide the period 2 x --change-every = " + std::to_string(o.period()) +
                             ", so that both windows sample the same frames of the cycle");
    }
    if (o.frames < o.warmup + 2 * o.period()) {
        return makeError("--frames " + std::to_string(o.frames),
                         "must be at least --warmup + 2 x the period (2 x --change-every) = " +
                             std::to_string(o.warmup + 2 * o.period()) + ", to compare two periods after the warm-up");
    }
    o.quiet = args.flags.count("quiet") > 0;
    o.plot = !args.flags.count("no-plot");
    const std::string modeName = args.get("mode", "both");
    if (modeName == "both") {
        o.modes = {SssMode::ScreenSpace, SssMode::TextureSpace};
    } else if (auto mode = kSssModes.parse(modeName)) {
        o.modes = {*mode};
    } else {
        std::vector<std::string> names = kSssModes.names();
        names.push_back("both");
        return makeError("--mode " + modeName, "expected " + expectedNames(kSssModes) + " or both" + didYouMean(modeName, names));
    }
    auto backend = parseBackend(args.get("backend", "auto"));
    if (!backend.ok()) return backend.error();
    o.backend = *backend;
    o.outDir = args.get("out", "out/soak");
    return o;
}

// Each mode soaked in turn, into report["modes"]; why each grew, into `failures`.
Status soakModes(const SoakOptions& options, nlohmann::ordered_json& report, std::vector<std::string>& failures) {
    for (const SssMode mode : options.modes) {
        const std::string name(kSssModes.name(mode));
        auto samples = soakMode(options, mode);
        if (!samples.ok()) return samples.error();
        const SoakGrowth growth = measureSoakGrowth(*samples, options.warmup, options.period(), options.frames);
        const std::string why = growthFailure(name, growth);
        if (!why.empty()) failures.push_back(why);
        nlohmann::ordered_json& m = report["modes"][name];
        m["resident_growth_bytes"] = growth.residentBytes();
        m["pool_growth_bytes"] = growth.poolBytes();
        m["first_window"] = {growth.firstWindowStart + 1, growth.firstWindowEnd};
        m["last_window"] = {growth.lastWindowStart + 1, growth.lastWindowEnd};
        m["flat"] = why.empty();
        for (const SoakSample& sample : *samples) {
            m["samples"].push_back({{"frame", sample.frame},
                                    {"characters", sample.characters},
                                    {"resident_bytes", sample.residentBytes},
                                    {"pool_bytes", sample.poolBytes}});
        }
    }
    return success();
}

}  // namespace

int runSoak(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs,
                          {"frames", "size", "mode", "change-every", "sample-every", "warmup", "out", "set",
                           "plant-leak", "backend"},
                          {"no-plot", "quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::printf(kHelp, kMaxResidentGrowthMiB);
        return 0;
    }
    auto options = parseSoakOptions(*args);
    if (!options.ok()) return usageError(options.error());
    auto context = gl::createHeadlessContext({options->backend, false});
    if (!context.ok()) return failure(context.error());
    log::setQuiet(true);  // each re-created renderer's loading messages would drown the progress lines
    const auto start = std::chrono::steady_clock::now();
    nlohmann::ordered_json report;
    report["scene"] = options->scenePath;
    report["renderer"] = (*context)->renderer();
    report["size"] = std::to_string(options->width) + "x" + std::to_string(options->height);
    report["frames"] = options->frames;
    report["change_every"] = options->changeEvery;
    report["sample_every"] = options->sampleEvery;
    report["warmup"] = options->warmup;
    report["plant_leak_kib"] = options->plantLeakKib;
    report["max_resident_growth_mib"] = kMaxResidentGrowthMiB;
    std::vector<std::string> failures;
    if (const Status soaked = soakModes(*options, report, failures); !soaked.ok()) return failure(soaked.error());
    report["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log::setQuiet(options->quiet);

    std::error_code ec;
    std::filesystem::create_directories(options->outDir, ec);
    const std::string jsonPath = (options->outDir / "soak.json").string();
    if (const Status written = writeTextFileAtomically(jsonPath, report.dump(1) + "\n"); !written.ok()) {
        return failure(written.error());
    }
    if (options->plot) {
        if (const Status plotted = drawPlot(options->outDir); !plotted.ok()) log::warn(plotted.error().message() + "; no plot");
    }
    for (const std::string& why : failures) log::error(why);
    if (!options->quiet) std::printf("%s in %.1f s (%s)\n", failures.empty() ? "flat" : "grew",
                                     report["seconds"].get<double>(), jsonPath.c_str());
    return failures.empty() ? 0 : 1;
}

}  // namespace dermis::cli
