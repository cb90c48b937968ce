// All-or-nothing outputs (core/OutputFiles.h): nothing reaches a destination
// before the commit, a commit that fails half-way puts back what was there,
// and nothing is left behind, not even a directory made for the outputs.
#include "TestSupport.h"

#include "core/OutputFiles.h"
#include "core/ImageResample.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace dermis;
using dermis::test::namesIn;
namespace fs = std::filesystem;

TEST(OutputFiles, NothingReachesADestinationBeforeTheCommit) {
    test::TempDir dir;
    {
        OutputFiles out;
        ASSERT_TRUE(out.stageText(dir.file("a.json"), "{}"));
        ASSERT_TRUE(out.stageImage(dir.file("b.png"), makeImage(2, 2, ColourSpace::Linear, glm::vec4(0.5f))));
        EXPECT_FALSE(fs::exists(dir.file("a.json")));
        EXPECT_FALSE(fs::exists(dir.file("b.png")));
        EXPECT_EQ(namesIn(dir.path()).size(), 2u);  // the two hidden temporaries
        ASSERT_TRUE(out.commit());
    }
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"a.json", "b.png"}));
    EXPECT_EQ(test::readTextFile(dir.file("a.json")), "{}");
}

TEST(OutputFiles, WithoutACommitEveryPathStaysAsItWas) {
    test::TempDir dir;
    test::writeTextFile(dir.file("a.json"), "old");
    {
        OutputFiles out;
        ASSERT_TRUE(out.stageText(dir.file("a.json"), "new"));
        ASSERT_TRUE(out.stageText(dir.file("made/deeper/c.txt"), "new"));
        // A later output fails: the command returns without committing.
        EXPECT_FALSE(out.stageImage(dir.file("d.jpg"), makeImage(1, 1, ColourSpace::Linear)));
    }
    EXPECT_EQ(test::readTextFile(dir.file("a.json")), "old");
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"a.json"}));  // no temporaries, no "made/"
}

TEST(OutputFiles, AFailedMovePutsBackWhatWasThere) {
    test::TempDir dir;
    test::writeTextFile(dir.file("a.json"), "old a");
    OutputFiles out;
    ASSERT_TRUE(out.stageText(dir.file("a.json"), "new a"));
    ASSERT_TRUE(out.stageText(dir.file("b.json"), "new b"));
    ASSERT_TRUE(out.stageText(dir.file("c.json"), "new c"));
    // Between staging and the commit, c.json becomes a directory that is not
    // empty: a.json and b.json move, c.json cannot.
    fs::create_directories(dir.path() / "c.json" / "x");
    const Status committed = out.commit();
    ASSERT_FALSE(committed);
    EXPECT_NE(committed.error().message().find("c.json"), std::string::npos) << committed.error().message();
    EXPECT_EQ(test::readTextFile(dir.file("a.json")), "old a");
    EXPECT_FALSE(fs::exists(dir.file("b.json")));
    EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"a.json", "c.json"}));
    EXPECT_EQ(namesIn(dir.path() / "c.json"), (std::vector<std::string>{"x"}));
}

TEST(OutputFiles, ADirectoryMadeForTheOutputsGoesWithoutACommit) {
    test::TempDir dir;
    {
        OutputFiles out;
        ASSERT_TRUE(out.prepareDirectory(dir.file("bench/run1")));
        EXPECT_TRUE(fs::is_directory(dir.file("bench/run1")));
    }
    EXPECT_TRUE(namesIn(dir.path()).empty());
    OutputFiles kept;
    ASSERT_TRUE(kept.prepareDirectory(dir.file("bench")));
    ASSERT_TRUE(kept.stageText(dir.file("bench/summary.json"), "{}"));
    ASSERT_TRUE(kept.commit());
    EXPECT_EQ(namesIn(dir.path() / "bench"), (std::vector<std::string>{"summary.json"}));
}
