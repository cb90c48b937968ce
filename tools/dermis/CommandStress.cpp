// dermis stress: numerical fuzzing of scenes and settings; every intermediate
// target is checked for non-finite texels.
#include "Args.h"
#include "Commands.h"
#include "measure/Session.h"

#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/TextFile.h"
#include "gl/GlContext.h"
#include "frame/Renderer.h"
#include "scene/SceneLoader.h"
#include "stress/InvariantFrame.h"
#include "stress/InvariantJson.h"
#include "stress/StressCases.h"
#include "stress/StressCounting.h"
#include "stress/StressHash.h"
#include "stress/StressLoading.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis stress [options]\n"
    "\n"
    "Renders N random scenes with extreme settings (SSS widths and tap counts, both\n"
    "SSS modes and every variant, every AOV, frames from 1x1 to 1280x720, near and\n"
    "far planes, a camera inside a character, degenerate triangles, glTFs without\n"
    "normals or UVs or with duplicate vertices, NaN/Inf texels, lights past fp16\n"
    "and of every size, no lights and 64 lights), 1 to 4 frames each with the\n"
    "camera and a light moving. A quarter of the scenes go through a JSON file, the\n"
    "scene loader and --set overrides; 1 in 16 cases holds a value the loader must\n"
    "refuse (counted as refused, not rendered). Each case is a function of its seed\n"
    "and gets a hash of every texel read and every output (the summary's\n"
    "\"hashes\", in seed order).\n"
    "Every pass counts the values its shaders' sanitisers replace (NaN, Inf,\n"
    "clamped above or below the range), and every target it writes is read back:\n"
    "float targets for NaN/Inf, the packed SSS chain half by half, the depth key's\n"
    "slot, unorm targets in [0, 1]. A NaN or Inf made by a pass, or a bad texel,\n"
    "fails the case, which names the first such pass; clamps are only counted.\n"
    "See docs/stress.md.\n"
    "\n"
    "options:\n"
    "  --cases N       how many cases (default 200)\n"
    "  --seed S        the first case's seed; case i uses S + i (default 1)\n"
    "  --out FILE      the summary JSON (default out/stress.json)\n"
    "  --backend NAME  egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --plant-nan PASS  make the pass named PASS (e.g. lighting, \"shadow:light0(dir)\")\n"
    "                output NaN in every case, to show that it is caught: each case\n"
    "                whose PASS shades a pixel then fails and names PASS; a name no\n"
    "                case's frame runs is a usage error that lists the passes run\n"
    "  --plant-violation NAME  plant a wrong image for one detector (docs/stress.md):\n"
    "                  none|coverage|energy|black|ss-ts|more-light (default none)\n"
    "  --failed-scenes DIR  write each failed case's scene, as its detectors saw\n"
    "                it (after the last frame's move), to DIR/seed-N.json, to\n"
    "                reproduce it with dermis render\n"
    "  --quiet         no progress\n"
    "  --help          this text\n"
    "\n"
    "Each case also runs the wrong-image detectors (coverage, energy, black,\n"
    "ss-ts, more-light; docs/stress.md) and fails when one is violated.\n"
    "\n"
    "Exit status: 0 when no case produced a NaN, an Inf or a bad texel or violated\n"
    "a detector, 1 otherwise or on error, 2 for bad usage. The summary lists every\n"
    "failing case with its seed; a case that cannot be set up at all (e.g. a frame\n"
    "larger than the GL allows), a legal scene the loader refuses, or a hostile\n"
    "value it accepts (or refuses without naming the file or override, the key and\n"
    "the range) is listed as an error and also fails the run.\n";

struct CaseResult {
    uint64_t seed = 0;
    std::string description;
    uint64_t nonFinite = 0;
    bool refused = false;  // a hostile case the loader refused as it must
    uint64_t hash = 0;     // stress/StressHash.h: every texel inspected and every frame's output
    std::string error;
    nlohmann::ordered_json counts;  // a failing case's (stress/StressCounting.h)
    std::vector<std::string> passes;
    bool planted = false;
    stress::InvariantReport invariants;
    std::string sceneJson;  // the case's scene after its frames (scene/SceneLoader.h)
    bool failed() const { return nonFinite > 0 || !error.empty() || invariants.anyViolated(); }
    // Wall-clock seconds by stage: loading the scene and creating the
    // renderer, the inspected frames, the detectors.
    double setUpSeconds = 0.0, frameSeconds = 0.0, detectorSeconds = 0.0;
    double seconds() const { return setUpSeconds + frameSeconds + detectorSeconds; }
};

// Seconds since the last call (or construction).
class Lap {
public:
    double next() {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - mLast).count();
        mLast = now;
        return seconds;
    }

private:
    std::chrono::steady_clock::time_point mLast = std::chrono::steady_clock::now();
};

// What a case is run with besides its own seed.
struct CaseOptions {
    std::shared_ptr<Programs> programs;  // compiled once for every case
    std::string plantPass;               // --plant-nan
    stress::Plant plant = stress::Plant::None;
};

