// dermis tune: the cheapest screen-space SSS choice within an error budget,
// per on-screen scale, written as a quality table (docs/quality.md).
#include "Args.h"
#include "Commands.h"
#include "QualityTableFiles.h"
#include "measure/QualityTuning.h"
#include "measure/Session.h"

#include "bench/BenchReport.h"
#include "bench/QualityTune.h"
#include "core/Log.h"
#include "core/OutputFiles.h"
#include "core/TextFile.h"
#include "scene/QualityTable.h"
#include "scene/SceneLoader.h"
#include "shards/ShardNote.h"
#include "shards/TuneShards.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace dermis::cli {

using namespace measure;
namespace {

// A choice qualifies when its loss is within this fraction of the budget: the
// loss depends on the content as well as the scale, and on
// content/scenes/crowd8_mixed.json at 640x360 a table tuned at the full
// budget on default.json lost 1.02% (docs/quality.md).
constexpr const char* kDefaultMargin = "0.8";
constexpr size_t kMaxDistances = 16;
constexpr double kMaxDistanceFactor = 1000.0;
// Every measurement is of the screen-space chain, with the scene's own budget
// off (the candidates are what is being chosen).
const std::vector<std::string> kTuneDefinition = {"mode=ss", "quality.error_budget=0"};

const char* const kHelp =
    "usage: dermis tune SCENE --budget B --out FILE [options]\n"
    "\n"
    "The cheapest screen-space SSS choice within an error budget, per on-screen scale.\n"
    "For each distance factor F the camera is dollied back along its view axis to F times\n"
    "its distance from its target; the on-screen scale is the pixels per mm at the SSS\n"
    "characters' nearest depth. At each distance every candidate choice is rendered and\n"
    "measured: the median GPU ms of its SSS passes over N frames, and its LOSS, the\n"
    "relative RMSE of the diffuse AOV over SSS pixels against the finest setting\n"
    "(FINEST, min_width_px 0) at the same view. Of the candidates whose loss is within\n"
    "the margin x the budget, those within TIE% of the cheapest SSS ms count as equally\n"
    "cheap (timings move more than that between runs), and the lowest loss among them\n"
    "becomes that scale's row; the finest when it is among them or none qualifies.\n"
    "Candidates:\n"
    "CANDIDATES"
    "Writes FILE (the quality table JSON a scene's settings.quality.table names) and\n"
    "FILE with the extension .md (the same as a Markdown table). A character at scale s\n"
    "uses the row tuned at the smallest scale >= s, the finest above the largest.\n"
    "\n"
    "options:\n"
    "  --budget B         the error budget: a fraction (0.01) or a percentage (1%); required\n"
    "  --out FILE         the quality table to write (.json); required\n"
    "  --size WxH         the frame size (default 640x360)\n"
    "  --distances LIST   distance factors, comma-separated, each > 0 (default 1,2,4,8)\n"
    "  --frames N         timed frames per measurement, after one warm-up (default 3)\n"
    "  --margin M         a candidate qualifies when its loss <= M x the budget, M in (0, 1]\n"
    "                     (default 0.8: the loss on other scenes differs from the tuned one's)\n"
    "  --set PATH=VALUE   override a scene value for every measurement; repeatable\n"
    "  --shard K/N        tune only the K-th of N parts of the distances (K from 1, N at most\n"
    "                     the number of distances) and write beside FILE its note\n"
    "                     FILE.shard.json; `dermis merge` joins the N tables (docs/shards.md)\n"
    "  --backend NAME     egl or osmesa (default: egl, falling back to osmesa)\n"
    "  --quiet            no progress (warnings stay)\n"
    "  --help             this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the scene, a render or a write fails or no SSS\n"
    "pixel is seen at a distance, 2 for bad command-line usage. Nothing is written unless\n"
    "every measurement succeeds.\n";

Result<std::vector<double>> parseDistances(const std::string& text) {
    std::vector<double> out;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        char* end = nullptr;
        const double value = item.empty() ? NAN : std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !(value > 0.0 && value <= kMaxDistanceFactor)) {
            return makeError("--distances " + text, "each factor must be a number in (0, " +
                                                        std::to_string(int(kMaxDistanceFactor)) + "], got '" + item + "'");
        }
        if (std::find(out.begin(), out.end(), value) != out.end()) {
            return makeError("--distances " + text, "the factor " + item + " is given twice");
        }
        out.push_back(value);
    }
    if (out.empty() || out.size() > kMaxDistances) {
        return makeError("--distances " + text, "expected 1 to " + std::to_string(kMaxDistances) + " factors");
    }
    return out;
}

