// Shards of `dermis reference` and `dermis stress` (docs/shards.md): the GNU
// parallel recipe and the Slurm job array's scripts (run here as plain bash,
// one task after another) each merge into what one run writes (the image bit
// for bit; the stress summary but for its times); `dermis merge` refuses a
// missing, repeated or foreign shard; bad --shard values are usage errors.
#include "TestSupport.h"

#include "core/Image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kShardsScript = std::string(DERMIS_SOURCE_DIR) + "/tools/shards.sh";
// Small enough to run in a few seconds, with a shadowed head and rows of background.
const std::string kJob = " --size 48x27 --density 2 --spp 1";

std::string scene() { return dermis::test::contentScene("default.json"); }

std::string reference(const std::string& out, const std::string& extra = "") {
    return kDermis + " reference " + scene() + kJob + " --quiet --threads 1" + extra + " --out " + out;
}

// Bit for bit: every texel's four floats.
void expectSameImage(const std::string& expectedPath, const std::string& actualPath) {
    auto expected = dermis::loadImage(expectedPath, dermis::ColourSpace::Linear);
    auto actual = dermis::loadImage(actualPath, dermis::ColourSpace::Linear);
    ASSERT_TRUE(expected.ok()) << expected.error().message();
    ASSERT_TRUE(actual.ok()) << actual.error().message();
    ASSERT_EQ(actual->width, expected->width);
    ASSERT_EQ(actual->height, expected->height);
    size_t different = 0, covered = 0;
    for (size_t i = 0; i < expected->texels.size(); ++i) {
        different += expected->texels[i] != actual->texels[i] ? 1 : 0;
        covered += expected->texels[i].a > 0.0f ? 1 : 0;
    }
    EXPECT_EQ(different, 0u);
    EXPECT_GT(covered, 100u) << "the job should see the head";
}

class ShardsCli : public ::testing::Test {
protected:
    void SetUp() override {
        const ProcessResult whole = runProcess(reference(mDir.file("whole.exr")));
        ASSERT_EQ(whole.exitCode, 0) << whole.err;
    }
    TempDir mDir;
};

TEST_F(ShardsCli, TheGnuParallelRecipeMergesIntoTheSingleRun) {
    const ProcessResult r = runProcess("DERMIS=" + kDermis + " " + kShardsScript + " parallel 2 " + mDir.file("merged.exr") +
                                       " reference " + scene() + kJob);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    expectSameImage(mDir.file("whole.exr"), mDir.file("merged.exr"));
}

