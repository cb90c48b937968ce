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
        // Option values of a closed set, as docs/cli.md promises (a probe found them without).
        {"render " + scene() + kTiny + " --aov normals" + out, "(did you mean 'normal'?)"},
        {"render " + scene() + kTiny + " --mode sss" + out, "--mode sss: expected ss or ts (did you mean 'ss'?)"},
        {"render " + scene() + kTiny + " --variant lbv" + out, "(did you mean 'lbb'?)"},
        {"view " + scene() + " --view splt", "--view splt: expected single, split or diff (did you mean 'split'?)"},
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

// Mistakes a user found that the program used to meet late, silently or with
// the wrong words: each is now one error line, found before the work, naming
// what the user gave (not a hidden temporary), with the usage status where it
// is a command-line mistake.
TEST(CliConduct, OutputMistakesAreFoundBeforeTheWorkAndNamedAsGiven) {
    TempDir dir;
    dermis::test::writeTextFile(dir.file("a-file"), "not a folder");
    std::filesystem::create_directories(dir.file("bench-a"));
    struct Case {
        std::string arguments;
        int exitCode;
        std::string message;
        std::string mustNotExist;
    };
    const Case cases[] = {
        {"render " + scene() + kTiny + " --out " + dir.file("a-file/x.png"), 1,
         dir.file("a-file") + ": cannot create the directory: a file of that name is in the way", dir.file("a-file/x.png")},
        {"stress --cases 2 --failed-scenes " + dir.file("a-file") + " --out " + dir.file("s.json"), 1,
         "--failed-scenes " + dir.file("a-file") + ": cannot create the directory", dir.file("s.json")},
        {"merge --out " + dir.file("m.exr") + " " + dir.file("bench-a") + " " + dir.file("bench-a"), 2,
         "--out " + dir.file("m.exr") + ": bench shard directories merge into a directory, not a .exr file", dir.file("m.exr")},
        {"merge --out " + dir.file("m.exr") + " " + dir.file("gone.exr"), 1, dir.file("gone.exr") + ": no such file or directory",
         dir.file("m.exr")},
        {"bench " + scene() + " --size 16x9 --out " + dir.file("b") + " --irradiance-size 100", 2,
         "--irradiance-size: must be a power of two from 64 to 8192, got 100", dir.file("b/reference.exr")},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " " + c.arguments);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.arguments << "\n" << r.err;
        EXPECT_NE(r.err.find("error: " + c.message), std::string::npos) << c.arguments << "\n" << r.err;
        EXPECT_EQ(r.err.find(".dermis-"), std::string::npos) << "names a temporary:\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(c.mustNotExist)) << c.arguments;
    }
    const ProcessResult help = runProcess(kDermis + " render -h");
    EXPECT_EQ(help.exitCode, 0) << help.err;
    EXPECT_EQ(help.out.rfind("usage: dermis render", 0), 0u) << help.out;
}
