// `dermis bench`'s sweep specification, Pareto fronts and report files.
#include "bench/BenchReport.h"
#include "bench/ParetoFront.h"
#include "bench/SweepPlan.h"
#include "bench/SweepSpec.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace dermis::bench;

namespace {

std::vector<std::string> labels(const std::vector<SweepConfig>& configs) {
    std::vector<std::string> result;
    for (const SweepConfig& c : configs) result.push_back(c.mode + " " + c.label);
    return result;
}

}  // namespace

TEST(SweepSpec, ModePrefixedAxesExpandPerModeFirstAxisSlowest) {
    auto axes = parseSweepSpec("ss:sss.taps=5,9;ss:scale=0.5,1;ts:ts.taps=3,7");
    ASSERT_TRUE(axes) << axes.error().message();
    auto configs = expandSweep(*axes);
    ASSERT_TRUE(configs) << configs.error().message();
    EXPECT_EQ(labels(*configs), (std::vector<std::string>{"ss taps=5 scale=0.5", "ss taps=5 scale=1",
                                                          "ss taps=9 scale=0.5", "ss taps=9 scale=1", "ts taps=3",
                                                          "ts taps=7"}));
    EXPECT_EQ((*configs)[0].overrides, (std::vector<std::string>{"mode=ss", "sss.taps=5"}));
    EXPECT_DOUBLE_EQ((*configs)[0].scale, 0.5);
    EXPECT_DOUBLE_EQ((*configs)[1].scale, 1.0);
    EXPECT_EQ((*configs)[5].overrides, (std::vector<std::string>{"mode=ts", "ts.taps=7"}));
}

TEST(SweepSpec, UnprefixedAxesApplyToBothModesAndJoinedKeysTakeEachValue) {
    auto only = expandSweep(*parseSweepSpec("sss.gaussians=4,6"));
    ASSERT_TRUE(only);
    EXPECT_EQ(labels(*only), (std::vector<std::string>{"ss gaussians=4", "ss gaussians=6", "ts gaussians=4",
                                                       "ts gaussians=6"}));

    auto mixed = expandSweep(*parseSweepSpec(" sss.gaussians=4 ; ts:ts.min_size+ts.max_size=256,512 "));
    ASSERT_TRUE(mixed);
    // A prefix names the modes swept: only ts here, with the shared axis too.
    EXPECT_EQ(labels(*mixed), (std::vector<std::string>{"ts gaussians=4 min_size+max_size=256",
                                                        "ts gaussians=4 min_size+max_size=512"}));
    EXPECT_EQ((*mixed)[1].overrides,
              (std::vector<std::string>{"mode=ts", "sss.gaussians=4", "ts.min_size=512", "ts.max_size=512"}));
}

TEST(SweepSpec, TheDefaultSweepCoversTheIssuesKnobs) {
    auto axes = parseSweepSpec(kDefaultSweepSpec);
    ASSERT_TRUE(axes) << axes.error().message();
    auto configs = expandSweep(*axes);
    ASSERT_TRUE(configs);
    size_t ss = 0, ts = 0;
    for (const SweepConfig& c : *configs) (c.mode == "ss" ? ss : ts)++;
    EXPECT_EQ(ss, 3u * 3u * 2u * 2u * 2u);  // taps, Gaussians, bilateral or control, resolution, transmittance
    EXPECT_EQ(ts, 3u * 3u * 2u);            // irradiance resolution, taps, translucent shadow map
}

TEST(SweepSpec, BadSpecsAreErrorsNamingTheAxis) {
    struct Case {
        const char* spec;
        const char* where;
        const char* what;
    };
    const Case cases[] = {
        {"", "--sweep", "no axes"},
        {"sss.taps", "--sweep sss.taps", "expected"},
        {"xx:sss.taps=5", "--sweep xx:sss.taps=5", "ss: or ts:"},
        {"sss.taps=5,,9", "--sweep sss.taps=5,,9", "empty value"},
        {"mode=ss,ts", "--sweep mode=ss,ts", "prefix"},
        {"camera.near_m=0.1", "--sweep camera.near_m=0.1", "settings only"},
        // The environment's source changes the picture the one reference shows.
        {"environment.source=sky", "--sweep environment.source=sky", "settings only"},
        {"scale=0", "--sweep scale=0", "scale must be"},
        {"scale=fast", "--sweep scale=fast", "scale must be"},
        {"scale+sss.taps=1", "--sweep scale+sss.taps=1", "cannot be joined"},
        {"+sss.taps=1", "--sweep +sss.taps=1", "empty key"},
    };
    for (const Case& c : cases) {
        auto axes = parseSweepSpec(c.spec);
        ASSERT_FALSE(axes) << c.spec;
        EXPECT_EQ(axes.error().where, c.where) << c.spec;
        EXPECT_NE(axes.error().what.find(c.what), std::string::npos) << c.spec << ": " << axes.error().what;
    }
}

TEST(SweepSpec, EnvironmentQualityKeysAreSwept) {
    auto axes = parseSweepSpec("ss:environment.sh_bands=1,3;ss:environment.occlusion=none,transfer");
    ASSERT_TRUE(axes) << axes.error().message();
    auto configs = expandSweep(*axes);
    ASSERT_TRUE(configs) << configs.error().message();
    EXPECT_EQ(configs->size(), 4u);
}

TEST(SweepSpec, TooManyConfigurationsIsAnError) {
    std::string values = "1";
    for (int i = 2; i <= 30; ++i) values += "," + std::to_string(i);
    const std::string spec = "a.x=" + values + ";a.y=" + values + ";a.z=" + values;  // 27000 per mode
    auto configs = expandSweep(*parseSweepSpec(spec));
    ASSERT_FALSE(configs);
    EXPECT_NE(configs.error().what.find("more than"), std::string::npos);
}

