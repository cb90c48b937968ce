// Texture-space mode from the command line: `dermis render --mode`, what the
// timings JSON says runs for characters on and off screen, and `dermis compare`.
#include "TestSupport.h"
#include "stress/StressCases.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;


nlohmann::json renderTimings(const TempDir& dir, const std::string& scenePath, const std::string& extra) {
    const std::string timings = dir.file("t.json");
    const ProcessResult r = runProcess(kDermis + " render " + scenePath + " --size 160x90 --frames 1 --quiet --out " +
                                       dir.file("x.png") + " --timings " + timings + " " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(dermis::test::readTextFile(timings)) : nlohmann::json();
}

// Passes whose names start with prefix: how many ran, and how many there are.
std::pair<int, int> passes(const nlohmann::json& timings, const std::string& prefix) {
    int executed = 0;
    int declared = 0;
    for (const auto& pass : timings["passes"]) {
        if (pass["name"].get<std::string>().rfind(prefix, 0) != 0) continue;
        ++declared;
        executed += pass["executed"].get<bool>() ? 1 : 0;
    }
    return {executed, declared};
}

// The default head twice: "near" where the camera looks, "away" far behind the camera.
std::string writeTwoHeads(const TempDir& dir) {
    const std::string path = dir.file("two.json");
    dermis::test::writeTextFile(path, R"({
      "camera": {"position_m": [0.16, 0.03, 0.42], "target_m": [0, 0, 0], "vertical_fov_deg": 35},
      "lights": [{"type": "directional", "direction": [-0.6, -0.35, -0.72], "intensity": 1.3}],
      "characters": [
        {"name": "near", "mesh": {"procedural": "head"}, "material": {"procedural": true}},
        {"name": "away", "mesh": {"procedural": "head"}, "material": {"procedural": true},
         "transform": {"translation_m": [0.5, 0, 1.5]}}
      ],
      "settings": {"mode": "ts"}
    })");
    return path;
}

}  // namespace

