// `dermis bench` and `dermis compare --reference`: run time against error
// against the CPU reference, from the command line.
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <sstream>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;
const std::string kScene = dermis::test::contentScene("default.json");
// Tiny on purpose: the references at density 1, the engine's irradiance for
// the matched reference at 512^2, and one frame per configuration.
const std::string kSmall = " --size 64x36 --frames 1 --density 1 --irradiance-size 512 --quiet";
const std::string kSweep = " --sweep 'ss:sss.taps=5,9;ts:ts.min_size+ts.max_size=256'";

bool matplotlibAvailable() { return std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0; }

std::vector<std::map<std::string, std::string>> readCsv(const std::string& path) {
    std::istringstream in(dermis::test::readTextFile(path));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::istringstream h(line); std::getline(h, line, ',');) header.push_back(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        // The test's labels and overrides hold no commas, so no field is quoted.
        std::map<std::string, std::string> row;
        std::istringstream fields(line);
        for (const std::string& name : header) std::getline(fields, row[name], ',');
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

// ctest: cost=95
TEST(BenchCli, SweepsBothModesAgainstTheReferenceAndPlots) {
    TempDir dir;
    const std::string out = dir.file("bench");
    const bool plots = matplotlibAvailable();
    if (!plots) std::fprintf(stderr, "python3-matplotlib is missing: the plots are not checked\n");
    const ProcessResult r = runProcess(kDermis + " bench " + kScene + " --out " + out + kSmall + kSweep +
                                       (plots ? "" : " --no-plots"));
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const auto rows = readCsv(out + "/results.csv");
    // ss: the default (9 taps, so the swept taps=9 is the same configuration) and
    // taps=5; ts: the default and 256^2.
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0].at("mode"), "ss");
    EXPECT_EQ(rows[0].at("label"), "default");
    EXPECT_EQ(rows[0].at("default"), "1");
    EXPECT_EQ(rows[1].at("label"), "taps=5");
    EXPECT_EQ(rows[2].at("mode"), "ts");
    EXPECT_EQ(rows[3].at("overrides"), "mode=ts ts.min_size=256 ts.max_size=256");
    int onFront[2] = {0, 0};
    for (const auto& row : rows) {
        const double error = std::stod(row.at("relative_rmse"));
        EXPECT_GT(error, 0.0) << row.at("label");
        EXPECT_LT(error, 0.5) << row.at("label");
        EXPECT_GT(std::stod(row.at("frame_gpu_ms")), 0.0);
        EXPECT_GT(std::stod(row.at("psnr_db")), 15.0);
        onFront[row.at("mode") == "ts"] += row.at("pareto") == "1";
        // Every cause is measured; the technique's own error is nonzero with SSS on.
        const double scatter = std::stod(row.at("scatter_rel_rmse"));
        EXPECT_GT(scatter, 0.0) << row.at("label");
        EXPECT_LT(scatter, 0.5) << row.at("label");
        EXPECT_GT(std::stod(row.at("irradiance_rel_rmse")), 0.0) << row.at("label");
        EXPECT_EQ(std::stod(row.at("total_rel_rmse")), error) << row.at("label");
        EXPECT_TRUE(row.count("scatter_rel_rmse_silhouette")) << "a column per cause and region";
    }
    EXPECT_GE(onFront[0], 1);
    EXPECT_GE(onFront[1], 1);
    // The texture-space rows run texture-space passes, the screen-space ones do not.
    const std::string passes = dermis::test::readTextFile(out + "/passes.csv");
    EXPECT_NE(passes.find("\n2,ts,ts head irradiance,"), std::string::npos);
    EXPECT_EQ(passes.find("\n0,ss,ts "), std::string::npos);

    const nlohmann::json summary = nlohmann::json::parse(dermis::test::readTextFile(out + "/summary.json"));
    EXPECT_GT(summary["sss_pixels"].get<int>(), 100);
    EXPECT_EQ(summary["modes"]["ss"]["default"]["id"], 0);
    EXPECT_EQ(summary["modes"]["ts"]["default"]["id"], 2);
    EXPECT_GT(summary["region_pixels"]["silhouette"].get<int>(), 0);
    EXPECT_EQ(summary["region_pixels"]["all"].get<int>(), summary["sss_pixels"].get<int>());
    EXPECT_FALSE(summary["modes"]["ss"]["default_errors"]["scatter"]["all"].is_null());
    for (const char* file : {"reference.exr", "reference_sss_off.exr", "thickness.exr", "error_ss.png", "error_ts.png"})
        EXPECT_TRUE(std::filesystem::is_regular_file(out + "/" + file)) << file;
    if (plots) {
        for (const char* png : {"pareto.png", "passes.png", "regions.png"}) EXPECT_GT(std::filesystem::file_size(out + "/" + png), 10000u) << png;
        // The plot script's Markdown table comes with the plots (bench --help lists it).
        EXPECT_TRUE(std::filesystem::is_regular_file(out + "/errors.md")) << "errors.md";
    }

    // The reference is reused, and the same frames give the same errors.
    const std::string again = dir.file("again");
    const ProcessResult reuse = runProcess(kDermis + " bench " + kScene + " --out " + again + kSmall +
                                           " --no-plots --sweep 'ss:sss.taps=5' --reference " + out + "/reference.exr");
    ASSERT_EQ(reuse.exitCode, 0) << reuse.err;
    const auto reused = readCsv(again + "/results.csv");
    ASSERT_EQ(reused.size(), 2u);
    EXPECT_NEAR(std::stod(reused[1].at("relative_rmse")), std::stod(rows[1].at("relative_rmse")), 1e-5);
    EXPECT_FALSE(std::filesystem::exists(again + "/reference.exr"));
    EXPECT_FALSE(std::filesystem::exists(again + "/pareto.png"));
    EXPECT_FALSE(std::filesystem::exists(again + "/errors.md"));

    // compare --reference: each mode's error against the same reference.
    const ProcessResult compared = runProcess(kDermis + " compare " + kScene + " --out " + dir.file("cmp") +
                                              " --size 64x36 --frames 1 --quiet --reference " + out + "/reference.exr" +
                                              " --set ssao.enabled=false");
    ASSERT_EQ(compared.exitCode, 0) << compared.err;
    const nlohmann::json metrics = nlohmann::json::parse(dermis::test::readTextFile(dir.file("cmp") + "/metrics.json"));
    for (const char* mode : {"ss", "ts"}) {
        const double error = metrics["against_reference"][mode]["relative_rmse"].get<double>();
        EXPECT_GT(error, 0.0) << mode;
        EXPECT_LT(error, 0.5) << mode;
    }
    EXPECT_NEAR(metrics["against_reference"]["ss"]["relative_rmse"].get<double>(),
                std::stod(rows[0].at("relative_rmse")), 1e-5);
}

