// dermis: the command-line front end. Each subcommand lives in its own
// Command*.cpp and is listed in commands().
#include "CommandReference.h"
#include "Commands.h"

#include "core/DataDirectory.h"
#include "core/Log.h"
#include "core/Suggest.h"

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace dermis::cli {

const std::vector<Command>& commands() {
    static const std::vector<Command> kCommands = {
        {"render", "render a scene headlessly to PNG/EXR and report per-pass GPU timings", runRender},
        {"stress", "fuzz scenes and settings: count sanitised values per pass, read every target, check wrong-image detectors and refusals", runStress},
        {"soak", "memory over a long run with the scene changing: resident and texture-pool bytes stay flat", runSoak},
        {"compare", "render one frame in screen-space and texture-space SSS: images, heatmap, metrics", runCompare},
        {"reference", "CPU reference of the diffuse AOV: the subsurface integral by brute force", runReference},
        {"bench", "run time against error: sweep the quality knobs of both modes against the CPU reference", runBench},
        {"tune", "the cheapest SSS choice within an error budget per on-screen scale: write a quality table", runTune},
        {"merge", "join the shards of a `reference`, `stress`, `bench` or `tune` job run with --shard K/N into what one run writes", runMerge},
        {"view", "open a window on a scene: live settings, A/B split, AOVs, live GPU profiler", runView},
        {"bake-lean", "bake LEAN maps (bump centre and second moments, full mip chain) from a normal map", runBakeLean},
    };
    return kCommands;
}

}  // namespace dermis::cli

namespace {

void printUsage(std::FILE* out) {
    std::fprintf(out,
                 "Dermis: real-time skin rendering (screen-space and texture-space subsurface scattering).\n\n"
                 "usage: dermis <command> [options]   (dermis <command> --help for its options)\n\ncommands:\n");
    for (const auto& command : dermis::cli::commands()) std::fprintf(out, "  %-10s %s\n", command.name, command.summary);
    std::fprintf(out,
                 "\noptions of every command:\n"
                 "  --quiet        no progress (warnings still print)\n"
                 "  --no-warnings  no warnings (progress stays unless --quiet; errors always print)\n"
                 "  --help         the command's options\n"
                 "\n"
                 "dermis --version prints the version, the git revision it was built from and the\n"
                 "folders it reads its shaders, content and plot scripts from (docs/install.md).\n"
                 "Exit status: 0 on success, 1 when the work fails (a file, a scene, a render), 2 for bad\n"
                 "command-line usage.\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        printUsage(stderr);
        return 2;
    }
    const std::string name = argv[1];
    if (name == "--help" || name == "-h" || name == "help") {
        printUsage(stdout);
        return 0;
    }
    if (name == "--version" || name == "version") {
        std::printf("dermis %s (git %s)\n", DERMIS_VERSION, dermis::cli::gitRevision());
        using dermis::DataKind;
        std::printf("shaders: %s\ncontent: %s\ntools:   %s\n", dermis::dataDirectory(DataKind::Shaders).c_str(),
                    dermis::dataDirectory(DataKind::Content).c_str(), dermis::dataDirectory(DataKind::Tools).c_str());
        return 0;
    }
    std::vector<std::string> arguments;
    for (int i = 2; i < argc; ++i) {
        if (std::string(argv[i]) == "--no-warnings") {
            dermis::log::setWarnings(false);
        } else {
            arguments.emplace_back(argv[i]);
        }
    }
    for (const auto& command : dermis::cli::commands()) {
        if (name != command.name) continue;
        // The last line of defence: every expected failure is an error value
        // with its own message; these say what broke instead of aborting.
        try {
            return command.run(arguments);
        } catch (const std::bad_alloc&) {
            std::fprintf(stderr, "error: dermis %s: out of memory (try a smaller --size, or fewer frames or samples)\n",
                         command.name);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "error: dermis %s: internal error: %s (please report it)\n", command.name, e.what());
        }
        return 1;
    }
    std::vector<std::string> names;
    for (const auto& command : dermis::cli::commands()) names.push_back(command.name);
    std::fprintf(stderr, "error: unknown command '%s'%s (run 'dermis --help' for the list)\n", name.c_str(),
                 dermis::didYouMean(name, names).c_str());
    return 2;
}
