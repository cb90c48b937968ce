// The timings JSON that `dermis render --timings` writes: every declared pass
// with whether it ran and why it was culled. Which passes the real frame
// culls, and why, is tested without GL in tests/unit/test_frame_declaration.cpp;
// this is the smoke test of the same words reaching the file.
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

}  // namespace

TEST(Skipping, TimingsJsonListsEveryPassWithWhyItWasCulled) {
    TempDir dir;
    const std::string timingsPath = dir.file("t.json");
    const ProcessResult r = runProcess(kDermis + " render " + dermis::test::contentScene("default.json") +
                                       " --size 160x90 --frames 1 --quiet --out " + dir.file("x.png") + " --timings " +
                                       timingsPath + " --set ssao.enabled=false");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json timings = nlohmann::json::parse(dermis::test::readTextFile(timingsPath));
    ASSERT_TRUE(timings["passes"].is_array());
    std::map<std::string, nlohmann::json> passes;
    for (const auto& pass : timings["passes"]) {
        ASSERT_TRUE(pass["name"].is_string());
        ASSERT_TRUE(pass["executed"].is_boolean()) << pass["name"];
        ASSERT_TRUE(pass["culled_because"].is_string()) << pass["name"];
        EXPECT_EQ(pass["executed"].get<bool>(), pass["culled_because"].get<std::string>().empty()) << pass["name"];
        passes[pass["name"].get<std::string>()] = pass;
    }
    EXPECT_TRUE(passes.at("lighting")["executed"].get<bool>());
    EXPECT_TRUE(passes.at("tonemap")["executed"].get<bool>());
    EXPECT_EQ(passes.at("ssao")["culled_because"], "predicate: SSAO is disabled (settings.ssao.enabled = false)");
    EXPECT_EQ(passes.at("sss skin g0 v")["culled_because"], "input 'sss skin g0 h' not produced");
}
