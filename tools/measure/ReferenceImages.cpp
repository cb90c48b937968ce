#include "measure/ReferenceImages.h"

#include "core/Log.h"
#include "core/TextFile.h"
#include "reference/PixelSampling.h"
#include "reference/ReferenceRenderer.h"
#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

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
// 6.7 s (docs/reference.md, "Speed").
constexpr int kSssOffEnvironmentSamples = 1024;

Result<Image> renderProgressive(const Scene& scene, const ReferenceSettings& settings, int environmentSamples) {
    reference::ReferenceOptions options = referenceOptions(settings);
    options.environmentSamples = environmentSamples;
    auto renderer = reference::ReferenceRenderer::load(scene, options);
    if (!renderer.ok()) return renderer.error();
    Image image = renderer->renderDiffuseProgressive(settings.width, settings.height, settings.progressive);
    log::info(referenceStagesSummary(renderer->stats()));
    return image;
}

}  // namespace

std::string referenceStagesSummary(const reference::ReferenceStats& stats) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "reference: last pass %.1f s nearest hits, %.1f s base cells, %.1f s integral; "
                  "%zu sample values asked, %.1f %% reused; %d pass(es), estimated relative RMSE %.3f %%",
                  stats.traceSeconds, stats.baseCellSeconds, stats.scatterSeconds, stats.sampleLookups,
                  stats.sampleLookups ? 100.0 * double(stats.sampleMemoHits) / double(stats.sampleLookups) : 0.0,
                  stats.passes, 100.0 * stats.estimatedRelativeRmse);
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
    return cached("reference", identityOf(scene, mSettings, "full"), [&]() -> Result<Image> {
        log::info("computing the CPU reference at " + std::to_string(mSettings.width) + "x" +
                  std::to_string(mSettings.height));
        return renderProgressive(scene, mSettings, reference::kEnvironmentSamples);
    });
}

Result<Image> ReferenceImages::sssOff(const Scene& scene) {
    Scene off = scene;
    off.settings.sss.enabled = false;
    const std::string what = "sss off, " + std::to_string(kSssOffEnvironmentSamples) + " environment rays";
    return cached("reference_sss_off", identityOf(off, mSettings, what), [&]() -> Result<Image> {
        log::info("computing the CPU reference with SSS off");
        return renderProgressive(off, mSettings, kSssOffEnvironmentSamples);
    });
}

Result<Image> ReferenceImages::thicknessMm(const Scene& scene) {
    return cached("thickness", identityOf(scene, mSettings, "thickness"), [&]() -> Result<Image> {
        // Thickness reads only the geometry: a renderer without SSS skips
        // tessellating every character for the diffusion integral.
        Scene geometryOnly = scene;
        geometryOnly.settings.sss.enabled = false;
        auto renderer = reference::ReferenceRenderer::load(geometryOnly, referenceOptions(mSettings));
        if (!renderer.ok()) return renderer.error();
        return renderer->renderThicknessMm(mSettings.width, mSettings.height);
    });
}

Result<Image> ReferenceImages::scatterChange(Session& session, bool scatters) {
    Scene scene = *session.scene;
    scene.settings.sss.enabled = scatters;
    const std::string identity =
        identityOf(scene, mSettings, "scatter change, engine irradiance " + std::to_string(mSettings.irradianceSizeTexels) +
                                         ", spp " + std::to_string(mSettings.changeSamplesPerPixel));
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
        reference::ReferenceOptions options = referenceOptions(mSettings);
        options.engineIrradiance = std::move(*irradiance);
        options.samplesPerPixel = mSettings.changeSamplesPerPixel;
        auto renderer = reference::ReferenceRenderer::load(scene, options);
        if (!renderer.ok()) return renderer.error();
        return renderer->renderScatterChange(mSettings.width, mSettings.height);
    });
}

}  // namespace dermis::measure
