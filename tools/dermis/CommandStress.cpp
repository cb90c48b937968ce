// dermis stress: numerical fuzzing of scenes and settings; every intermediate
// target is checked for non-finite texels.
#include "Args.h"
#include "Commands.h"
#include "Session.h"

#include "core/Log.h"
#include "core/TextFile.h"
#include "gl/GlContext.h"
#include "gl/NonFiniteCounter.h"
#include "frame/Renderer.h"
#include "stress/InvariantFrame.h"
#include "stress/InvariantJson.h"
#include "stress/StressCases.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace dermis::cli {
namespace {

const char* const kHelp =
    "usage: dermis stress [options]\n"
    "\n"
    "Renders N random scenes with extreme settings (SSS widths and tap counts, near\n"
    "and far planes, a camera inside a character, degenerate and zero-area\n"
    "triangles, zero normals, NaN/Inf texels, light intensities past fp16, grazing\n"
    "views, no lights and 64 lights) and reads back every float target every pass\n"
    "writes, counting non-finite texels. Each case is a function of its seed.\n"
    "\n"
    "options:\n"
    "  --cases N       how many cases (default 200)\n"
    "  --seed S        the first case's seed; case i uses S + i (default 1)\n"
    "  --out FILE      the summary JSON (default out/stress.json)\n"
    "  --backend NAME  egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --plant-violation NAME  plant a wrong image for one detector (docs/stress.md):\n"
    "                  none|coverage|energy|black|ss-ts (default none)\n"
    "  --quiet         no progress\n"
    "  --help          this text\n"
    "\n"
    "Each case also runs the wrong-image detectors (coverage, energy, black,\n"
    "ss-ts; docs/stress.md) and fails when one is violated.\n"
    "\n"
    "Exit status: 0 when no case produced a non-finite texel or violated a\n"
    "detector, 1 otherwise or on\n"
    "error, 2 for bad usage. The summary lists every failing case with its seed;\n"
    "a case that cannot be set up at all (e.g. a frame larger than the GL allows)\n"
    "is listed as an error and also fails the run.\n";

struct CaseResult {
    uint64_t seed = 0;
    std::string description;
    uint64_t nonFinite = 0;
    double largest = 0.0;
    std::string error;
    nlohmann::ordered_json badTargets = nlohmann::ordered_json::object();
    stress::InvariantReport invariants;
};

CaseResult runCase(const stress::StressCase& c, stress::Plant plant) {
    CaseResult result;
    result.seed = c.seed;
    result.description = c.description;
    auto renderer = Renderer::create(c.scene);
    if (!renderer.ok()) {
        result.error = renderer.error().message();
        return result;
    }
    gl::NonFiniteCounter counter;
    (*renderer)->setPassInspector(counter.inspector());
    const Status status = (*renderer)->renderFrame({c.width, c.height, c.aov});
    if (!status.ok()) {
        result.error = status.error().message();
        return result;
    }
    result.nonFinite = counter.totalNonFinite();
    result.largest = counter.largest();
    for (const auto& [target, stats] : counter.targets()) {
        if (stats.nonFinite > 0) result.badTargets[target] = stats.nonFinite;
    }
    auto invariants = stress::checkCaseInvariants(**renderer, c, plant);
    if (!invariants.ok()) result.error = invariants.error().message();
    else result.invariants = *invariants;
    return result;
}

}  // namespace

int runStress(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"cases", "seed", "out", "backend", "plant-violation"}, {"quiet", "help"});
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

    auto context = gl::createHeadlessContext({*backend, false});
    if (!context.ok()) return failure(context.error());
    const std::filesystem::path assets = std::filesystem::temp_directory_path() / "dermis-stress-assets";
    std::error_code ec;
    std::filesystem::create_directories(assets, ec);
    if (const Status written = stress::writeStressAssets(assets.string()); !written.ok()) return failure(written.error());

    log::setQuiet(true);  // per-case loading messages would drown the progress bar
    const auto start = std::chrono::steady_clock::now();
    nlohmann::ordered_json failures = nlohmann::ordered_json::array();
    uint64_t totalNonFinite = 0;
    double largest = 0.0;
    int failed = 0;
    stress::InvariantReport invariants;
    {
        std::unique_ptr<log::Progress> progress;
        if (!quiet) {
            log::setQuiet(false);
            progress = std::make_unique<log::Progress>("stress", static_cast<size_t>(*cases));
            log::setQuiet(true);
        }
        for (int i = 0; i < *cases; ++i) {
            const stress::StressCase c = stress::makeStressCase(uint64_t(*seed) + uint64_t(i), assets.string());
            const CaseResult r = runCase(c, *plant);
            invariants.add(r.invariants);
            totalNonFinite += r.nonFinite;
            largest = std::max(largest, r.largest);
            if (r.nonFinite > 0 || !r.error.empty() || r.invariants.anyViolated()) {
                ++failed;
                nlohmann::ordered_json f;
                f["seed"] = r.seed;
                f["description"] = r.description;
                f["non_finite"] = r.nonFinite;
                f["targets"] = r.badTargets;
                f["error"] = r.error;
                f["invariants"] = stress::violationsJson(r.invariants);
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
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    nlohmann::ordered_json summary;
    summary["cases"] = *cases;
    summary["first_seed"] = *seed;
    summary["renderer"] = (*context)->renderer();
    summary["failed_cases"] = failed;
    summary["non_finite_texels"] = totalNonFinite;
    summary["largest_finite_value"] = largest;
    summary["plant_violation"] = stress::kPlants.name(*plant);
    summary["invariants"] = stress::countsJson(invariants);
    summary["seconds"] = seconds;
    summary["failures"] = failures;

    if (const Status written = writeTextFileAtomically(outPath, summary.dump(2) + "\n"); !written.ok())
        return failure(written.error());

    std::printf("%d cases in %.1f s: %d failed, %llu non-finite texels, largest finite value %.3g; invariants %s (%s)\n",
                *cases, seconds, failed, static_cast<unsigned long long>(totalNonFinite), largest,
                stress::countsLine(invariants).c_str(), outPath.c_str());
    return failed == 0 ? 0 : 1;
}

}  // namespace dermis::cli
