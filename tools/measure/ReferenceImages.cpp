#include "measure/ReferenceImages.h"

#include "core/CacheDirectory.h"
#include "core/ContentHash.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/TextFile.h"
#include "reference/PixelSampling.h"
#include "reference/ReferenceRenderer.h"
#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

namespace dermis::measure {
namespace {

std::string readIdentity(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) return {};
    try {
        return nlohmann::json::parse(in).at("identity").get<std::string>();
    } catch (const std::exception&) {
        return {};  // unreadable: computed again
    }
}

reference::ReferenceOptions referenceOptions(const ReferenceSettings& settings) {
    reference::ReferenceOptions options;
    options.quadrature.density = settings.density;
    options.samplesPerPixel = settings.samplesPerPixel;
    options.showProgress = !log::quiet();
    return options;
}

// Environment rays per pixel of the SSS-off reference. Each of its pixels is
// one shading point, where the full reference averages thousands of the
// integral's samples, so its noise per pass is far larger at the same count:
// the default head under tools/make_sun_map.py's sun at 320x180 stopped at 8
// passes and 2.85% with 16 rays; with 1024 it reached 0.16% in 2 passes and
// 6.7 s (docs/results/reference.md, "Speed").
constexpr int kSssOffEnvironmentSamples = 1024;

Image renderProgressive(reference::ReferenceRenderer& renderer, const ReferenceSettings& settings) {
    Image image = renderer.renderDiffuseProgressive(settings.width, settings.height, settings.progressive);
    log::info(referenceStagesSummary(renderer.stats()));
    return image;
}

// The shared cache's copy of an image: found by a key of its identity, the
// content the renderer read from files and the program itself, and checked
// against the identity written beside it.
Result<Image> sharedOrComputed(const std::string& identity, const reference::ReferenceRenderer& renderer,
                               const ReferenceSettings& settings, const std::function<Image()>& compute) {
    const std::filesystem::path directory = cacheDirectory();
    if (directory.empty() || programContentHash() == 0) return compute();
    const std::string fullIdentity = identity + "\ncontent " + std::to_string(renderer.contentHash()) + " program " +
                                     std::to_string(programContentHash());
    const std::string name = hex16(ContentHash().text(fullIdentity).value());
    const std::filesystem::path image = directory / "reference" / (std::string(name) + ".exr");
    const std::filesystem::path note = directory / "reference" / (std::string(name) + ".json");
    std::error_code error;
    if (std::filesystem::exists(image, error) && readIdentity(note) == fullIdentity) {
        auto loaded = loadImage(image.string(), ColourSpace::Linear);
        if (loaded.ok() && loaded->width == settings.width && loaded->height == settings.height) {
            log::info("reusing " + image.string() + " (the same scene, files, settings and program)");
            return loaded;
        }
    }
    Image computed = compute();
    OutputFiles files;
    Status saved = files.stageImage(image.string(), computed);
    if (saved.ok()) saved = files.stageText(note.string(), nlohmann::ordered_json{{"identity", fullIdentity}}.dump() + "\n");
    if (saved.ok()) saved = files.commit();
    if (!saved.ok()) log::warn("the reference is not cached: " + saved.error().message());
    return computed;
}

}  // namespace

std::string referenceStagesSummary(const reference::ReferenceStats& stats) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "reference: last pass %.1f s nearest hits, %.1f s base cells, %.1f s integral; "
                  "%zu sample values asked, %.1f %% reused; %d pass%s, estimated relative RMSE %.3f %%",
                  stats.traceSeconds, stats.baseCellSeconds, stats.scatterSeconds, stats.sampleLookups,
                  stats.sampleLookups ? 100.0 * double(stats.sampleMemoHits) / double(stats.sampleLookups) : 0.0,
                  std::max(stats.passes, 1), stats.passes > 1 ? "es" : "",  // one pass unless progressive
                  100.0 * stats.estimatedRelativeRmse);
    return text;
}

Scene lightingOnly(const Scene& scene) {
    Scene lighting = scene;
    const RenderSettings defaults;
    RenderSettings& settings = lighting.settings;
    settings.mode = defaults.mode;
    settings.sss.technique = defaults.sss.technique;
    settings.sss.separableSamples = defaults.sss.separableSamples;
    settings.sss.diskSamples = defaults.sss.diskSamples;
    settings.sss.taps = defaults.sss.taps;
    settings.sss.blur = defaults.sss.blur;
    settings.sss.bilateralDepthMm = defaults.sss.bilateralDepthMm;
    settings.sss.controlDepthScalePerMm = defaults.sss.controlDepthScalePerMm;
    settings.sss.gaussians = defaults.sss.gaussians;
    settings.sss.minWidthPx = defaults.sss.minWidthPx;
    settings.transmittance = defaults.transmittance;
    settings.ts = defaults.ts;
    return lighting;
}

ReferenceImages::ReferenceImages(std::filesystem::path directory, ReferenceSettings settings)
    : mDirectory(std::move(directory)), mSettings(settings) {}

template <class Compute>
Result<Image> ReferenceImages::cached(const std::string& name, const std::string& identity, Compute&& compute) {
    if (auto found = mMemory.find(identity); found != mMemory.end()) return found->second;
    const std::filesystem::path image = mDirectory / (name + ".exr");
    const std::filesystem::path note = mDirectory / (name + ".json");
    if (std::filesystem::exists(image) && readIdentity(note) == identity) {
        auto loaded = loadImage(image.string(), ColourSpace::Linear);
        if (loaded.ok() && loaded->width == mSettings.width && loaded->height == mSettings.height) {
            log::info("reusing " + image.string() + " (computed from the same scene and settings)");
            mMemory[identity] = *loaded;
            return loaded;
        }
    }
    Result<Image> computed = compute();
    if (!computed.ok()) return computed;
    if (Status saved = saveImage(image.string(), *computed); !saved.ok()) return saved.error();
    const std::string noteText = nlohmann::ordered_json{{"identity", identity}}.dump() + "\n";
    if (Status written = writeTextFileAtomically(note.string(), noteText); !written.ok()) return written.error();
    mMemory[identity] = *computed;
    return computed;
}

