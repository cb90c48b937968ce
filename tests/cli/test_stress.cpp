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
    // Lights past fp16 must reach the sanitisers' clamp (the old "largest finite
    // value" was the shadow maps' 1e30 clear value, met by every case).
    EXPECT_GT(summary["counting"]["sanitised"]["overflow"].get<uint64_t>(), 0u) << "the cases should push past fp16";
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

// --plant-nan (docs/stress.md, "Counting and reading every target"): the run
// fails, and each failing case names the planted pass, not a later one. The
// tonemap runs in every case with the final output and sanitises every pixel,
// so each such case must fail; cases with an AOV do not run it.
TEST(Stress, PlantedNanFailsTheRunAndNamesThePass) {
    TempDir dir;
    const std::string summaryPath = dir.file("summary.json");
    const auto r = runProcess(std::string(DERMIS_BINARY) +
                              " stress --cases 3 --seed 1 --quiet --plant-nan tonemap --out " + summaryPath);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("'tonemap'"), std::string::npos) << r.out;
    const auto summary = nlohmann::json::parse(dermis::test::readTextFile(summaryPath));
    EXPECT_EQ(summary["plant_nan"], "tonemap");
    ASSERT_GE(summary["failed_cases"].get<int>(), 1);
    for (const auto& failure : summary["failures"]) {
        EXPECT_EQ(failure["pass"], "tonemap") << failure.dump(2);
        EXPECT_GT(failure["counts"]["sanitised"]["tonemap"]["nan"].get<uint64_t>(), 0u) << failure.dump(2);
    }
}

TEST(Stress, UnknownPlantPassIsAUsageErrorListingThePasses) {
    TempDir dir;
    const auto r = runProcess(std::string(DERMIS_BINARY) + " stress --cases 1 --seed 1 --quiet --plant-nan nosuchpass --out " +
                              dir.file("summary.json"));
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("nosuchpass"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("gbuffer"), std::string::npos) << "the error lists the frame's passes: " << r.err;
}
