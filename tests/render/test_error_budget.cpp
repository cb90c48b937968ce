// THE BUDGET CHECK (docs/quality.md): on a scene the shipped table was NOT
// tuned on (content/scenes/crowd8_mixed.json: eight heads from 0.5 m to
// 5.5 m; the table was tuned on default.json at 640x360), rendering with the
// 1% budget stays within 1% relative RMSE of the diffuse AOV over SSS pixels
// of the finest choice, each head with its table row for its own scale, and
// the timings JSON says which.
#include "RenderFixture.h"

#include "core/ImageMetrics.h"
#include "bench/QualityTune.h"
#include "scene/QualityTable.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace dermis;
using dermis::test::RenderFixture;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
constexpr long kMinHeadPixels = 50;
using ErrorBudget = RenderFixture;

double relativeRmse(const Image& finest, const Image& image, const std::vector<uint8_t>& mask) {
    auto difference = compareImages(finest, image, mask);
    EXPECT_TRUE(difference.ok());
    return difference.ok() ? difference->relativeRmse : NAN;
}

}  // namespace

// Measured with the shipped table (tuned on llvmpipe with the separable and
// disk techniques, margin 0.8): loss 0.92% with the table. Broken on purpose (every head
// given the cheapest candidate, 2 Gaussians and 5 taps, regardless of the
// budget) the loss was 1.70% and the bound failed; that break is kept below as
// a check that the bound can fail.
// Each head is bound too (2026-12-07, the twelve-row table with no-blur rows
// for the smallest heads): loss 0.27%, near 0.26%, far 1 0.10%, far 2 0.64%,
// far 4 0.11% (55 pixels), far 5 0.11%; the break puts the near head at 1.26%
// and the whole at 1.18%.
TEST_F(ErrorBudget, CrowdNotUsedForTuningStaysWithinTheBudgetOfTheFinest) {
    load("crowd8_mixed.json");  // as shipped: 1% budget, content/quality/default_1pct.json
    const QualityTable table = mScene->settings.quality.loaded;
    ASSERT_FALSE(table.empty());
    const double budget = mScene->settings.quality.errorBudget;
    EXPECT_FLOAT_EQ(float(budget), 0.01f);
    const Image budgeted = render(Aov::Diffuse, kWidth, kHeight);
    const std::vector<CharacterReport> reports = mRenderer->characterReports();

    // The finest at the same view: the renderer reads the scene every frame.
    const RenderSettings shipped = mScene->settings;
    mScene->settings.quality.errorBudget = 0.0f;
    SssChoice::finest().applyTo(mScene->settings.sss);
    mScene->settings.sss.minWidthPx = 0.0f;
    const Image ids = render(Aov::Object, kWidth, kHeight);
    std::vector<uint8_t> mask(ids.texels.size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = std::lround(ids.texels[i].r) >= 1 ? 1 : 0;  // all skin
    ASSERT_GT(std::count(mask.begin(), mask.end(), uint8_t{1}), 1000);
    const Image finest = render(Aov::Diffuse, kWidth, kHeight);
    const double loss = relativeRmse(finest, budgeted, mask);
    EXPECT_LE(loss, budget);
    std::printf("crowd8_mixed at %dx%d, 1%% budget: loss %.4f%%\n", kWidth, kHeight, 100.0 * loss);
    // Each head over its own pixels (the goal of the budget is per head). A
    // head of fewer than kMinHeadPixels is counted and printed, not bound: over
    // a few pixels, all on its outline, the loss is one pixel's (docs/results/quality.md, far 7).
    const auto worstHeadLoss = [&](const Image& image) {
        double worst = 0.0;
        int small = 0;
        for (size_t head = 0; head < mScene->characters.size(); ++head) {
            const std::vector<uint8_t> own = objectMask(ids, long(head) + 1);
            const auto pixels = std::count(own.begin(), own.end(), uint8_t{1});
            if (pixels == 0) continue;
            const double headLoss = relativeRmse(finest, image, own);
            std::printf("  %s: %ld pixels, loss %.4f%%\n", mScene->characters[head].name.c_str(), long(pixels), 100.0 * headLoss);
            if (pixels < kMinHeadPixels) {
                ++small;
            } else if (!(headLoss <= worst)) {
                worst = headLoss;
            }
        }
        std::printf("  %d head(s) under %ld pixels not bound\n", small, kMinHeadPixels);
        return worst;
    };
    EXPECT_LE(worstHeadLoss(budgeted), budget);

    // Each head rendered its own row's choice by the rule; the near and the far ones differ.
    std::set<size_t> rows;
    ASSERT_EQ(reports.size(), 8u);
    for (const CharacterReport& report : reports) {
        ASSERT_TRUE(report.hasSss) << report.name;
        ASSERT_GT(report.pixelsPerMm, 0.0f) << report.name;
        const size_t row = table.rowFor(report.pixelsPerMm);
        EXPECT_EQ(report.sssChoice, table.choiceAt(row)) << report.name;
        EXPECT_EQ(report.sssChoiceSource, row < table.rows.size() ? "table" : "finest") << report.name;
        rows.insert(row);
    }
    EXPECT_GE(rows.size(), 2u);
    // The near head (character 0) is the largest on screen.
    for (const CharacterReport& report : reports) EXPECT_LE(report.pixelsPerMm, reports[0].pixelsPerMm);
    RunInfo info;
    info.characters = reports;
    const auto json = nlohmann::json::parse(mRenderer->timings().toJson(info));
    const auto& near = json["characters"][0]["sss"];
    EXPECT_EQ(near["technique"], std::string(kSssTechniques.name(reports[0].sssChoice.technique)));
    EXPECT_EQ(near["taps"], reports[0].sssChoice.taps);
    EXPECT_EQ(near["gaussians"], reports[0].sssChoice.gaussians);
    EXPECT_EQ(near["source"], reports[0].sssChoiceSource);
    EXPECT_NEAR(near["pixels_per_mm"].get<double>(), reports[0].pixelsPerMm, 1e-4);
    // The render command's table and the viewer's panel print describeCharacterSss: a line per head with its row's choice.
    const std::string text = mRenderer->timings().toTable(info);
    for (const CharacterReport& report : reports) {
        const std::string line = "  " + report.name + ": " + describeSssChoice(table.choiceAt(table.rowFor(report.pixelsPerMm)));
        EXPECT_NE(text.find(line), std::string::npos) << line << " not in\n" << text;
    }

    // The break: the cheapest candidate for every head, whatever the budget.
    mScene->settings = shipped;
    for (QualityRow& row : mScene->settings.quality.loaded.rows) row.choice = bench::tuneCandidates().front();
    const Image broken = render(Aov::Diffuse, kWidth, kHeight);
    const double brokenLoss = relativeRmse(finest, broken, mask);
    std::printf("the cheapest candidate for every head: loss %.4f%%\n", 100.0 * brokenLoss);
    EXPECT_GT(brokenLoss, budget);
    EXPECT_GT(worstHeadLoss(broken), budget);
}
