// dermis reference: brute-force CPU evaluation of the subsurface integral that
// both real-time modes approximate (engine/reference/ReferenceRenderer.h).
#include "CommandReference.h"

#include "Args.h"
#include "ReferenceOptions.h"
#include "measure/ReferenceImages.h"
#include "measure/Session.h"
#include "scene/JsonReader.h"

#include "core/Image.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "shards/ReferenceShards.h"
#include "shards/ShardNote.h"
#include "raytrace/ParallelFor.h"
#include "reference/ReferenceRenderer.h"
#include "scene/SceneLoader.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace dermis::cli {

using namespace measure;
namespace {

constexpr int kMaxReferenceDimension = 8192;

const char* const kHelp =
    "usage: dermis reference SCENE --out FILE.exr [options]\n"
    "\n"
    "Computes the CPU reference of the diffuse AOV: for each sub-sample of a pixel, the\n"
    "point x_o the camera ray hits and\n"
    "  L_d(x_o) = albedo^(1-mix)(x_o) (1 - rho_s rho_dt(N.V, m))\n"
    "             x integral over the character of R(|x_o - x_i|) E(x_i) albedo^mix(x_i) dA_i\n"
    "with R the character's diffusion profile over 3-D distance and E the irradiance of\n"
    "the scene's lights with exact (ray-traced) shadows, the environment's light with exact\n"
    "visibility (ray-traced, by importance sampling) and the ambient (AO = 1, no\n"
    "transmittance). The integral runs over the character's skin only: surface of one\n"
    "closed part that lies inside another (an ear sunk into a skull) gives no light.\n"
    "Characters without a profile are Lambertian. The result compares\n"
    "with `dermis render SCENE --aov diffuse --out x.exr` at the same size; run that with\n"
    "--set ssao.enabled=false --set transmittance.enabled=false for the same definition.\n"
    "A pixel is the mean of its sub-samples: alpha is the fraction that hit a surface and\n"
    "RGB counts the background as 0, so compare with the engine only where alpha is 1.\n"
    "Albedo and normal maps are read trilinearly at the level of detail of the whole\n"
    "pixel's footprint, as the GPU reads them.\n"
    "\n"
    "options:\n"
    "  --out FILE          output image, linear float .exr (required); written only on success\n"
    "  --aov NAME          the component to compute: diffuse (the only one; default diffuse)\n"
    "  --size WxH          image size in pixels (default 640x360, as dermis render)\n"
    "  --density N         quadrature samples per s^2 for each Gaussian of standard deviation s,\n"
    "                      near x_o; the error falls about as 1/N (default 8)\n"
    "  --spp N             sub-samples per pixel, a perfect square from 1 to 256 on a jittered\n"
    "                      sqrt(N) x sqrt(N) grid; 1 is the pixel centre (default 4); the time\n"
    "                      grows about as N\n"
    "  --env-samples N     rays per shading point for the environment's light, 2 to 65536 (half\n"
    "                      drawn from the map's brightness, half cosine-weighted; default 16);\n"
    "                      the noise falls about as 1/sqrt(N), the time grows about as N\n"
    "  --integral-env-samples N  the same at each sample of the subsurface integral, which\n"
    "                      averages thousands of them per pixel (default 16)\n"
    "  --target-error PCT  progressive: repeat the image with independent environment rays\n"
    "                      until the estimated relative RMSE of its noise is at most PCT percent\n"
    "                      (e.g. 0.2), printing the estimate after each pass; the image is the\n"
    "                      passes' mean. Without it, one pass; without an environment, one pass\n"
    "  --max-passes N      the progressive mode's limit, up to 64 (default 8)\n"
    "  --set PATH=VALUE    override a scene value, checked like the file; repeatable (as in\n"
    "                      dermis render: --set sss.mix=0.5 --set camera.position_m=[0,0.1,0.5])\n"
    "  --threads N         worker threads (default: one per hardware thread); the image does not\n"
    "                      depend on it\n"
    "  --shard K/N         compute only the K-th of N bands of rows (K from 1), the other rows 0,\n"
    "                      and write FILE.exr.shard.json beside the image; `dermis merge` joins\n"
    "                      the N shards into the image one run makes, bit for bit\n"
    "                      (docs/shards.md). Not with --target-error or --max-passes\n"
    "  --quiet             no progress bars or summary (warnings stay)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene or its content fails to load or the file\n"
    "cannot be written, 2 for bad command-line usage. On failure no output file is written.\n";

struct ReferenceCommandOptions {
    std::string scenePath;
    std::string outPath;
    int width = 0, height = 0;
    reference::ReferenceOptions renderer;
    std::optional<reference::ProgressiveSettings> progressive;  // with --target-error or --max-passes
    std::vector<std::string> overrides;
    shards::ShardSpec shard;
};

// --density, --spp, --env-samples, --integral-env-samples and --threads into `options`.
Status parseRendererOptions(const ParsedArgs& args, reference::ReferenceOptions& options) {
    if (args.has("density")) {
        auto density = parsePositiveFloat("--density", args.get("density", ""));
        if (!density.ok()) return density.error();
        options.quadrature.density = *density;
    }
    if (args.has("spp")) {
        auto spp = parsePositiveInt("--spp", args.get("spp", ""));
        if (!spp.ok()) return spp.error();
        if (reference::strataPerSide(*spp) == 0) {
            return makeError("--spp " + args.get("spp", ""), "expected a perfect square from 1 to " +
                                                                 std::to_string(reference::kMaxSamplesPerPixel) +
                                                                 " (1, 4, 9, 16, ...)");
        }
        options.samplesPerPixel = *spp;
    }
    for (auto [name, target] : {std::pair<std::string, int*>{"env-samples", &options.environmentSamples},
                                {"integral-env-samples", &options.integralEnvironmentSamples}}) {
        if (!args.has(name)) continue;
        auto samples = parsePositiveInt("--" + name, args.get(name, ""));
        if (!samples.ok()) return samples.error();
        if (*samples < reference::kMinEnvironmentSamples || *samples > reference::kMaxEnvironmentSamples) {
            return makeError("--" + name + " " + args.get(name, ""), "expected " +
                                                                         std::to_string(reference::kMinEnvironmentSamples) +
                                                                         " to " + std::to_string(reference::kMaxEnvironmentSamples));
        }
        *target = *samples;
    }
    if (args.has("threads")) {
        auto threads = parsePositiveInt("--threads", args.get("threads", ""));
        if (!threads.ok()) return threads.error();
        if (*threads > 1024) return makeError("--threads", "at most 1024");
        options.threads = *threads;
    }
    return success();
}

// A usage error is marked by `usage`; a missing output directory is not one.
Result<ReferenceCommandOptions> parseReferenceCommandOptions(const ParsedArgs& args, bool* usage) {
    *usage = true;
    if (args.positional.size() != 1) return makeError("reference", "expected exactly one SCENE file");
    if (!args.has("out")) return makeError("reference", "--out FILE.exr is required");
    ReferenceCommandOptions options;
    options.scenePath = args.positional[0];
    options.outPath = args.get("out", "");
    if (std::filesystem::path(options.outPath).extension() != ".exr")
        return makeError("--out " + options.outPath, "the reference is linear float: the file must end in .exr");
    const std::string aov = args.get("aov", "diffuse");
    if (aov != "diffuse") return makeError("--aov " + aov, "the reference computes only: diffuse");
    auto size = parseSize(args.get("size", "640x360"), kMaxReferenceDimension);
    if (!size.ok()) return size.error();
    options.width = size->first;
    options.height = size->second;
    if (Status parsed = parseRendererOptions(args, options.renderer); !parsed.ok()) return parsed.error();
    if (args.has("target-error") || args.has("max-passes")) {
        auto settings = progressiveSettingsFromArgs(args);
        if (!settings.ok()) return settings.error();
        options.progressive = *settings;
    }
    options.overrides = args.all("set");
    if (args.has("shard")) {
        auto shard = shards::parseShardSpec(args.get("shard", ""));
        if (!shard.ok()) return shard.error();
        if (options.progressive) {
            return makeError("--shard", "not with --target-error or --max-passes: the progressive passes stop on the "
                                        "noise of the whole image");
        }
        options.shard = *shard;
    }
    *usage = false;
    return options;
}

// A hash of what the pixels depend on: the scene as loaded, the options, the content.
std::string referenceIdentity(const ReferenceCommandOptions& options, const Scene& scene,
                              const reference::ReferenceRenderer& renderer) {
    const reference::ReferenceOptions& r = options.renderer;
    std::string text = std::to_string(options.width) + "x" + std::to_string(options.height) + " density " +
                       std::to_string(r.quadrature.density) + " spp " + std::to_string(r.samplesPerPixel) + " env " +
                       std::to_string(r.environmentSamples) + " integral env " + std::to_string(r.integralEnvironmentSamples) +
                       " content " + std::to_string(renderer.contentHash()) + "\n" + sceneToJson(scene);
    return shards::identityOf(text);
}

}  // namespace

