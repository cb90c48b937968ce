// A failed command leaves every output path exactly as it was (docs/cli.md,
// "Outputs"; core/OutputFiles.h): a second output that fails takes the
// first with it, a sequence that fails at a frame keeps none, and a process
// killed mid-sequence leaves the destinations untouched.
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;
using dermis::test::namesIn;
namespace fs = std::filesystem;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kScene = dermis::test::contentScene("default.json");


}  // namespace

TEST(OutputsCli, AFailingTimingsFileKeepsTheImageAsItWas) {
    TempDir dir;
    dermis::test::writeTextFile(dir.file("frame.png"), "an older frame");
    fs::create_directories(dir.path() / "timings.json");  // --timings names a directory
    const ProcessResult r = runProcess(kDermis + " render " + kScene + " --size 64x36 --frames 1 --out " +
                                       dir.file("frame.png") + " --timings " + dir.file("timings.json"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("timings.json: is a directory"), std::string::npos) << r.err;
    EXPECT_EQ(dermis::test::readTextFile(dir.file("frame.png")), "an older frame");
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"frame.png", "timings.json"}));
}

TEST(OutputsCli, ASequenceThatFailsAtAFrameKeepsNone) {
    TempDir dir;
    fs::create_directories(dir.path() / "seq_0002.png");  // the third frame's path
    const ProcessResult r = runProcess(kDermis + " render " + kScene + " --size 64x36 --sequence 0:1:4 --out " +
                                       dir.file("seq.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("seq_0002.png: is a directory"), std::string::npos) << r.err;
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"seq_0002.png"}));  // frames 0 and 1 gone, no temporaries
}

TEST(OutputsCli, AProcessKilledMidSequenceLeavesTheDestinationsUntouched) {
    TempDir dir;
    dermis::test::writeTextFile(dir.file("seq_0000.png"), "an older frame");
    // Killed (SIGKILL: no handler runs) once it has staged its second frame of 40.
    const std::string command = kDermis + " render " + kScene + " --size 64x36 --sequence 0:3.9:10 --out " +
                                dir.file("seq.png") + " 2> " + dir.file("log.txt") + " & pid=$!; " +
                                "for i in $(seq 600); do grep -q 'frame 2/40' " + dir.file("log.txt") +
                                " && break; sleep 0.1; done; kill -9 $pid; wait $pid; echo $?";
    const ProcessResult r = runProcess(command);
    ASSERT_NE(dermis::test::readTextFile(dir.file("log.txt")).find("frame 2/40"), std::string::npos)
        << dermis::test::readTextFile(dir.file("log.txt"));
    EXPECT_EQ(r.out, "137\n");  // killed, not finished
    EXPECT_EQ(dermis::test::readTextFile(dir.file("seq_0000.png")), "an older frame");
    for (const std::string& name : namesIn(dir.path())) {
        // Only the older frame, the log and hidden temporaries (".seq_0001.dermis-PID-N.png").
        const bool expected = name == "seq_0000.png" || name == "log.txt" || name.rfind(".seq_", 0) == 0;
        EXPECT_TRUE(expected) << name;
    }
}
