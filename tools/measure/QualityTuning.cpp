#include "measure/QualityTuning.h"

#include "measure/MeasuredRender.h"

#include "bench/BenchReport.h"
#include "bench/QualityTune.h"
#include "core/ImageMetrics.h"
#include "core/Log.h"
#include "frame/Renderer.h"
#include "scene/JsonReader.h"

#include <algorithm>
#include <cstdio>

namespace dermis::measure {
namespace {

constexpr int kFirstWarmUpFrames = 3;

double sssGpuMs(const FrameTimings& timings) {
    double total = 0.0;
    for (const PassSummary& pass : timings.summary()) {
        if (pass.executed && bench::isSssPass(pass.name)) total += pass.gpuMs;
    }
    return total;
}

// The largest pixels per mm of the characters with SSS in the last frame.
float nearestPixelsPerMm(const Session& session) {
    float best = 0.0f;
    for (const CharacterReport& report : session.renderer->characterReports()) {
        if (report.hasSss && report.visible) best = std::max(best, report.pixelsPerMm);
    }
    return best;
}

}  // namespace

Result<QualityTable> tuneQualityTable(Session& session, const TuneSettings& settings) {
    const Camera camera = session.scene->camera;
    const SssSettings sss = session.scene->settings.sss;
    const std::vector<SssChoice>& candidates = bench::tuneCandidates();
    const size_t total = settings.distances.size() * (candidates.size() + 1);
    log::info("tune: margin " + formatNumberForMessage(float(settings.margin)) + " x budget; " + settings.scenePath + " at " +
              std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", " +
              std::to_string(settings.distances.size()) + " distances x " + std::to_string(candidates.size() + 1) +
              " choices, " + std::to_string(settings.frames) + " frames each");

    QualityTable table;
    table.budget = settings.budget;
    table.tunedOn = settings.scenePath;
    table.width = settings.width;
    table.height = settings.height;
    size_t done = 0;
    for (double distance : settings.distances) {
        session.scene->camera = camera;
        session.scene->camera.positionM = camera.targetM + float(distance) * (camera.positionM - camera.targetM);
        // The finest, the reference of every loss at this view.
        session.scene->settings.sss = sss;
        SssChoice::finest().applyTo(session.scene->settings.sss);
        session.scene->settings.sss.minWidthPx = 0.0f;
        auto finest = measureRender(session, settings.scenePath, settings.width, settings.height, settings.frames, done == 0 ? kFirstWarmUpFrames : 1);
        if (!finest.ok()) return finest.error();
        const float pixelsPerMm = nearestPixelsPerMm(session);
        auto mask = sssMask(*session.renderer, settings.width, settings.height);
        if (!mask.ok()) return mask.error();
        if (pixelsPerMm <= 0.0f || std::count(mask->begin(), mask->end(), uint8_t{1}) == 0) {
            const bool anyScatters = session.scene->settings.sss.enabled &&
                                     std::any_of(session.scene->characters.begin(), session.scene->characters.end(),
                                                 [](const Character& c) { return c.material.profile != "none"; });
            return makeError(settings.scenePath, "no SSS pixel is seen at distance factor " + formatNumberForMessage(distance) +
                                                     (anyScatters ? " (fewer or smaller --distances)"
                                                                  : ": no character's material scatters (every profile is "
                                                                    "\"none\", or settings.sss.enabled is false)"));
        }
        const double finestSssMs = sssGpuMs(finest->timings);
        ++done;
        if (!log::quiet()) {
            std::printf("[%zu/%zu] distance %g: %.3g px/mm, finest %-28s SSS %8.3f ms  frame %8.3f ms\n", done, total,
                        distance, pixelsPerMm, describeSssChoice(SssChoice::finest()).c_str(), finestSssMs,
                        finest->timings.frameGpuMs());
            std::fflush(stdout);
        }
        std::vector<bench::TuneMeasurement> measured;
        for (const SssChoice& choice : candidates) {
            session.scene->settings.sss = sss;
            choice.applyTo(session.scene->settings.sss);
            auto render = measureRender(session, settings.scenePath, settings.width, settings.height, settings.frames, 1);
            if (!render.ok()) return render.error();
            auto loss = compareImages(finest->diffuse, render->diffuse, *mask);
            if (!loss.ok()) return loss.error();
            measured.push_back({choice, loss->relativeRmse, sssGpuMs(render->timings), render->timings.frameGpuMs()});
            ++done;
            if (!log::quiet()) {
                std::printf("[%zu/%zu] distance %g: %.3g px/mm, %-35s SSS %8.3f ms  frame %8.3f ms  loss %6.3f%%%s\n",
                            done, total, distance, pixelsPerMm, describeSssChoice(choice).c_str(),
                            measured.back().sssMs, measured.back().frameMs, 100.0 * measured.back().loss,
                            measured.back().loss <= settings.margin * settings.budget ? "" : "  (over margin x budget)");
                std::fflush(stdout);
            }
        }
        table.rows.push_back(bench::cheapestWithin(pixelsPerMm, measured, settings.margin * settings.budget, finestSssMs));
    }
    if (Status sorted = bench::sortQualityRows(table, settings.scenePath); !sorted.ok()) return sorted.error();
    return table;
}

}  // namespace dermis::measure