// Renders the case's frames, each inspected and hashed (the scene moves
// between them), then runs the wrong-image detectors on the last frame's scene.
void renderCase(const stress::StressCase& c, Scene& scene, const CaseOptions& options, stress::CountingTotals& totals,
                Lap& lap, CaseResult& result) {
    auto renderer = Renderer::create(scene, options.programs);
    result.setUpSeconds += lap.next();
    if (!renderer.ok()) {
        result.error = renderer.error().message();
        return;
    }
    {
        stress::CaseCounting counting(**renderer, options.plantPass);
        stress::CaseHash hash;
        (*renderer)->setPassInspector(hash.inspector(counting.targetsInspector()));
        for (int frame = 0; frame < c.frames; ++frame) {
            if (frame > 0) stress::advanceFrame(c, scene);
            if (const Status status = (*renderer)->renderFrame({c.width, c.height, c.aov}); !status.ok()) {
                result.error = "frame " + std::to_string(frame) + ": " + status.error().message();
                return;
            }
            auto output = (*renderer)->readOutput();
            if (!output.ok()) {
                result.error = output.error().message();
                return;
            }
            hash.addImage(*output);
        }
        result.hash = hash.value();
        totals.add(counting);
        result.nonFinite = counting.failures();
        if (result.nonFinite > 0) result.counts = stress::failureJson(counting);
        result.passes = (*renderer)->framePasses();
        result.planted = counting.planted();
    }
    result.frameSeconds = lap.next();
    auto invariants = stress::checkCaseInvariants(**renderer, scene, c, options.plant, options.programs);
    if (!invariants.ok()) result.error = invariants.error().message();
    else result.invariants = *invariants;
    result.detectorSeconds = lap.next();
}

CaseResult runCase(const stress::StressCase& c, const CaseOptions& options, stress::CountingTotals& totals) {
    CaseResult result;
    result.seed = c.seed;
    result.description = c.description;
    Lap lap;
    Result<Scene> loaded = stress::loadCaseScene(c);
    result.setUpSeconds = lap.next();
    if (c.path == stress::CasePath::Hostile) {
        result.error = stress::refusalProblem(c, loaded);
        result.refused = result.error.empty();
        stress::CaseHash hash;  // of the refusal, so that a changed message changes the hash
        if (!loaded.ok()) hash.addText(loaded.error().message());
        result.hash = hash.value();
        return result;
    }
    if (!loaded.ok()) {
        result.error = "the loader refused a legal case: " + loaded.error().message();
        return result;
    }
    Scene scene = std::move(*loaded);  // outlives the renderer, which holds a reference
    renderCase(c, scene, options, totals, lap, result);
    if (result.failed()) result.sceneJson = sceneToJson(scene);
    return result;
}

std::string hex(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(value));
    return text;
}

}  // namespace