int runReference(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"out", "aov", "size", "density", "spp", "env-samples", "integral-env-samples", "target-error", "max-passes", "set", "threads", "shard"}, {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) return std::printf("%s", kHelp), 0;
    log::setQuiet(args->flags.count("quiet") > 0);
    bool usage = false;
    auto options = parseReferenceCommandOptions(*args, &usage);
    if (!options.ok()) return usage ? usageError(options.error()) : failure(options.error());
    options->renderer.showProgress = !log::quiet();
    auto scene = loadScene(options->scenePath, options->overrides);
    if (!scene.ok()) return failure(scene.error());
    OutputFiles out;  // the image (and a shard's note), or nothing
    if (Status writable = out.checkWritable(options->outPath); !writable.ok()) return failure(writable.error());

    const auto start = std::chrono::steady_clock::now();
    log::info("reference: loading " + options->scenePath);
    auto renderer = reference::ReferenceRenderer::load(*scene, options->renderer);
    if (!renderer.ok()) return failure(renderer.error());
    const auto built = std::chrono::steady_clock::now();
    log::info("reference: " + std::to_string(options->width) + "x" + std::to_string(options->height) + ", density " +
              formatNumberForMessage(options->renderer.quadrature.density) + " per s^2, " +
              std::to_string(options->renderer.samplesPerPixel) + " samples per pixel, " +
              std::to_string(raytrace::resolveThreadCount(options->renderer.threads)) + " threads");
    const shards::ShardRange rows = shards::shardRange(options->shard, options->height);
    const Image image = options->progressive ? renderer->renderDiffuseProgressive(options->width, options->height, *options->progressive)
                        : options->shard.whole()
                            ? renderer->renderDiffuse(options->width, options->height)
                            : renderer->renderDiffuseRows(options->width, options->height, rows.first, rows.count);
    const auto done = std::chrono::steady_clock::now();
    if (Status staged = out.stageImage(options->outPath, image); !staged.ok()) return failure(staged.error());
    if (!options->shard.whole()) {
        const shards::ReferenceShardNote note{options->shard, options->width, options->height, rows.first, rows.count,
                                              referenceIdentity(*options, *scene, *renderer)};
        if (Status staged = out.stageText(shards::referenceShardNotePath(options->outPath), shards::referenceShardNoteJson(note));
            !staged.ok()) {
            return failure(staged.error());
        }
    }
    if (Status committed = out.commit(); !committed.ok()) return failure(committed.error());

    const reference::ReferenceStats& stats = renderer->stats();
    auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
    char summary[512];
    std::snprintf(summary, sizeof summary,
                  "reference: %zu SSS sub-samples, %zu triangles (%zu inside the body, %zu across its boundary), "
                  "%zu of %zu base cells shaded; load %.1f s, render %.1f s",
                  stats.sssHits, stats.triangles, stats.buriedTriangles, stats.straddlingTriangles, stats.shadedBaseCells,
                  stats.baseCells, seconds(start, built), seconds(built, done));
    log::info(summary);
    log::info(referenceStagesSummary(stats));
    log::info("wrote " + options->outPath);
    return 0;
}

}  // namespace dermis::cli
