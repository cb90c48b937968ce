#pragma once
// Every `dermis` subcommand: a name, a one-line summary, its --help text and
// its entry point. Each lives in its own Command*.cpp.

#include <string>
#include <vector>

namespace dermis::cli {

struct Command {
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>& args);  // args after the command name
};

int runRender(const std::vector<std::string>& args);
int runStress(const std::vector<std::string>& args);
int runSoak(const std::vector<std::string>& args);
int runCompare(const std::vector<std::string>& args);
int runView(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);
int runBakeLean(const std::vector<std::string>& args);
int runTune(const std::vector<std::string>& args);
int runMerge(const std::vector<std::string>& args);

const std::vector<Command>& commands();

// `git describe --always --dirty` of the checkout the program was built from
// (generated at build time by tools/cmake/GitRevision.cmake).
const char* gitRevision();

}  // namespace dermis::cli
