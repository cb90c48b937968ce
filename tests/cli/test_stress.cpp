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
    EXPECT_GT(summary["largest_finite_value"].get<double>(), 65504.0) << "the cases should push past fp16";
}

TEST(Stress, SameSeedGivesTheSameSummary) {
    TempDir dir;
    const std::string command = std::string(DERMIS_BINARY) + " stress --cases 3 --seed 77 --quiet --out ";
    ASSERT_EQ(runProcess(command + dir.file("a.json")).exitCode, 0);
    ASSERT_EQ(runProcess(command + dir.file("b.json")).exitCode, 0);
    auto a = nlohmann::json::parse(dermis::test::readTextFile(dir.file("a.json")));
    auto b = nlohmann::json::parse(dermis::test::readTextFile(dir.file("b.json")));
    a.erase("seconds");
    b.erase("seconds");
    EXPECT_EQ(a, b);
}
