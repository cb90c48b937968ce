// `dermis stress --cases 200` (issue: it runs in CI and finds no non-finite texel).
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using dermis::test::runProcess;
using dermis::test::TempDir;

TEST(Stress, TwoHundredCasesFindNoNonFiniteTexel) {
    TempDir dir;
    const std::string summaryPath = dir.file("summary.json");
    const auto r = runProcess(std::string(DERMIS_BINARY) + " stress --cases 200 --seed 1 --quiet --out " + summaryPath);
    const auto summary = nlohmann::json::parse(dermis::test::readTextFile(summaryPath));
    std::printf("%s\n", r.out.c_str());
    EXPECT_EQ(r.exitCode, 0) << r.err << summary["failures"].dump(2);
    EXPECT_EQ(summary["cases"], 200);
    EXPECT_EQ(summary["non_finite_texels"], 0);
    EXPECT_EQ(summary["failed_cases"], 0);
    EXPECT_TRUE(summary["failures"].empty());
    // About 1 in 16 cases is hostile (docs/stress.md, "Cases"); each refused
    // as it must be counts here, one accepted or vaguely refused fails above.
    EXPECT_GT(summary["refused"].get<int>(), 0);
    EXPECT_EQ(summary["hashes"].size(), 200u);
    EXPECT_GT(summary["largest_finite_value"].get<double>(), 65504.0) << "the cases should push past fp16";
}

// Determinism, texel for texel: each case's hash covers every texel the pass
// inspector reads and every frame's output (tools/stress/StressHash.h).
// Runs: A = seeds 77-80, B = the same again, C = seeds 79-80 alone.
// - A and B must agree hash for hash: a case depends on its seed only.
// - The four hashes must differ: a hash that ignored the texels (or a case
//   ignoring its seed) would repeat.
// - C's hashes must equal A's last two: the programs shared across cases
//   (Renderer::create with Programs) carry no state from one case to the next.
TEST(Stress, SameSeedsGiveTheSameCaseHashes) {
    TempDir dir;
    const std::string stress = std::string(DERMIS_BINARY) + " stress --quiet";
    const std::string common = " --cases 4 --seed 77 --out ";
    ASSERT_EQ(runProcess(stress + common + dir.file("a.json")).exitCode, 0);
    ASSERT_EQ(runProcess(stress + common + dir.file("b.json")).exitCode, 0);
    ASSERT_EQ(runProcess(stress + " --cases 2 --seed 79 --out " + dir.file("c.json")).exitCode, 0);
    const auto a = nlohmann::json::parse(dermis::test::readTextFile(dir.file("a.json")))["hashes"];
    const auto b = nlohmann::json::parse(dermis::test::readTextFile(dir.file("b.json")))["hashes"];
    const auto c = nlohmann::json::parse(dermis::test::readTextFile(dir.file("c.json")))["hashes"];
    ASSERT_EQ(a.size(), 4u);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(a, b) << "the same seeds gave different texels";
    for (size_t i = 0; i < a.size(); ++i) {
        for (size_t j = i + 1; j < a.size(); ++j) EXPECT_NE(a[i], a[j]) << "seeds " << 77 + i << " and " << 77 + j;
    }
    EXPECT_EQ(c[0], a[2]) << "seed 79 depends on the cases run before it";
    EXPECT_EQ(c[1], a[3]) << "seed 80 depends on the cases run before it";
}
