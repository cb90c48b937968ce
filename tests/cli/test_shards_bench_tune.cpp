// Shards of `dermis bench` and `dermis tune` (docs/shards.md) through the GNU
// parallel recipe: what one run measures that does not depend on the clock
// (every error, every scale and loss) is the same in the merged output, to the
// last digit; `dermis merge` refuses a missing or foreign shard and writes
// nothing; too many shards is a usage error.
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using dermis::test::ProcessResult;
using dermis::test::readTextFile;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kShardsScript = std::string(DERMIS_SOURCE_DIR) + "/tools/shards.sh";
const std::string kScene = dermis::test::contentScene("default.json");
// As tests/cli/test_bench_cli.cpp: tiny references, one frame, four configurations.
const std::string kBench = " --size 64x36 --frames 1 --density 1 --irradiance-size 512 --no-plots"
                           " --sweep 'ss:sss.taps=5,9;ts:ts.min_size+ts.max_size=256'";
const std::string kTune = " --budget 1% --size 64x36 --distances 1,3 --frames 1 --set shadow.map_size=256";

// results.csv without the columns that come from the clock: the times, and the
// Pareto marks, which weigh the times.
std::vector<std::string> untimedRows(const std::string& path) {
    const std::set<std::string> timed = {"frame_gpu_ms", "sss_gpu_ms", "wall_ms", "pareto", "pareto_scatter"};
    std::istringstream in(readTextFile(path));
    std::string line;
    std::vector<bool> keep;
    std::vector<std::string> rows;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string field, kept;
        for (size_t column = 0; std::getline(fields, field, ','); ++column) {
            if (rows.empty() && keep.size() == column) keep.push_back(timed.count(field) == 0);
            if (column < keep.size() && keep[column]) kept += field + ",";
        }
        rows.push_back(kept);
    }
    return rows;
}

}  // namespace

// ctest: cost=30
TEST(ShardsCliBench, TheMergedDirectoryHoldsTheSingleRunsErrors) {
    TempDir dir;
    const std::string whole = dir.file("whole");
    const ProcessResult single = runProcess(kDermis + " bench " + kScene + " --quiet --out " + whole + kBench);
    ASSERT_EQ(single.exitCode, 0) << single.err;
    const std::string merged = dir.file("merged");
    const ProcessResult sharded =
        runProcess("DERMIS=" + kDermis + " " + kShardsScript + " parallel 2 " + merged + " bench " + kScene + kBench);
    ASSERT_EQ(sharded.exitCode, 0) << sharded.out << sharded.err;

    const std::vector<std::string> expected = untimedRows(whole + "/results.csv");
    const std::vector<std::string> actual = untimedRows(merged + "/results.csv");
    ASSERT_EQ(expected.size(), 5u) << "a header and four configurations";
    EXPECT_EQ(actual, expected);
    // Each default's error image came from the shard that measured it.
    for (const char* image : {"error_ss.png", "error_ts.png"})
        EXPECT_EQ(readTextFile(merged + "/" + image), readTextFile(whole + "/" + image)) << image;
    nlohmann::json a = nlohmann::json::parse(readTextFile(whole + "/summary.json"));
    nlohmann::json b = nlohmann::json::parse(readTextFile(merged + "/summary.json"));
    for (const char* mode : {"ss", "ts"})
        EXPECT_EQ(b["modes"][mode]["default_errors"], a["modes"][mode]["default_errors"]) << mode;
    for (nlohmann::json* summary : {&a, &b}) {
        summary->erase("modes");      // its cheapest configurations weigh times
        summary->erase("reference");  // a path in the shard's directory
    }
    EXPECT_EQ(b, a);

    // Without shard 2 the merge refuses and writes nothing; a stress shard is not a bench shard.
    const std::string out = dir.file("partial");
    ProcessResult missing = runProcess(kDermis + " merge --no-plots --out " + out + " " + merged + ".shards/shard-1");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("shards missing of 2: 2"), std::string::npos) << missing.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    ProcessResult notAShard = runProcess(kDermis + " merge --no-plots --out " + out + " " + whole);
    EXPECT_EQ(notAShard.exitCode, 1);
    EXPECT_NE(notAShard.err.find("bench_shard.json: cannot be read"), std::string::npos) << notAShard.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    ProcessResult tooMany = runProcess(kDermis + " bench " + kScene + " --quiet --shard 5/5 --out " + out + kBench);
    EXPECT_EQ(tooMany.exitCode, 2);
    EXPECT_NE(tooMany.err.find("more shards than configurations (4)"), std::string::npos) << tooMany.err;
}

// ctest: cost=15
TEST(ShardsCliTune, TheMergedTableHoldsTheSingleRunsScalesAndLosses) {
    TempDir dir;
    const ProcessResult single = runProcess(kDermis + " tune " + kScene + " --quiet --out " + dir.file("whole.json") + kTune);
    ASSERT_EQ(single.exitCode, 0) << single.err;
    const std::string merged = dir.file("merged.json");
    const ProcessResult sharded =
        runProcess("DERMIS=" + kDermis + " " + kShardsScript + " parallel 2 " + merged + " tune " + kScene + kTune);
    ASSERT_EQ(sharded.exitCode, 0) << sharded.out << sharded.err;
    const nlohmann::json a = nlohmann::json::parse(readTextFile(dir.file("whole.json")));
    const nlohmann::json b = nlohmann::json::parse(readTextFile(merged));
    ASSERT_EQ(a["rows"].size(), 2u);
    ASSERT_EQ(b["rows"].size(), 2u);
    EXPECT_EQ(b["budget"], a["budget"]);
    EXPECT_EQ(b["size"], a["size"]);
    int sameChoice = 0;
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(b["rows"][i]["pixels_per_mm"], a["rows"][i]["pixels_per_mm"]) << i;
        // The choice weighs times (kTuneTimingTie); where it is the same, so is its loss, to the last digit.
        if (b["rows"][i]["choice"] != a["rows"][i]["choice"]) continue;
        ++sameChoice;
        EXPECT_EQ(b["rows"][i]["loss"], a["rows"][i]["loss"]) << i;
    }
    EXPECT_GE(sameChoice, 1) << "at this size a choice that blurs nothing is far the cheapest at both scales, and "
                                "of those with one loss the first candidate is taken";
    // Each shard's rows, as the shard wrote them (times too), sorted by scale.
    for (int k = 1; k <= 2; ++k) {
        const nlohmann::json shard = nlohmann::json::parse(readTextFile(merged + ".shards/shard-" + std::to_string(k) + ".json"));
        ASSERT_EQ(shard["rows"].size(), 1u);
        EXPECT_EQ(b["rows"][2 - k], shard["rows"][0]) << "distance 1 is the larger scale";
    }
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("merged.md")));

    const std::string out = dir.file("m.json");
    ProcessResult missing = runProcess(kDermis + " merge --out " + out + " " + merged + ".shards/shard-2.json");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("shards missing of 2: 1"), std::string::npos) << missing.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    ProcessResult tooMany = runProcess(kDermis + " tune " + kScene + " --quiet --shard 3/3 --out " + out + kTune);
    EXPECT_EQ(tooMany.exitCode, 2);
    EXPECT_NE(tooMany.err.find("more shards than distances (2)"), std::string::npos) << tooMany.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}