// The matched reference's sanity check: with SSS off in the render and the
// references, the scatter error is exactly 0 (the change is 0 and the render
// with SSS off is the render), and the total error is the irradiance error.
// Then a second run into the same directory reuses the CPU images.
TEST(BenchCli, CompareErrorsWithSssOffHaveNoScatterError) {
    TempDir dir;
    const std::string out = dir.file("cmp");
    const std::string command = kDermis + " compare " + kScene + " --out " + out +
                                " --size 64x36 --frames 1 --density 1 --irradiance-size 256 --errors --set sss.enabled=false";
    const ProcessResult r = runProcess(command);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json metrics = nlohmann::json::parse(dermis::test::readTextFile(out + "/metrics.json"));
    for (const char* mode : {"ss", "ts"}) {
        const nlohmann::json& errors = metrics["errors"][mode];
        EXPECT_EQ(errors["scatter"]["all"]["relative_rmse"].get<double>(), 0.0) << mode;
        EXPECT_EQ(errors["scatter"]["all"]["max_abs_difference"].get<double>(), 0.0) << mode;
        EXPECT_GT(errors["total"]["all"]["relative_rmse"].get<double>(), 0.0) << mode;
        EXPECT_EQ(errors["total"]["all"]["relative_rmse"], errors["irradiance"]["all"]["relative_rmse"]) << mode;
        // Measured at pixel centres on both sides, the silhouette band is no worse than the face: 1.69%
        // against 1.61% over all pixels (shadow maps against shadow rays). With box-filtered references
        // (--spp 4, partly covered pixels left out) the band reads 6.9%, and with those pixels counted
        // far more: both fail this bound.
        EXPECT_LT(errors["irradiance"]["silhouette"]["relative_rmse"].get<double>(), 0.03) << mode;
    }
    // The engine and the reference's centre rays agree on which pixels show the head.
    EXPECT_EQ(metrics["uncovered_pixels"].get<int>(), 0);
    const ProcessResult again = runProcess(command);
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.err.find("reusing"), std::string::npos) << again.err;
    const nlohmann::json second = nlohmann::json::parse(dermis::test::readTextFile(out + "/metrics.json"));
    EXPECT_EQ(second["errors"], metrics["errors"]);
}

