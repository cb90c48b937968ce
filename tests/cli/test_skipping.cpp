// "Skip every pass a scene doesn't need", read from the timings JSON that
// `dermis render --timings` writes.
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using dermis::test::ProcessResult;
using dermis::test::runProcess;
using dermis::test::TempDir;

namespace {

const std::string kDermis = DERMIS_BINARY;

nlohmann::json renderTimings(const TempDir& dir, const std::string& scene, const std::string& extra = "") {
    const std::string timings = dir.file("t.json");
    const ProcessResult r = runProcess(kDermis + " render " + scene + " --size 160x90 --frames 1 --quiet --out " +
                                       dir.file("x.png") + " --timings " + timings + " " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(dermis::test::readTextFile(timings));
}

int executedWithPrefix(const nlohmann::json& timings, const std::string& prefix) {
    int n = 0;
    for (const auto& pass : timings["passes"]) {
        if (pass["name"].get<std::string>().rfind(prefix, 0) == 0 && pass["executed"].get<bool>()) ++n;
    }
    return n;
}

bool executed(const nlohmann::json& timings, const std::string& name) {
    for (const auto& pass : timings["passes"]) {
        if (pass["name"] == name) return pass["executed"].get<bool>();
    }
    ADD_FAILURE() << "no pass named " << name;
    return false;
}


}  // namespace

TEST(Skipping, NoSssSceneExecutesNoSssPass) {
    TempDir dir;
    const nlohmann::json timings = renderTimings(dir, dermis::test::contentScene("no_sss.json"));
    EXPECT_EQ(executedWithPrefix(timings, "sss"), 0);
    EXPECT_FALSE(executed(timings, "transmittance"));
    EXPECT_TRUE(executed(timings, "lighting"));
}

TEST(Skipping, FarHeadExecutesFewerBlurPassesThanNear) {
    TempDir dir;
    const int near = executedWithPrefix(renderTimings(dir, dermis::test::contentScene("default.json")), "sss skin");
    const int far =
        executedWithPrefix(renderTimings(dir, dermis::test::contentScene("default.json"), "--set camera.position_m=[1.6,0.3,4.2]"), "sss skin");
    std::printf("blur passes executed: near %d, far %d\n", near, far);
    EXPECT_GT(near, 0);
    EXPECT_LT(far, near);
}

TEST(Skipping, SceneWithoutBackLightExecutesNoTransmittancePass) {
    TempDir dir;
    EXPECT_TRUE(executed(renderTimings(dir, dermis::test::contentScene("default.json")), "transmittance"));
    // The default's second light is the back light; point it from the camera's side.
    const nlohmann::json timings = renderTimings(
        dir, dermis::test::contentScene("default.json"), "--set lights.1.position_m=[0.25,0.12,0.6] --set lights.1.direction=[-0.4,-0.2,-0.9]");
    EXPECT_FALSE(executed(timings, "transmittance"));
    EXPECT_GT(executedWithPrefix(timings, "sss skin"), 0);
}

TEST(Skipping, DisabledEffectsAreCulledWithTheirReason) {
    TempDir dir;
    const nlohmann::json timings =
        renderTimings(dir, dermis::test::contentScene("default.json"), "--set sss.enabled=false --set transmittance.enabled=false");
    EXPECT_EQ(executedWithPrefix(timings, "sss"), 0);
    for (const auto& pass : timings["passes"]) {
        if (pass["name"] == "sss init") EXPECT_EQ(pass["culled_because"], "predicate: SSS disabled");
        if (pass["name"] == "transmittance") EXPECT_EQ(pass["culled_because"], "predicate: transmittance disabled");
    }
}