TEST(ParetoFront, KeepsExactlyTheUndominatedPoints) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<CostError> points = {
        {10, 0.5},  // front: cheapest
        {20, 0.2},  // front
        {25, 0.3},  // dominated by {20, 0.2}
        {40, 0.1},  // front: most accurate
        {40, 0.1},  // a duplicate stays on the front
        {20, 0.4},  // dominated: as cheap as {20, 0.2}, worse
        {5, nan},   // never on the front, dominates nothing
        {50, 0.05 * nan},
    };
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{true, true, false, true, true, false, false, false}));
    EXPECT_TRUE(paretoFront({}).empty());
}

TEST(BenchReport, SummaryFindsTheDefaultTheBestAndTheCheapestUnderTheLimit) {
    std::vector<BenchRow> rows(5);
    auto set = [&](size_t i, const char* mode, const char* label, double ms, double error, bool isDefault) {
        rows[i].id = int(i);
        rows[i].mode = mode;
        rows[i].label = label;
        rows[i].frameGpuMs = ms;
        rows[i].relativeRmse = error;
        rows[i].isDefault = isDefault;
    };
    set(0, "ss", "default", 30, 0.015, true);
    set(1, "ss", "cheap", 10, 0.019, false);
    set(2, "ss", "cheaper but wrong", 5, 0.08, false);
    set(3, "ts", "default", 100, 0.05, true);
    set(4, "ts", "big", 400, 0.03, false);
    markParetoFronts(rows);
    EXPECT_TRUE(rows[0].onParetoFront && rows[1].onParetoFront && rows[2].onParetoFront);
    EXPECT_TRUE(rows[3].onParetoFront && rows[4].onParetoFront);

    const auto summary = benchSummary(rows, 0.02);
    EXPECT_EQ(summary["ss"]["default"]["label"], "default");
    EXPECT_EQ(summary["ss"]["most_accurate"]["label"], "default");
    EXPECT_EQ(summary["ss"]["cheapest_within_limit"]["label"], "cheap");
    EXPECT_EQ(summary["ss"]["cheapest_within_limit_of_most_accurate"]["label"], "cheap");
    EXPECT_TRUE(summary["ts"]["cheapest_within_limit"].is_null());  // none reaches 2%
    EXPECT_EQ(summary["ts"]["cheapest_within_limit_of_most_accurate"]["label"], "default");  // 0.05 <= 0.03 + 0.02
}

TEST(BenchReport, CsvQuotesFieldsWithCommasAndQuotes) {
    BenchRow row;
    row.mode = "ss";
    row.label = "pos=[0,1]";
    row.overrides = {"mode=ss", "name=\"x\""};
    row.relativeRmse = std::numeric_limits<double>::infinity();
    row.passes = {{"sss skin g1 h", true, 1, 1, "", 2.5, 0.1, 1}};
    const std::string csv = resultsCsv({row});
    EXPECT_NE(csv.find(",\"pos=[0,1]\","), std::string::npos) << csv;
    EXPECT_NE(csv.find(",\"mode=ss name=\"\"x\"\"\"\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",nan,"), std::string::npos) << csv;
    EXPECT_EQ(passesCsv({row}), "id,mode,pass,gpu_ms\n0,ss,sss skin g1 h,2.5\n");
    EXPECT_TRUE(isSssPass("sss skin g1 h") && isSssPass("ts head irradiance") && isSssPass("transmittance"));
    EXPECT_FALSE(isSssPass("gbuffer") || isSssPass("ssao blur") || isSssPass("shadow:light0(dir)") ||
                 isSssPass("lighting") || isSssPass("composite") || isSssPass("tonemap") || isSssPass("aov"));
    // A technique added later counts without being listed.
    EXPECT_TRUE(isSssPass("unblurred"));
}

// The technique x samples sweep of docs/bench.md: 3 x 2 x 2 = 12 configurations
// but 5 distinct renders (gaussians once, the shipped default; separable 7
// and 17; disk 16 and 64), counted by hand. Without the canonicalisation
// (broken on purpose) the plan had 13: every gaussians configuration apart.
TEST(BenchSweep, TechniqueSweepMeasuresEachDistinctRenderOnce) {
    auto axes = parseSweepSpec("ss:sss.technique=gaussians,separable,disk;ss:sss.separable_samples=7,17;"
                               "ss:sss.disk_samples=16,64");
    ASSERT_TRUE(axes.ok()) << axes.error().message();
    auto configs = expandSweep(*axes);
    ASSERT_TRUE(configs.ok());
    ASSERT_EQ(configs->size(), 12u);
    auto planned = planConfigs(dermis::test::contentScene("default.json"), {}, *configs);
    ASSERT_TRUE(planned.ok()) << planned.error().message();
    std::vector<std::string> found;
    for (const PlannedConfig& p : *planned) {
        const dermis::SssSettings& sss = p.scene.settings.sss;
        found.push_back(std::string(dermis::kSssTechniques.name(sss.technique)) + " " +
                        std::to_string(sss.separableSamples) + " " + std::to_string(sss.diskSamples) +
                        (p.isDefault ? " default" : ""));
    }
    EXPECT_EQ(found, (std::vector<std::string>{"gaussians 17 40 default", "separable 7 40", "separable 17 40",
                                               "disk 17 16", "disk 17 64"}));
    // Labels name only what the technique reads.
    std::vector<std::string> shown;
    for (const PlannedConfig& p : *planned) shown.push_back(p.sweep.label);
    EXPECT_EQ(shown, (std::vector<std::string>{"default", "technique=separable separable_samples=7",
                                               "technique=separable separable_samples=17",
                                               "technique=disk disk_samples=16", "technique=disk disk_samples=64"}));
}