// Everything a tuned table depends on but the program: the scene as loaded with
// every override, the size, frames, budget, margin and all of the job's distances.
std::string tuneIdentity(const TuneSettings& settings, const Scene& scene) {
    std::string text = "tune " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " frames " +
                       std::to_string(settings.frames) + " budget " + formatNumberForMessage(settings.budget) + " margin " +
                       formatNumberForMessage(settings.margin) + " distances";
    for (double distance : settings.distances) text += " " + formatNumberForMessage(distance);
    return shards::identityOf(text + "\n" + sceneToJson(scene));
}

}  // namespace

int runTune(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"budget", "out", "size", "distances", "frames", "margin", "set", "backend", "shard"},
                          {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::string help = kHelp;
        for (const auto& [word, text] :
             {std::pair<std::string, std::string>{"CANDIDATES", bench::describeTuneCandidates()},
              {"FINEST", describeSssChoice(SssChoice::finest())},
              {"TIE", std::to_string(int(std::lround(100.0 * bench::kTuneTimingTie)))}}) {
            help.replace(help.find(word), word.size(), text);
        }
        std::fputs(help.c_str(), stdout);
        return 0;
    }
    if (args->positional.size() != 1) return usageError(makeError("tune", "expected exactly one SCENE file"));
    if (!args->has("budget")) return usageError(makeError("tune", "--budget B is required (e.g. --budget 1%)"));
    if (!args->has("out")) return usageError(makeError("tune", "--out FILE is required"));
    auto budget = bench::parseBudget(args->get("budget", ""));
    if (!budget.ok()) return usageError(budget.error());
    auto size = parseSize(args->get("size", "640x360"), kMaxFrameDimension);
    if (!size.ok()) return usageError(size.error());
    auto distances = parseDistances(args->get("distances", "1,2,4,8"));
    if (!distances.ok()) return usageError(distances.error());
    auto frames = parsePositiveInt("--frames", args->get("frames", "3"));
    if (!frames.ok()) return usageError(frames.error());
    auto margin = parseFloatIn("--margin", args->get("margin", kDefaultMargin), 1e-6, 1.0);
    if (!margin.ok()) return usageError(margin.error());
    auto backend = parseBackend(args->get("backend", "auto"));
    if (!backend.ok()) return usageError(backend.error());
    const std::string outPath = args->get("out", "");
    if (std::filesystem::path(outPath).extension() != ".json") {
        return usageError(makeError("--out " + outPath, "the quality table must be a .json file"));
    }
    shards::ShardSpec shard;
    if (args->has("shard")) {
        auto parsed = shards::parseShardSpec(args->get("shard", ""));
        if (!parsed.ok()) return usageError(parsed.error());
        if (size_t(parsed->count) > distances->size()) {
            return usageError(makeError("--shard " + parsed->text(),
                                        "more shards than distances (" + std::to_string(distances->size()) + ")"));
        }
        shard = *parsed;
    }
    log::setQuiet(args->flags.count("quiet") > 0);
    const std::string scenePath = args->positional[0];
    const int width = size->first;
    const int height = size->second;

    std::vector<std::string> base = kTuneDefinition;
    for (const std::string& change : args->all("set")) base.push_back(change);
    auto session = Session::open(scenePath, base, *backend, false);
    if (!session.ok()) return failure(session.error());
    TuneSettings settings{scenePath, width, height, *distances, *frames, *budget, *margin};
    const std::string identity = tuneIdentity(settings, *session->scene);
    const shards::ShardRange range = shards::shardRange(shard, int(distances->size()));
    settings.distances.assign(distances->begin() + range.first, distances->begin() + range.first + range.count);
    auto tuned = tuneQualityTable(*session, settings);
    if (!tuned.ok()) return failure(tuned.error());
    OutputFiles outputs;  // every file, or none (docs/cli.md, "Outputs")
    if (Status staged = stageQualityTable(qualityTableJson(*tuned), *tuned, *margin, outPath, outputs); !staged.ok()) return failure(staged.error());
    if (!shard.whole()) {
        const std::string note = shards::tuneShardNoteJson(shard, identity, *distances, *margin);
        if (Status written = outputs.stageText(shards::tuneShardNotePath(outPath), note); !written.ok())
            return failure(written.error());
    }
    if (Status committed = outputs.commit(); !committed.ok()) return failure(committed.error());
    const std::string markdown = bench::qualityTableMarkdown(*tuned, *margin);
    if (!log::quiet()) std::fputs(markdown.c_str(), stdout);
    log::info("wrote " + outPath + " and " + markdownPath(outPath));
    return 0;
}

}  // namespace dermis::cli