namespace {

std::string identityOf(const Scene& scene, const ReferenceSettings& settings, const std::string& what) {
    std::ostringstream text;
    text << what << " " << settings.width << "x" << settings.height << " density " << settings.density << " spp "
         << settings.samplesPerPixel << " target " << settings.progressive.targetRelativeRmse << " passes "
         << settings.progressive.maxPasses << "\n"
         << sceneToJson(lightingOnly(scene));
    return text.str();
}

}  // namespace

Result<Image> ReferenceImages::full(const Scene& scene) {
    const std::string identity = identityOf(scene, mSettings, "full");
    return cached("reference", identity, [&]() -> Result<Image> {
        auto renderer = reference::ReferenceRenderer::load(scene, referenceOptions(mSettings));
        if (!renderer.ok()) return renderer.error();
        return sharedOrComputed(identity, *renderer, mSettings, [&] {
            log::info("computing the CPU reference at " + std::to_string(mSettings.width) + "x" +
                      std::to_string(mSettings.height));
            return renderProgressive(*renderer, mSettings);
        });
    });
}

Result<Image> ReferenceImages::sssOff(const Scene& scene) {
    Scene off = scene;
    off.settings.sss.enabled = false;
    const std::string what = "sss off, " + std::to_string(kSssOffEnvironmentSamples) + " environment rays";
    const std::string identity = identityOf(off, mSettings, what);
    return cached("reference_sss_off", identity, [&]() -> Result<Image> {
        reference::ReferenceOptions options = referenceOptions(mSettings);
        options.environmentSamples = kSssOffEnvironmentSamples;
        auto renderer = reference::ReferenceRenderer::load(off, options);
        if (!renderer.ok()) return renderer.error();
        return sharedOrComputed(identity, *renderer, mSettings, [&] {
            log::info("computing the CPU reference with SSS off");
            return renderProgressive(*renderer, mSettings);
        });
    });
}

Result<Image> ReferenceImages::thicknessMm(const Scene& scene) {
    const std::string identity = identityOf(scene, mSettings, "thickness");
    return cached("thickness", identity, [&]() -> Result<Image> {
        // Thickness reads only the geometry: a renderer without SSS skips
        // tessellating every character for the diffusion integral.
        Scene geometryOnly = scene;
        geometryOnly.settings.sss.enabled = false;
        auto renderer = reference::ReferenceRenderer::load(geometryOnly, referenceOptions(mSettings));
        if (!renderer.ok()) return renderer.error();
        return sharedOrComputed(identity, *renderer, mSettings,
                                [&] { return renderer->renderThicknessMm(mSettings.width, mSettings.height); });
    });
}

Result<Image> ReferenceImages::scatterChange(Session& session, bool scatters) {
    Scene scene = *session.scene;
    scene.settings.sss.enabled = scatters;
    // The words after the spp name how the engine's capture and the change are
    // made: when that changes, files made the old way must not be reused.
    const std::string identity =
        identityOf(scene, mSettings, "scatter change, engine irradiance " + std::to_string(mSettings.irradianceSizeTexels) +
                                         ", spp " + std::to_string(mSettings.changeSamplesPerPixel) +
                                         " over the centre's surface, maps at the pixel's mip level, the G-buffer's normal");
    // One file per lighting setup, named by its identity's hash.
    char name[64];
    std::snprintf(name, sizeof name, "scatter_change_%016zx", std::hash<std::string>{}(identity));
    return cached(name, identity, [&]() -> Result<Image> {
        log::info("capturing the engine's irradiance at " + std::to_string(mSettings.irradianceSizeTexels) +
                  " texels and scattering it exactly (the matched reference)");
        // The capture plans the SSS characters of the session's scene: they are there only with SSS on.
        const bool configured = session.scene->settings.sss.enabled;
        session.scene->settings.sss.enabled = scatters;
        auto irradiance = session.renderer->captureIrradianceTextures(mSettings.irradianceSizeTexels);
        session.scene->settings.sss.enabled = configured;
        if (!irradiance.ok()) return irradiance.error();
        // The engine's part is the captured irradiance itself: its hash keys the shared copy,
        // whatever code and shaders made it.
        ContentHash captured;
        for (const Image& texture : *irradiance) captured.image(texture);
        reference::ReferenceOptions options = referenceOptions(mSettings);
        options.engineIrradiance = std::move(*irradiance);
        options.samplesPerPixel = mSettings.changeSamplesPerPixel;
        auto renderer = reference::ReferenceRenderer::load(scene, options);
        if (!renderer.ok()) return renderer.error();
        return sharedOrComputed(identity + "\nengine irradiance " + std::to_string(captured.value()), *renderer,
                                mSettings, [&] {
                                    Image change = renderer->renderScatterChange(mSettings.width, mSettings.height);
                                    if (const size_t empty = renderer->stats().emptyIrradianceReads; empty > 0)
                                        log::warn("the matched reference read the engine's irradiance " +
                                                  std::to_string(empty) +
                                                  " times where no texel within 3 was covered (a gap in the UV "
                                                  "layout); those reads count as 0 light (docs/reference.md, "
                                                  "\"Matched-irradiance mode\")");
                                    return change;
                                });
    });
}

}  // namespace dermis::measure
