// A failed command leaves every output path exactly as it was (docs/cli.md,
// "Outputs"; core/OutputFiles.h): a second output that fails takes the
// first with it. A sequence writes each frame whole as it goes: one that
// fails at a frame keeps the frames before it, and a process killed
// mid-sequence keeps the frames it finished (until 2026-12-07 both kept
// none, and an interrupted long sequence lost every frame).
#include "TestSupport.h"
#include "core/Image.h"

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

TEST(OutputsCli, ASequenceThatFailsAtAFrameKeepsTheFramesBefore) {
    TempDir dir;
    fs::create_directories(dir.path() / "seq_0002.png");  // the third frame's path
    const ProcessResult r = runProcess(kDermis + " render " + kScene + " --size 64x36 --sequence 0:1:4 --out " +
                                       dir.file("seq.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("seq_0002.png: is a directory"), std::string::npos) << r.err;
    // Frames 0 and 1 whole, no temporaries.
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"seq_0000.png", "seq_0001.png", "seq_0002.png"}));
    for (const char* frame : {"seq_0000.png", "seq_0001.png"}) {
        auto image = dermis::loadImage(dir.file(frame), dermis::ColourSpace::Srgb);
        ASSERT_TRUE(image.ok()) << frame << ": " << image.error().message();
        EXPECT_EQ(image->width, 64) << frame;
    }
}

TEST(OutputsCli, AProcessKilledMidSequenceKeepsTheFramesItFinished) {
    TempDir dir;
    dermis::test::writeTextFile(dir.file("seq_0000.png"), "an older frame");
    // Killed (SIGKILL: no handler runs) once it has written its second frame of 40.
    const std::string command = kDermis + " render " + kScene + " --size 64x36 --sequence 0:3.9:10 --out " +
                                dir.file("seq.png") + " 2> " + dir.file("log.txt") + " & pid=$!; " +
                                "for i in $(seq 600); do grep -q 'frame 2/40' " + dir.file("log.txt") +
                                " && break; sleep 0.1; done; kill -9 $pid; wait $pid; echo $?";
    const ProcessResult r = runProcess(command);
    ASSERT_NE(dermis::test::readTextFile(dir.file("log.txt")).find("frame 2/40"), std::string::npos)
        << dermis::test::readTextFile(dir.file("log.txt"));
    EXPECT_EQ(r.out, "137\n");  // killed, not finished
    for (const char* frame : {"seq_0000.png", "seq_0001.png"}) {  // the older frame replaced
        auto image = dermis::loadImage(dir.file(frame), dermis::ColourSpace::Srgb);
        ASSERT_TRUE(image.ok()) << frame << ": " << image.error().message();
        EXPECT_EQ(image->height, 36) << frame;
    }
    for (const std::string& name : namesIn(dir.path())) {
        // Whole frames, the log and at most hidden temporaries (".seq_0002.dermis-PID-N.png").
        const bool expected = (name.rfind("seq_", 0) == 0 && name.size() == 12) || name == "log.txt" || name.rfind(".seq_", 0) == 0;
        EXPECT_TRUE(expected) << name;
    }
}