// A configuration that turns SSS off is scored against the scene's own
// scattering change, so leaving SSS out shows as scatter error; it used to read
// a perfect 0 (the change was computed with SSS off too) and sat on every
// scatter Pareto front. Both rows share one scattering change: the real-time
// SSS switches do not change the matched reference.
TEST(BenchCli, LeavingOutSssIsScatterError) {
    TempDir dir;
    const std::string out = dir.file("bench");
    // At 64x36 a pixel is wider than the profile and SSS changes almost nothing: 320x180.
    const ProcessResult r = runProcess(kDermis + " bench " + kScene + " --out " + out +
                                       " --size 320x180 --frames 1 --density 1 --irradiance-size 1024 --quiet"
                                       " --no-plots --sweep 'ss:sss.enabled=true,false'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readCsv(out + "/results.csv");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].at("label"), "sss.enabled=false");
    const double on = std::stod(rows[0].at("scatter_rel_rmse"));
    const double off = std::stod(rows[1].at("scatter_rel_rmse"));
    std::printf("scatter error: SSS on %.4f, off %.4f\n", on, off);
    EXPECT_GT(on, 0.0);
    // Measured 5.68% against 3.34%; a bound of 1.5x leaves room and still fails a 0.
    EXPECT_GT(off, 1.5 * on) << "leaving SSS out must cost more than the default technique's own error";
    int changes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        changes += name.rfind("scatter_change_", 0) == 0 && entry.path().extension() == ".exr";
    }
    EXPECT_EQ(changes, 1) << "the SSS switches and the technique recomputed the scattering change";
}

// The default head's scatter error, where the ear carries the back light
// through (include/Transmittance.glsl; docs/screen-space.md, "Transmittance
// against the reference"): `compare --errors` at 320x180 with cheap
// references (density 1, the irradiance at 1024^2; 27 s on 2 cores).
// Measured 1.57% (ss) and 1.76% (ts). The thickness along the ray at the
// pixel alone (Jimenez et al. 2010) read 3.33%, and the translucent shadow
// map in texture space 3.77%: 2.5% fails both.
// ctest: cost=35
TEST(BenchCli, TheEarsTransmittedLightFollowsTheReference) {
    TempDir dir;
    const std::string out = dir.file("cmp");
    const ProcessResult r = runProcess(kDermis + " compare " + kScene + " --out " + out +
                                       " --size 320x180 --frames 1 --density 1 --irradiance-size 1024 --errors --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json metrics = nlohmann::json::parse(dermis::test::readTextFile(out + "/metrics.json"));
    for (const char* mode : {"ss", "ts"}) {
        const nlohmann::json& scatter = metrics["errors"][mode]["scatter"];
        const double all = scatter["all"]["relative_rmse"].get<double>();
        std::printf("%s: scatter error %.2f%%, in parts under 4 mm thick %.2f%%\n", mode, 100.0 * all,
                    100.0 * scatter["thin_under_4mm"]["relative_rmse"].get<double>());
        EXPECT_GT(scatter["thin_under_4mm"]["pixels"].get<int>(), 100) << mode << ": the ear is not in view";
        EXPECT_LT(all, 0.025) << mode;
    }
}

TEST(BenchCli, BadInputFailsBeforeAnythingIsWritten) {
    TempDir dir;
    const std::string out = dir.file("bench");
    struct Case {
        std::string arguments;
        int exitCode;
        std::string message;
    };
    const Case cases[] = {
        {kScene + " --sweep 'ss:sss.taps=5,,9'", 2, "--sweep ss:sss.taps=5,,9: axis has an empty value"},
        {kScene + " --sweep 'camera.near_m=1'", 2, "settings only"},
        {kScene + " --sweep 'ss:sss.taps=4'", 2, "must be an odd number"},  // a value the command line gave
        {kScene + " --size 64x36 --reference " + dir.file("missing.exr"), 1, "missing.exr"},
        {dir.file("nope.json"), 1, "nope.json"},
        {kScene + " --frames 0", 2, "--frames"},
        // Refused before the full and SSS-off references are computed, not after.
        {kScene + " --change-spp 3", 2, "--change-spp: must be a perfect square from 1 to 256, got 3"},
        {kScene + " --spp 2", 2, "--spp: must be a perfect square"},
    };
    for (const Case& c : cases) {
        const ProcessResult r = runProcess(kDermis + " bench " + c.arguments + " --out " + out + " --quiet");
        EXPECT_EQ(r.exitCode, c.exitCode) << c.arguments << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(out + "/results.csv")) << c.arguments;
        EXPECT_FALSE(std::filesystem::exists(out + "/reference.exr")) << c.arguments;
    }
    const ProcessResult noOut = runProcess(kDermis + " bench " + kScene + " --quiet");
    EXPECT_EQ(noOut.exitCode, 2);
    EXPECT_NE(noOut.err.find("--out DIR is required"), std::string::npos);

    // A reference of another size is refused with the size it should have.
    const std::string small = dir.file("small.exr");
    ASSERT_EQ(runProcess(kDermis + " reference " + kScene + " --size 16x9 --density 1 --quiet --out " + small).exitCode, 0);
    const ProcessResult wrongSize =
        runProcess(kDermis + " bench " + kScene + " --size 64x36 --quiet --out " + out + " --reference " + small);
    EXPECT_EQ(wrongSize.exitCode, 1);
    EXPECT_NE(wrongSize.err.find("the reference is 16x9 but the frame is 64x36"), std::string::npos) << wrongSize.err;
}
