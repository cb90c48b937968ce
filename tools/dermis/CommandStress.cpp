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
#include "stress/StressCases.h"
#include "stress/StressHash.h"
#include "stress/StressLoading.h"

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
    "Renders N random scenes with extreme settings (SSS widths and tap counts, both\n"
    "SSS modes and every variant, every AOV, frames from 1x1 to 1280x720, near and\n"
    "far planes, a camera inside a character, degenerate triangles, glTFs without\n"
    "normals or UVs or with duplicate vertices, NaN/Inf texels, lights past fp16\n"
    "and of every size, no lights and 64 lights), 1 to 4 frames each with the\n"
    "camera and a light moving, and reads back every float target every pass\n"
    "writes, counting non-finite texels. A quarter of the scenes go through a\n"
    "JSON file, the scene loader and --set overrides; 1 in 16 cases holds a value\n"
    "the loader must refuse (counted as refused, not rendered). Each case is a\n"
    "function of its seed and gets a hash of every texel read and every output\n"
    "(the summary's \"hashes\", in seed order). See docs/stress.md.\n"
    "\n"
    "options:\n"
    "  --cases N       how many cases (default 200)\n"
    "  --seed S        the first case's seed; case i uses S + i (default 1)\n"
    "  --out FILE      the summary JSON (default out/stress.json)\n"
    "  --backend NAME  egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --quiet         no progress\n"
    "  --help          this text\n"
    "\n"
    "Exit status: 0 when no case produced a non-finite texel, 1 otherwise or on\n"
    "error, 2 for bad usage. The summary lists every failing case with its seed;\n"
    "a case that cannot be set up at all (e.g. a frame larger than the GL allows),\n"
    "a legal scene the loader refuses, or a hostile value it accepts (or refuses\n"
    "without naming the file or override, the key and the range) is listed as an\n"
    "error and also fails the run.\n";

struct CaseResult {
    uint64_t seed = 0;
    std::string description;
    uint64_t nonFinite = 0;
    double largest = 0.0;
    bool refused = false;  // a hostile case the loader refused as it must
    uint64_t hash = 0;     // stress/StressHash.h: every texel inspected and every frame's output
    std::string error;
    nlohmann::ordered_json badTargets = nlohmann::ordered_json::object();
};

// Renders the case's frames, each inspected and hashed; the scene moves between them.
void renderCase(const stress::StressCase& c, Scene& scene, const std::shared_ptr<Programs>& programs,
                CaseResult& result) {
    auto renderer = Renderer::create(scene, programs);
    if (!renderer.ok()) {
        result.error = renderer.error().message();
        return;
    }
    gl::NonFiniteCounter counter;
    stress::CaseHash hash;
    (*renderer)->setPassInspector(hash.inspector(counter.inspector()));
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
    result.nonFinite = counter.totalNonFinite();
    result.largest = counter.largest();
    for (const auto& [target, stats] : counter.targets()) {
        if (stats.nonFinite > 0) result.badTargets[target] = stats.nonFinite;
    }
}

CaseResult runCase(const stress::StressCase& c, const std::shared_ptr<Programs>& programs) {
    CaseResult result;
    result.seed = c.seed;
    result.description = c.description;
    Result<Scene> loaded = stress::loadCaseScene(c);
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
    renderCase(c, scene, programs, result);
    return result;
}

std::string hex(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(value));
    return text;
}

}  // namespace

int runStress(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"cases", "seed", "out", "backend"}, {"quiet", "help"});
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
    const std::string outPath = args->get("out", "out/stress.json");
    const bool quiet = args->flags.count("quiet") > 0;

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
    const auto programs = std::make_shared<Programs>(std::move(*built));

    log::setQuiet(true);  // per-case loading messages would drown the progress bar
    const auto start = std::chrono::steady_clock::now();
    nlohmann::ordered_json failures = nlohmann::ordered_json::array();
    uint64_t totalNonFinite = 0;
    double largest = 0.0;
    int failed = 0;
    int refused = 0;
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
            const CaseResult r = runCase(c, programs);
            totalNonFinite += r.nonFinite;
            largest = std::max(largest, r.largest);
            refused += r.refused ? 1 : 0;
            hashes.push_back(hex(r.hash));
            if (r.nonFinite > 0 || !r.error.empty()) {
                ++failed;
                nlohmann::ordered_json f;
                f["seed"] = r.seed;
                f["description"] = r.description;
                f["non_finite"] = r.nonFinite;
                f["targets"] = r.badTargets;
                f["error"] = r.error;
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
    summary["refused"] = refused;
    summary["non_finite_texels"] = totalNonFinite;
    summary["largest_finite_value"] = largest;
    summary["seconds"] = seconds;
    summary["failures"] = failures;
    summary["hashes"] = hashes;  // per case, in seed order

    if (const Status written = writeTextFileAtomically(outPath, summary.dump(2) + "\n"); !written.ok())
        return failure(written.error());

    std::printf("%d cases in %.1f s: %d failed, %d refused as they must be, %llu non-finite texels, largest finite value %.3g (%s)\n", *cases,
                seconds, failed, refused, static_cast<unsigned long long>(totalNonFinite), largest, outPath.c_str());
    return failed == 0 ? 0 : 1;
}

}  // namespace dermis::cli
