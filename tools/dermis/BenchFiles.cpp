#include "BenchFiles.h"

#include "Python.h"

#include "core/Log.h"
#include "core/TextFile.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

namespace dermis::cli {
namespace {

// Draws the plots of `texts` (the CSV and JSON files, by name) in a hidden
// directory inside outDir, and stages each plot as outDir's file.
Status stagePlots(const std::filesystem::path& outDir, const std::vector<std::pair<std::string, std::string>>& texts,
                  OutputFiles& outputs) {
    namespace fs = std::filesystem;
    const fs::path drawing = outDir / (".plots.dermis-" + std::to_string(::getpid()));
    struct RemoveAfter {
        fs::path dir;
        ~RemoveAfter() {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    } removeAfter{drawing};
    for (const auto& [name, text] : texts)
        if (Status written = writeTextFileAtomically((drawing / name).string(), text); !written.ok()) return written;
    const std::string script = toolScript("plot_bench.py");
    const std::string command = pythonInterpreter() + " '" + script + "' '" + drawing.string() + "'";
    if (std::system(command.c_str()) != 0) {
        return makeError(script, "plotting failed (it needs python3 with matplotlib: apt-get install python3-matplotlib); "
                                 "nothing was written, --no-plots skips the plots");
    }
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(drawing, error)) {
        // What the plot script draws: the PNGs and errors.md (the inputs it read stay behind).
        if (entry.path().extension() != ".png" && entry.path().filename() != "errors.md") continue;
        const std::string target = (outDir / entry.path().filename()).string();
        if (Status staged = outputs.stageFile(target, entry.path()); !staged.ok()) return staged;
    }
    if (error) return makeError(drawing.string(), "could not list the plots: " + error.message());
    return success();
}

}  // namespace

Status stageBenchTables(const std::filesystem::path& outDir, const std::vector<bench::BenchRow>& rows,
                        const nlohmann::ordered_json& summary, bool plots, OutputFiles& outputs) {
    const std::vector<std::pair<std::string, std::string>> texts = {{"results.csv", bench::resultsCsv(rows)},
                                                                     {"passes.csv", bench::passesCsv(rows)},
                                                                     {"summary.json", summary.dump(2) + "\n"}};
    for (const auto& [name, text] : texts)
        if (Status written = outputs.stageText((outDir / name).string(), text); !written.ok()) return written;
    return plots ? stagePlots(outDir, texts, outputs) : success();
}

void printBenchDefaults(const nlohmann::ordered_json& summary) {
    for (const auto& [mode, entry] : summary["modes"].items()) {
        if (log::quiet() || entry["default"].is_null()) continue;
        std::printf("%s default: %.1f ms, relative RMSE %.2f%% (scatter %.2f%%)\n", mode.c_str(),
                    entry["default"]["frame_gpu_ms"].get<double>(), 100.0 * entry["default"]["relative_rmse"].get<double>(),
                    entry["default"]["scatter_relative_rmse"].is_null()
                        ? NAN : 100.0 * entry["default"]["scatter_relative_rmse"].get<double>());
    }
}

}  // namespace dermis::cli
