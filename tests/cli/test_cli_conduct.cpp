// How the program behaves as a tool (docs/cli.md, "Errors"): --version, "did
// you mean" for commands, options and scene keys, warnings that --quiet keeps
// and --no-warnings drops, errors after loading that name the scene file and
// the key, exit status 2 for every command-line mistake (a refused --set
// included), and a warning for a scene that nothing lights.
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
std::string scene() { return dermis::test::contentScene("default.json"); }
const std::string kTiny = " --size 32x18 --frames 1";

}  // namespace

TEST(CliConduct, VersionNamesTheReleaseTheGitRevisionAndTheDataFolders) {
    const ProcessResult r = runProcess(kDermis + " --version");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    // The build tree's program reads the source tree's folders
    // (core/DataDirectory.h); tests/install/ checks an installed one.
    const std::string source = DERMIS_SOURCE_DIR;
    EXPECT_EQ(r.out.substr(r.out.find('\n') + 1),
              "shaders: " + source + "/shaders\ncontent: " + source + "/content\ntools:   " + source + "/tools\n");
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^dermis \d+\.\d+\.\d+ \(git [^)\s]+\)\n)"))) << r.out;
}

TEST(CliConduct, MistypedNamesGetASuggestion) {
    TempDir dir;
    const std::string out = " --out " + dir.file("x.png");
    struct Case {
        std::string arguments;
        std::string message;
    };
    const Case cases[] = {
        {"rendr", "unknown command 'rendr' (did you mean 'render'?)"},
        {"render " + scene() + " --frame 2" + out, "--frame: unknown option (did you mean '--frames'?)"},
        {"render " + scene() + kTiny + " --set sss.tap=5" + out, "unknown key \"tap\": did you mean \"taps\"?"},
        {"render " + scene() + kTiny + " --set mode=sss" + out, "unknown SSS mode \"sss\": did you mean \"ss\"?"},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " " + c.arguments + " --quiet");
        EXPECT_EQ(r.exitCode, 2) << c.arguments << ": every one is a command-line mistake";
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    }
}

TEST(CliConduct, ARefusedSetIsAUsageErrorAsOtherBadValuesAre) {
    TempDir dir;
    for (const std::string& option : {std::string(" --set sss.taps=abc"), std::string(" --size 0x0"), std::string(" --frames -2")}) {
        const ProcessResult r = runProcess(kDermis + " render " + scene() + kTiny + option + " --quiet --out " + dir.file("x.png"));
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.err;
    }
}

TEST(CliConduct, ErrorsAfterLoadingNameTheSceneFileAndTheKey) {
    TempDir dir;
    struct Case {
        std::string set;
        std::string message;
    };
    const Case cases[] = {
        {"'environment={\"source\":\"skyy\"}'",
         "default.json: /environment/source: "},
        {"'characters.0.mesh={\"gltf\":\"missing.gltf\"}'", "default.json: /characters/0/mesh/gltf: "},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " render " + scene() + kTiny + " --quiet --set " + c.set + " --out " + dir.file("x.png"));
        EXPECT_EQ(r.exitCode, 1) << c.set << ": a file the scene names is missing: not a usage error";
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.set << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    }
    const ProcessResult misspelt = runProcess(kDermis + " render " + scene() + kTiny + " --quiet --set 'environment={\"source\":\"skyy\"}' --out " + dir.file("x.png"));
    EXPECT_NE(misspelt.err.find("is not a built-in environment (sky, studio or uniform) (did you mean 'sky'?)"), std::string::npos)
        << misspelt.err;
}

TEST(CliConduct, QuietKeepsWarningsAndNoWarningsDropsThem) {
    TempDir dir;
    const std::string unlit = kDermis + " render " + scene() + kTiny + " --set 'lights=[]' --out " + dir.file("x.png");
    const ProcessResult quiet = runProcess(unlit + " --quiet");
    ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_NE(quiet.err.find("warning: " + scene() + ": no light and no environment; only the ambient term"), std::string::npos)
        << quiet.err;
    EXPECT_EQ(quiet.err.find("loading"), std::string::npos) << "--quiet still silences progress: " << quiet.err;
    const ProcessResult silent = runProcess(unlit + " --quiet --no-warnings");
    ASSERT_EQ(silent.exitCode, 0) << silent.err;
    EXPECT_EQ(silent.err, "");
    // A lit scene draws no such warning.
    const ProcessResult lit = runProcess(kDermis + " render " + scene() + kTiny + " --quiet --out " + dir.file("y.png"));
    EXPECT_EQ(lit.err.find("lights it"), std::string::npos) << lit.err;
}