TEST_F(ShardsCli, TheSlurmArrayScriptsMergeIntoTheSingleRun) {
    const std::string out = mDir.file("slurm.exr");
    const ProcessResult written = runProcess("DERMIS=" + kDermis + " " + kShardsScript + " slurm 3 " + out + " reference " + scene() + kJob);
    ASSERT_EQ(written.exitCode, 0) << written.err;
    EXPECT_NE(written.out.find("sbatch --dependency=afterany:"), std::string::npos) << written.out;
    for (int task = 1; task <= 3; ++task) {
        const ProcessResult r = runProcess("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + out + ".shards/array.sbatch");
        ASSERT_EQ(r.exitCode, 0) << "task " << task << ": " << r.err;
    }
    const ProcessResult merged = runProcess("bash " + out + ".shards/merge.sbatch");
    ASSERT_EQ(merged.exitCode, 0) << merged.err;
    expectSameImage(mDir.file("whole.exr"), out);
}

TEST_F(ShardsCli, MergeRefusesAMissingRepeatedOrForeignShard) {
    for (int k = 1; k <= 3; ++k) {
        const ProcessResult r = runProcess(reference(mDir.file("s" + std::to_string(k) + ".exr"), " --shard " + std::to_string(k) + "/3"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    const ProcessResult other = runProcess(kDermis + " reference " + scene() + " --size 48x28 --density 2 --spp 1 --quiet "
                                           "--threads 1 --shard 2/3 --out " + mDir.file("other.exr"));
    ASSERT_EQ(other.exitCode, 0) << other.err;
    const std::string out = mDir.file("m.exr");
    struct Case {
        std::string shards;
        std::string message;
    };
    const Case cases[] = {
        {mDir.file("s1.exr") + " " + mDir.file("s3.exr"), "shards missing of 3: 2"},
        {mDir.file("s1.exr") + " " + mDir.file("s2.exr") + " " + mDir.file("s2.exr"), "shard 2/3 is also"},
        {mDir.file("s1.exr") + " " + mDir.file("other.exr") + " " + mDir.file("s3.exr"), "another job's shard"},
        {mDir.file("whole.exr"), "whole.exr.shard.json: cannot be read"},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " merge --out " + out + " " + c.shards);
        EXPECT_EQ(r.exitCode, 1) << c.shards;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written on failure";
    }
    // --out naming one of the shards would overwrite it (a probe found it done, exit 0).
    const ProcessResult onto = runProcess(kDermis + " merge --out " + mDir.file("s1.exr") + " " + mDir.file("s1.exr") + " " +
                                          mDir.file("s2.exr") + " " + mDir.file("s3.exr"));
    EXPECT_EQ(onto.exitCode, 2) << onto.err;
    EXPECT_NE(onto.err.find("is one of the shards"), std::string::npos) << onto.err;
    const ProcessResult all = runProcess(kDermis + " merge --out " + out + " " + mDir.file("s3.exr") + " " + mDir.file("s1.exr") +
                                         " " + mDir.file("s2.exr"));
    ASSERT_EQ(all.exitCode, 0) << all.err;
    expectSameImage(mDir.file("whole.exr"), out);
}

// Stress: 4 cases as one run and as 2 shards through GNU parallel. Every value
// of the merged summary equals the single run's but the times, which no two
// runs share; the seeds' hashes in particular, in seed order. Seed 119 is a
// refused case whose message names an asset file: each process has its own
// asset folder, and a hash that kept the folder's name differed.
TEST(ShardsCliStress, TheMergedSummaryIsTheSingleRunsButForItsTimes) {
    TempDir dir;
    const ProcessResult whole = runProcess(kDermis + " stress --cases 4 --seed 116 --quiet --out " + dir.file("whole.json"));
    ASSERT_EQ(whole.exitCode, 0) << whole.err;
    const ProcessResult sharded = runProcess("DERMIS=" + kDermis + " " + kShardsScript + " parallel 2 " + dir.file("merged.json") +
                                             " stress --cases 4 --seed 116");
    ASSERT_EQ(sharded.exitCode, 0) << sharded.out << sharded.err;
    auto read = [](const std::string& path) {
        std::ifstream in(path);
        nlohmann::json json = nlohmann::json::parse(in);
        for (const char* time : {"seconds", "seconds_by_stage", "slowest_cases"}) {
            EXPECT_TRUE(json.contains(time)) << path << " " << time;
            json.erase(time);
        }
        return json;
    };
    const nlohmann::json expected = read(dir.file("whole.json"));
    const nlohmann::json merged = read(dir.file("merged.json"));
    EXPECT_EQ(merged["hashes"].size(), 4u);
    for (const auto& [key, value] : expected.items()) EXPECT_EQ(merged[key], value) << key;
    EXPECT_EQ(merged.size(), expected.size());
    // Without the second shard the merge refuses and writes nothing.
    const ProcessResult missing = runProcess(kDermis + " merge --out " + dir.file("m.json") + " " + dir.file("merged.json.shards/shard-1.json"));
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("shards missing of 2: 2"), std::string::npos) << missing.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("m.json")));
}

TEST(ShardsCliUsage, BadShardValuesAreUsageErrors) {
    TempDir dir;
    const std::pair<std::string, std::string> cases[] = {
        {"--shard 3/2", "K must be 1 to N"},
        {"--shard 0/2", "K must be 1 to N"},
        {"--shard 1/0", "N must be 1 to"},
        {"--shard 1of2", "expected K/N"},
        {"--shard 1/2 --target-error 0.5", "not with --target-error"},
    };
    for (const auto& [option, message] : cases) {
        const ProcessResult r = runProcess(reference(dir.file("x.exr"), " " + option));
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << option << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.exr")));
    }
}

}  // namespace