int runStress(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"cases", "seed", "out", "backend", "plant-nan", "plant-violation", "failed-scenes"}, {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::printf("%s", kHelp);
        return 0;
    }
    if (!args->positional.empty()) return usageError(makeError("stress", "takes no positional arguments"));
    auto cases = parsePositiveInt("--cases", args->get("cases", "200"));
    if (!cases.ok()) return usageError(cases.error());
    auto seed = parsePositiveInt("--seed", args->get("seed", "1"));
    if (!seed.ok()) return usageError(seed.error());
    auto backend = parseBackend(args->get("backend", "auto"));
    if (!backend.ok()) return usageError(backend.error());
    const auto plant = stress::kPlants.parse(args->get("plant-violation", "none"));
    if (!plant) return usageError(makeError("--plant-violation", "expected " + stress::kPlants.list()));
    const std::string outPath = args->get("out", "out/stress.json");
    const bool quiet = args->flags.count("quiet") > 0;
    const std::string plantPass = args->get("plant-nan", "");
    const std::string failedScenesDir = args->get("failed-scenes", "");

    auto context = gl::createHeadlessContext({*backend, false});
    if (!context.ok()) return failure(context.error());
    const std::filesystem::path assets = std::filesystem::temp_directory_path() / "dermis-stress-assets";
    std::error_code ec;
    std::filesystem::create_directories(assets, ec);
    if (const Status written = stress::writeStressAssets(assets.string()); !written.ok()) return failure(written.error());

    // Compiled once for every case (most of a renderer's set-up time); the
    // test Stress.CaseHashesDoNotDependOnEarlierCases checks that no case
    // leaves state in them that changes a later one.
    auto built = Programs::build();
    if (!built.ok()) return failure(built.error());
    const CaseOptions options{std::make_shared<Programs>(std::move(*built)), plantPass, *plant};

    log::setQuiet(true);  // per-case loading messages would drown the progress bar
    const auto start = std::chrono::steady_clock::now();
    // The report and the failed cases' scenes, all or none (docs/cli.md,
    // "Outputs"): failed cases are results, so a run that ends commits them.
    OutputFiles outputs;
    nlohmann::ordered_json failures = nlohmann::ordered_json::array();
    uint64_t totalNonFinite = 0;
    stress::CountingTotals totals;
    std::vector<std::string> passesSeen;  // for --plant-nan's usage error
    bool planted = false;
    int failed = 0;
    stress::InvariantReport invariants;
    int refused = 0;
    double setUpSeconds = 0.0, frameSeconds = 0.0, detectorSeconds = 0.0;
    std::vector<std::pair<double, uint64_t>> caseSeconds;  // (seconds, seed), for the slowest cases
    nlohmann::ordered_json hashes = nlohmann::ordered_json::array();
    {
        std::unique_ptr<log::Progress> progress;
        if (!quiet) {
            log::setQuiet(false);
            progress = std::make_unique<log::Progress>("stress", static_cast<size_t>(*cases));
            log::setQuiet(true);
        }
        for (int i = 0; i < *cases; ++i) {
            const stress::StressCase c = stress::makeStressCase(uint64_t(*seed) + uint64_t(i), assets.string());
            const CaseResult r = runCase(c, options, totals);
            invariants.add(r.invariants);
            totalNonFinite += r.nonFinite;
            planted = planted || r.planted;
            refused += r.refused ? 1 : 0;
            hashes.push_back(hex(r.hash));
            setUpSeconds += r.setUpSeconds;
            frameSeconds += r.frameSeconds;
            detectorSeconds += r.detectorSeconds;
            caseSeconds.emplace_back(r.seconds(), r.seed);
            for (const std::string& pass : r.passes) {
                if (std::find(passesSeen.begin(), passesSeen.end(), pass) == passesSeen.end()) passesSeen.push_back(pass);
            }
            if (r.failed()) {
                ++failed;
                nlohmann::ordered_json f;
                f["seed"] = r.seed;
                f["description"] = r.description;
                f["non_finite"] = r.nonFinite;
                f["pass"] = r.counts.is_object() ? r.counts.value("pass", "") : "";
                f["counts"] = r.counts;
                f["error"] = r.error;
                f["invariants"] = stress::violationsJson(r.invariants);
                if (!failedScenesDir.empty() && !r.sceneJson.empty()) {
                    const std::string path =
                        (std::filesystem::path(failedScenesDir) / ("seed-" + std::to_string(r.seed) + ".json")).string();
                    if (const Status written = outputs.stageText(path, r.sceneJson); written.ok())
                        f["scene"] = path;
                    else
                        f["scene_error"] = written.error().message();
                }
                failures.push_back(f);
            }
            if (progress) {
                log::setQuiet(false);
                progress->advance();
                log::setQuiet(true);
            }
        }
    }
    log::setQuiet(quiet);
    if (!plantPass.empty() && !planted) {
        std::string names;
        for (const std::string& pass : passesSeen) names += (names.empty() ? "" : ", ") + pass;
        return usageError(makeError("--plant-nan", "no case's frame runs a pass named '" + plantPass +
                                                       "'; the frames ran: " + names));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    nlohmann::ordered_json summary;
    summary["cases"] = *cases;
    summary["first_seed"] = *seed;
    summary["renderer"] = (*context)->renderer();
    summary["failed_cases"] = failed;
    summary["plant_nan"] = plantPass;
    summary["refused"] = refused;
    summary["non_finite_texels"] = totalNonFinite;
    summary["counting"] = totals.json();
    summary["plant_violation"] = stress::kPlants.name(*plant);
    summary["invariants"] = stress::countsJson(invariants);
    summary["seconds"] = seconds;
    summary["seconds_by_stage"] = {{"set_up", setUpSeconds}, {"frames", frameSeconds}, {"detectors", detectorSeconds}};
    constexpr size_t kSlowestListed = 5;
    std::sort(caseSeconds.rbegin(), caseSeconds.rend());
    nlohmann::ordered_json slowest = nlohmann::ordered_json::array();
    for (size_t i = 0; i < std::min(kSlowestListed, caseSeconds.size()); ++i)
        slowest.push_back({{"seed", caseSeconds[i].second}, {"seconds", caseSeconds[i].first}});
    summary["slowest_cases"] = slowest;
    summary["failures"] = failures;
    summary["hashes"] = hashes;  // per case, in seed order

    if (const Status written = outputs.stageText(outPath, summary.dump(2) + "\n"); !written.ok())
        return failure(written.error());
    if (const Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());

    std::string failedPasses;
    for (const auto& f : failures) {
        const std::string pass = f.value("pass", "");
        if (!pass.empty() && failedPasses.find("'" + pass + "'") == std::string::npos)
            failedPasses += (failedPasses.empty() ? " in " : ", ") + ("'" + pass + "'");
    }
    std::printf("%d cases in %.1f s: %d failed%s, %d refused as they must be, %llu NaN/Inf/bad values; %s; invariants %s "
                "(%s)\n",
                *cases, seconds, failed, failedPasses.c_str(), refused, static_cast<unsigned long long>(totalNonFinite),
                totals.line().c_str(), stress::countsLine(invariants).c_str(), outPath.c_str());
    return failed == 0 ? 0 : 1;
}

}  // namespace dermis::cli
