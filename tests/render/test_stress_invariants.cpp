// The wrong-image detectors (tools/stress/InvariantFrame.h) on real frames:
// they hold on the default head in both SSS modes and on the smooth-lighting
// family, and each planted violation is caught.
#include "RenderFixture.h"

#include "stress/InvariantFrame.h"

#include <gtest/gtest.h>

using namespace dermis;
using namespace dermis::stress;

namespace {

class StressInvariantsRender : public test::RenderFixture {
protected:
    InvariantReport run(Plant plant) {
        auto report = checkFrameInvariants(*mRenderer, *mScene, 96, 54, plant);
        EXPECT_TRUE(report.ok()) << (report.ok() ? "" : report.error().message());
        return report.ok() ? *report : InvariantReport{};
    }
};

std::string describe(const InvariantReport& report) {
    std::string out;
    for (const auto& entry : kInvariants) {
        const InvariantTally& t = report[entry.value];
        out += std::string(entry.name) + ": " + std::to_string(t.checked) + " checked, " + std::to_string(t.violated) +
               " violated\n";
        for (const std::string& d : t.details) out += "  " + d + "\n";
    }
    return out;
}

void expectHolds(const InvariantReport& report) {
    EXPECT_FALSE(report.anyViolated()) << describe(report);
    // Each of invariants 1-3 checked something: the head is lit and on screen.
    EXPECT_GT(report[Invariant::Coverage].checked, 0u);
    EXPECT_GT(report[Invariant::Energy].checked, 0u);
    EXPECT_GT(report[Invariant::Black].checked, 0u);
}

}  // namespace

TEST_F(StressInvariantsRender, HoldOnTheDefaultHeadInScreenSpace) {
    load("default.json");
    expectHolds(run(Plant::None));
}

TEST_F(StressInvariantsRender, HoldOnTheDefaultHeadInTextureSpace) {
    // Without transmittance: in ts mode its TSM terms are added outside the
    // irradiance texture, and the energy check is skipped (InvariantFrame.cpp).
    load("default.json", {"mode=ts", "transmittance.enabled=false"});
    expectHolds(run(Plant::None));
}

TEST_F(StressInvariantsRender, EachPlantIsCaughtByItsInvariant) {
    load("default.json");
    const std::pair<Plant, Invariant> plants[] = {
        {Plant::Coverage, Invariant::Coverage}, {Plant::Energy, Invariant::Energy}, {Plant::Black, Invariant::Black}};
    for (const auto& [plant, invariant] : plants) {
        const InvariantReport report = run(plant);
        EXPECT_GT(report[invariant].violated, 0u) << kPlants.name(plant) << "\n" << describe(report);
    }
}

TEST_F(StressInvariantsRender, ScreenAndTextureSpaceAgreeOnSmoothLighting) {
    // Three seeds of the family (the stress run checks every tenth case's).
    for (uint64_t seed : {10u, 20u, 30u}) {
        float relative = -1.0f;
        auto tally = checkScreenVsTextureCase(seed, Plant::None, &relative);
        ASSERT_TRUE(tally.ok()) << tally.error().message();
        EXPECT_EQ(tally->checked, 1u);
        EXPECT_EQ(tally->violated, 0u) << "seed " << seed << ": " << (tally->details.empty() ? "" : tally->details[0]);
        std::printf("seed %llu: relative difference %.4f\n", static_cast<unsigned long long>(seed), relative);
        auto planted = checkScreenVsTextureCase(seed, Plant::SsTs);
        ASSERT_TRUE(planted.ok());
        EXPECT_EQ(planted->violated, 1u) << "seed " << seed;
    }
}

// Invariant 5 on the default head: each of addLight's four ways (seeds 0-3)
// darkens no pixel in either mode, and the planted 0.9 is caught.
TEST_F(StressInvariantsRender, MoreLightDarkensNoPixelInEitherMode) {
    for (const char* mode : {"ss", "ts"}) {
        load("default.json", {std::string("mode=") + mode});
        const std::vector<Light> lights = mScene->lights;
        for (uint64_t seed = 0; seed < 4; ++seed) {
            auto tally = checkMoreLight(*mRenderer, *mScene, seed, 96, 54);
            ASSERT_TRUE(tally.ok()) << tally.error().message();
            EXPECT_EQ(tally->checked, 1u);
            EXPECT_EQ(tally->violated, 0u) << mode << " seed " << seed << ": "
                                           << (tally->details.empty() ? "" : tally->details[0]);
            EXPECT_EQ(mScene->lights.size(), lights.size()) << "the scene is restored";
        }
        auto planted = checkMoreLight(*mRenderer, *mScene, 0, 96, 54, Plant::MoreLight);
        ASSERT_TRUE(planted.ok());
        EXPECT_EQ(planted->violated, 1u) << mode;
    }
}