TEST(TextureSpaceCli, ModeOptionSelectsTheChain) {
    TempDir dir;
    const nlohmann::json ts = renderTimings(dir, dermis::test::contentScene("default.json"), "--mode ts");
    EXPECT_GT(passes(ts, "ts head").first, 8);
    EXPECT_EQ(passes(ts, "sss ").first, 0);
    const nlohmann::json ss = renderTimings(dir, dermis::test::contentScene("default.json"), "--mode ss");
    EXPECT_EQ(passes(ss, "ts ").second, 0) << "screen-space mode declares no texture-space pass";
    const ProcessResult bad = runProcess(kDermis + " render " + dermis::test::contentScene("default.json") + " --mode tx --quiet --out " +
                                         dir.file("bad.png"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--mode tx: expected ss or ts"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

TEST(TextureSpaceCli, OffScreenCharacterRunsNoTextureSpacePass) {
    TempDir dir;
    const nlohmann::json timings = renderTimings(dir, writeTwoHeads(dir), "");
    const auto [awayRan, awayDeclared] = passes(timings, "ts away ");
    EXPECT_EQ(awayRan, 0);
    EXPECT_GT(awayDeclared, 10);
    for (const auto& pass : timings["passes"]) {
        if (pass["name"].get<std::string>().rfind("ts away ", 0) == 0) {
            EXPECT_EQ(pass["culled_because"], "predicate: character off screen") << pass["name"];
            EXPECT_EQ(pass["gpu_ms"], 0.0);
        }
    }
    EXPECT_GT(passes(timings, "ts near ").first, 8);
    EXPECT_EQ(passes(timings, "ts near gather").first, 1);
}

TEST(TextureSpaceCli, CompareWritesImagesHeatmapAndMetrics) {
    TempDir dir;
    const std::string out = dir.file("cmp");
    const ProcessResult r =
        runProcess(kDermis + " compare " + dermis::test::contentScene("default.json") + " --out " + out + " --size 160x90 --frames 2 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"ss.exr", "ts.exr", "ss.png", "ts.png", "difference.png", "metrics.json"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(out + "/" + name)) << name;
        EXPECT_GT(std::filesystem::file_size(out + "/" + name), 100u) << name;
    }
    const nlohmann::json m = nlohmann::json::parse(dermis::test::readTextFile(out + "/metrics.json"));
    EXPECT_GT(m["sss_pixels"].get<int>(), 1000);
    EXPECT_LT(m["sss_pixels"].get<int>(), 160 * 90);
    const double relativeRmse = m["relative_rmse"].get<double>();
    EXPECT_GT(relativeRmse, 0.0);
    EXPECT_LT(relativeRmse, 0.5);
    EXPECT_GT(m["psnr_db"].get<double>(), 20.0);
    EXPECT_GE(m["max_abs_difference"].get<double>(), m["difference_p99"].get<double>());
    for (const char* mode : {"ss", "ts"}) {
        const auto& timings = m["timings"][mode];
        EXPECT_EQ(timings["frames"], 2) << mode;
        EXPECT_GT(timings["passes"].size(), 5u) << mode;
        EXPECT_GT(timings["frame"]["gpu_ms"].get<double>(), 0.0) << mode;
    }
    EXPECT_GT(passes(m["timings"]["ts"], "ts head").first, 8);
    EXPECT_EQ(passes(m["timings"]["ss"], "ts ").second, 0);

    const ProcessResult missing = runProcess(kDermis + " compare " + dermis::test::contentScene("default.json") + " --quiet");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("--out DIR is required"), std::string::npos) << missing.err;
}

// plan/TsPlan.h: a character without TEXCOORD_0 falls back to screen space
// out loud: one warning naming the file, the character and the reason over
// all frames, and the timings JSON gives the reason for each skipped pass.
TEST(TextureSpaceCli, CharacterWithoutUvsFallsBackWithOneWarning) {
    TempDir dir;
    ASSERT_TRUE(dermis::stress::writeStressAssets(dir.path().string()).ok());
    const std::string scene = dir.file("bare.json");
    dermis::test::writeTextFile(scene, R"({
      "camera": {"position_m": [0, 0.25, 0.35], "target_m": [0, 0, 0], "vertical_fov_deg": 40},
      "lights": [{"type": "directional", "direction": [0, -0.6, -1], "intensity": 1}],
      "characters": [{"name": "bare", "mesh": {"gltf": "no_uvs.gltf"}, "material": {"profile": "skin"}}],
      "settings": {"mode": "ts"}
    })");
    const std::string timings = dir.file("t.json");
    const ProcessResult r = runProcess(kDermis + " render " + scene + " --size 160x90 --frames 3 --out " +
                                       dir.file("x.png") + " --timings " + timings);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string warning = "warning: " + scene +
                                ": character 'bare' falls back to screen-space SSS in texture-space mode: 100% of its "
                                "surface has no UV area (limit 1%; the mesh has no TEXCOORD_0, or all UVs equal)\n";
    const std::string output = r.out + r.err;
    const size_t first = output.find(warning);
    EXPECT_NE(first, std::string::npos) << output;
    EXPECT_EQ(output.find(warning, first + 1), std::string::npos) << "warned more than once:\n" << output;

    const nlohmann::json t = nlohmann::json::parse(dermis::test::readTextFile(timings));
    int skipped = 0;
    for (const auto& pass : t["passes"]) {
        if (pass["name"].get<std::string>().rfind("ts bare", 0) != 0) continue;
        ++skipped;
        EXPECT_FALSE(pass["executed"].get<bool>());
        EXPECT_NE(pass["culled_because"].get<std::string>().find("falls back to screen space"), std::string::npos);
    }
    EXPECT_GE(skipped, 4);
    EXPECT_GT(passes(t, "sss ").first, 0);
}
