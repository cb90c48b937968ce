// `dermis tune`: the quality table from the command line, end to end on a
// tiny frame (docs/quality.md).
#include "TestSupport.h"

#include "scene/QualityTable.h"

#include <gtest/gtest.h>

#include <filesystem>

using dermis::QualityTable;
using dermis::SssChoice;
using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kScene = dermis::test::contentScene("default.json");
// Tiny on purpose: 23 candidates + the finest at each of 2 distances, one
// timed frame each (about 20 s on llvmpipe).
const std::string kSmall = " --size 64x36 --distances 1,3 --frames 1 --set shadow.map_size=256 --quiet";

QualityTable readTable(const std::string& path) {
    auto table = dermis::loadQualityTable(path);
    EXPECT_TRUE(table.ok()) << table.error().message();
    return table.ok() ? *table : QualityTable{};
}

}  // namespace

TEST(TuneCli, WritesASortedTableWithinTheBudgetAndTheFinestWhenNothingFits) {
    TempDir dir;
    const std::string out = dir.file("table.json");
    ProcessResult r = runProcess(kDermis + " tune " + kScene + " --budget 1% --out " + out + kSmall);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const QualityTable table = readTable(out);
    EXPECT_DOUBLE_EQ(float(table.budget), 0.01f);
    EXPECT_EQ(table.width, 64);
    ASSERT_EQ(table.rows.size(), 2u);
    // Sorted by scale (the loader refuses anything else) and 3x the distance
    // is about a third of the scale (the nearest depth is not the target's).
    EXPECT_LT(table.rows[0].pixelsPerMm, table.rows[1].pixelsPerMm / 2.0f);
    for (const dermis::QualityRow& row : table.rows) EXPECT_LE(row.loss, 0.01);
    EXPECT_TRUE(std::filesystem::exists(dir.file("table.md")));
    EXPECT_NE(dermis::test::readTextFile(dir.file("table.md")).find("| pixels per mm"), std::string::npos);

    // No candidate is within 1e-9 of the finest: the row is the finest, loss 0
    // (one distance: the test's time).
    const std::string strict = dir.file("strict.json");
    r = runProcess(kDermis + " tune " + kScene + " --budget 0.000000001 --out " + strict + kSmall + " --distances 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const QualityTable finest = readTable(strict);
    ASSERT_EQ(finest.rows.size(), 1u);
    for (const dermis::QualityRow& row : finest.rows) {
        EXPECT_EQ(row.choice, SssChoice::finest());
        EXPECT_EQ(row.loss, 0.0);
    }
}

TEST(TuneCli, BadInputFailsClearlyAndWritesNothing) {
    TempDir dir;
    const std::string out = dir.file("table.json");
    const std::vector<std::tuple<std::string, int, std::string>> cases = {
        {kScene + " --budget 0 --out " + out, 2, "--budget 0"},
        {kScene + " --budget 150% --out " + out, 2, "must be in (0, 1)"},
        {kScene + " --budget one --out " + out, 2, "a percentage"},
        {kScene + " --budget 1% --out " + out + " --size 0x10", 2, "0x10"},
        {kScene + " --budget 1% --out " + out + " --distances 1,-2", 2, "--distances"},
        {kScene + " --budget 1% --out " + dir.file("table.txt"), 2, ".json"},
        {kScene + " --budget 1% --out " + out + " --margin 1.5", 2, "--margin"},
        {dir.file("nothing.json") + " --budget 1% --out " + out, 1, "nothing.json"},
        {kScene + " --out " + out, 2, "--budget B is required"},
    };
    for (const auto& [args, code, message] : cases) {
        const ProcessResult r = runProcess(kDermis + " tune " + args);
        EXPECT_EQ(r.exitCode, code) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
    const ProcessResult help = runProcess(kDermis + " tune --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("separable: samples=7; samples=11"), std::string::npos) << help.out;
}
