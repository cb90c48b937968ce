// dermis_benchmarks: Google Benchmark runs, then the comparisons the issues
// ask for, printed as ratios measured side by side in this one run.
#include "AnimatedCrowdBenchmarks.h"
#include "BenchContext.h"
#include "CrowdBenchmarks.h"
#include "EnvironmentBenchmarks.h"
#include "GltfDecodeBenchmarks.h"
#include "LeanBenchmarks.h"
#include "ParallelLoopBenchmarks.h"
#include "ProfilingBenchmarks.h"
#include "QualityBenchmarks.h"
#include "RayBenchmarks.h"
#include "TechniqueBenchmarks.h"
#include "TsBenchmarks.h"

#include "core/Log.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

namespace {

void printRatio(const char* what, const std::string& numerator, const std::string& denominator, double limit) {
    const auto& r = dermis::bench::recorded();
    const auto n = r.find(numerator);
    const auto d = r.find(denominator);
    if (n == r.end() || d == r.end() || d->second <= 0.0) return;
    const double ratio = n->second / d->second;
    std::printf("%-58s %8.3f ms / %8.3f ms = %5.2fx%s\n", what, n->second, d->second, ratio,
                limit > 0.0 ? (ratio <= limit ? "  (within the target)" : "  (OVER the target)") : "");
}

}  // namespace

int main(int argc, char** argv) {
    dermis::log::setQuiet(true);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    std::printf("renderer: %s\n", dermis::bench::context().renderer().c_str());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    std::printf("\nComparisons (median GPU ms of the SSS passes, same machine, same run):\n");
    for (const char* size : {"640x360", "1280x720"}) {
        const std::string floor(dermis::kSssBlurs.name(dermis::SssBlur::FetchOnly));
        for (const dermis::SssBlur blur : {dermis::SssBlur::Bilateral, dermis::SssBlur::Control}) {
            const std::string mode(dermis::kSssBlurs.name(blur));
            const std::string what = "SSS blur " + mode + " / " + floor + " floor, " + size;
            printRatio(what.c_str(), "blur/" + mode + "/" + size, "blur/" + floor + "/" + size, 1.25);
        }
    }
    const auto& r = dermis::bench::recorded();
    for (const char* layout : {"1 head", "4 heads, same pixels", "1 head, 4x pixels"}) {
        const std::string key = std::string("layout/") + layout;
        if (r.count(key) == 0) continue;
        const double ms = r.at(key);
        const double pixels = r.at(key + "/pixels");
        std::printf("%-24s %8.0f SSS pixels %8.3f ms  %6.3f ms per 10k SSS pixels\n", layout, pixels, ms,
                    pixels > 0 ? 1e4 * ms / pixels : 0.0);
    }
    dermis::bench::printTextureSpaceSummary();
    dermis::bench::printLeanSummary();
    dermis::bench::printCrowdSummary();
    dermis::bench::printGltfDecodeSummary();
    dermis::bench::printAnimatedCrowdSummary();
    dermis::bench::printEnvironmentSummary();
    dermis::bench::printTechniqueSummary();
    dermis::bench::printQualitySummary();
    dermis::bench::printRaySummary();
    dermis::bench::printParallelLoopSummary();
    dermis::bench::printProfilingSummary();
    return 0;
}
