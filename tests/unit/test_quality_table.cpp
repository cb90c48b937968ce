// Quality tables (scene/QualityTable.h, docs/quality.md): loading and its
// errors, the conservative choice by scale, and the SSS plan's per-character
// choices under an error budget. No GL.
#include "TestSupport.h"
#include "bench/QualityTune.h"
#include "render/FrameTimings.h"
#include "plan/SssPlan.h"
#include "scene/QualityTable.h"
#include "scene/SceneLoader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;
using dermis::test::TempDir;
using dermis::test::writeTextFile;

namespace {

// A table of `rows` rows at pixels per mm 1, 2, 4, ..., row i choosing the
// gaussians technique with 2 + (i % 5) Gaussians and 5 taps (distinct choices).
std::string tableText(double budget, size_t rows, const std::string& technique = "gaussians") {
    std::string text = "{\"budget\": " + std::to_string(budget) + ", \"tuned_on\": \"test\", \"size\": [64, 36], \"rows\": [";
    for (size_t i = 0; i < rows; ++i) {
        text += std::string(i ? ", " : "") + "{\"pixels_per_mm\": " + std::to_string(1 << i) +
                ", \"choice\": {\"technique\": \"" + technique + "\", \"taps\": 5, \"gaussians\": " +
                std::to_string(2 + int(i % 5)) + ", \"separable_samples\": 17, \"disk_samples\": 40}, " +
                "\"loss\": 0.005, \"sss_ms\": 1.0, \"finest_sss_ms\": 2.0}";
    }
    return text + "]}";
}

// The error's message must name the file and contain every fragment.
void expectError(const Result<QualityTable>& table, const std::string& file, std::initializer_list<const char*> parts) {
    ASSERT_FALSE(table.ok());
    const std::string message = table.error().message();
    EXPECT_NE(message.find(file), std::string::npos) << message;
    for (const char* part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}

QualityRow row(float pixelsPerMm, int gaussians) {
    QualityRow r;
    r.pixelsPerMm = pixelsPerMm;
    r.choice.gaussians = gaussians;
    r.choice.taps = 5;
    return r;
}

// Heads of half-depth 0.12 m at view depths (of their centres) `depths`, along the camera's axis.
Scene headsAt(const std::vector<float>& depthsM, const QualityTable& table) {
    Scene scene;
    for (size_t i = 0; i < depthsM.size(); ++i) {
        Character head;
        head.name = "head " + std::to_string(i);
        head.mesh.procedural = "head";
        head.material.profile = "skin";
        scene.characters.push_back(head);
    }
    scene.settings.quality.errorBudget = static_cast<float>(table.budget);
    scene.settings.quality.loaded = table;
    return scene;
}

constexpr float kFovDeg = 35.0f;
constexpr int kHeightPx = 360;

ViewParams frontView() {
    ViewParams view;
    view.viewFromWorld = glm::lookAt(glm::vec3(0, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    view.clipFromView = glm::perspective(glm::radians(kFovDeg), 640.0f / kHeightPx, 0.05f, 100.0f);
    view.nearM = 0.05f;
    view.widthPx = 640;
    view.heightPx = kHeightPx;
    return view;
}

// A head's bounds with its centre at view depth d on the axis.
Bounds headAtDepth(float depthM) {
    return Bounds{glm::vec3(-0.1f, -0.19f, -depthM - 0.12f), glm::vec3(0.1f, 0.13f, -depthM + 0.12f)};
}

// Pixels per mm at the head's nearest depth (d - 0.12 m), from the pinhole
// camera: heightPx / (2 tan(fov/2)) pixels per metre at 1 m.
float pixelsPerMmAt(float centreDepthM) {
    return kHeightPx / (2.0f * std::tan(glm::radians(kFovDeg) / 2.0f)) * 1e-3f / (centreDepthM - 0.12f);
}

}  // namespace

TEST(QualityTable, ReadsWhatTuneWritesAndKeepsEveryField) {
    auto table = parseQualityTable(tableText(0.01, 3), "t.json");
    ASSERT_TRUE(table.ok()) << table.error().message();
    ASSERT_EQ(table->rows.size(), 3u);
    EXPECT_FLOAT_EQ(table->rows[2].pixelsPerMm, 4.0f);
    EXPECT_EQ(table->rows[2].choice.gaussians, 4);
    EXPECT_EQ(table->width, 64);
    auto again = parseQualityTable(qualityTableJson(*table), "again.json");
    ASSERT_TRUE(again.ok()) << again.error().message();
    ASSERT_EQ(again->rows.size(), 3u);
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ(again->rows[i].choice, table->rows[i].choice);
    EXPECT_FLOAT_EQ(float(again->budget), 0.01f);
}

TEST(QualityTable, LoadErrorsNameTheFileTheKeyAndTheProblem) {
    TempDir dir;
    expectError(loadQualityTable(dir.file("missing.json")), "missing.json", {"no such file"});
    const std::string bad = dir.file("bad.json");
    writeTextFile(bad, "{\"budget\": 0.01, \"rows\": [");
    expectError(loadQualityTable(bad), "bad.json", {"line"});
    std::string text = tableText(0.01, 2);
    text.replace(text.find("\"loss\""), 6, "\"lost\"");
    expectError(parseQualityTable(text, "key.json"), "key.json", {"/rows/0", "lost"});
    expectError(parseQualityTable(tableText(0.01, 2, "blobs"), "technique.json"), "technique.json",
                {"/rows/0/choice/technique", "blobs", "gaussians, separable, disk or preintegrated"});
    text = tableText(0.01, 2);
    text.replace(text.find("\"pixels_per_mm\": 2"), 18, "\"pixels_per_mm\": 1");  // row 1 as row 0
    expectError(parseQualityTable(text, "order.json"), "order.json", {"/rows/1/pixels_per_mm", "strictly increasing"});
    text = tableText(0.01, 2);
    text.replace(text.find("\"taps\": 5"), 9, "\"taps\": 4");
    expectError(parseQualityTable(text, "taps.json"), "taps.json", {"/rows/0/choice/taps", "odd"});
    expectError(parseQualityTable(tableText(0.01, 0), "empty.json"), "empty.json", {"/rows", "at least one"});
    expectError(parseQualityTable(tableText(1.5, 1), "budget.json"), "budget.json", {"/budget"});
}

TEST(QualityTable, SceneLoadChecksTheTableAndItsBudget) {
    TempDir dir;
    writeTextFile(dir.file("table.json"), tableText(0.01, 2));
    const std::string scene = dir.file("scene.json");
    auto sceneWith = [&](const std::string& quality) {
        writeTextFile(scene, "{\"settings\": {\"quality\": " + quality + "}}");
        return loadScene(scene);
    };
    auto ok = sceneWith("{\"error_budget\": 0.01, \"table\": \"table.json\"}");
    ASSERT_TRUE(ok.ok()) << ok.error().message();
    EXPECT_EQ(ok->settings.quality.loaded.rows.size(), 2u);
    // Written back relative to the scene file, read back to the same table.
    writeTextFile(dir.file("again.json"), sceneToJson(*ok));
    auto again = loadScene(dir.file("again.json"));
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(again->settings.quality.table, ok->settings.quality.table);

    auto mismatch = sceneWith("{\"error_budget\": 0.02, \"table\": \"table.json\"}");
    ASSERT_FALSE(mismatch.ok());
    for (const char* part : {"scene.json", "/settings/quality/error_budget", "0.02", "table.json", "0.01"})
        EXPECT_NE(mismatch.error().message().find(part), std::string::npos) << mismatch.error().message();
    auto missing = sceneWith("{\"error_budget\": 0.01, \"table\": \"nothing.json\"}");
    ASSERT_FALSE(missing.ok());
    for (const char* part : {"scene.json", "/settings/quality/table", "nothing.json", "no such file"})
        EXPECT_NE(missing.error().message().find(part), std::string::npos) << missing.error().message();
    auto noTable = sceneWith("{\"error_budget\": 0.01}");
    ASSERT_FALSE(noTable.ok());
    EXPECT_NE(noTable.error().message().find("/settings/quality/table: is required"), std::string::npos)
        << noTable.error().message();
    auto off = sceneWith("{\"error_budget\": 0, \"table\": \"nothing.json\"}");  // no budget: the table is not read
    EXPECT_TRUE(off.ok()) << off.error().message();
}

// The rule (QualityTable.h): the row tuned at the smallest scale >= s; the
// finest above the largest. Written out by hand for rows at 1, 4 and 16 px/mm.
// Broken on purpose to "the largest scale <= s" (the coarser row between
// two scales), 2 and 10 px/mm got rows 0 and 1 and this test failed.
TEST(QualityTable, ChoosesTheRowOfTheLargerTunedScale) {
    QualityTable table;
    table.budget = 0.01;
    table.rows = {row(1.0f, 2), row(4.0f, 3), row(16.0f, 4)};
    const std::vector<std::pair<float, size_t>> expected = {{0.2f, 0}, {1.0f, 0}, {1.01f, 1}, {2.0f, 1}, {4.0f, 1},
                                                            {10.0f, 2}, {16.0f, 2}, {16.5f, 3}, {1000.0f, 3}};
    for (const auto& [scale, index] : expected) EXPECT_EQ(table.rowFor(scale), index) << scale;
    EXPECT_EQ(table.choiceAt(3), SssChoice::finest());
    EXPECT_EQ(SssChoice::finest().technique, SssTechnique::Gaussians);
    EXPECT_EQ(SssChoice::finest().taps, kMaxBlurTaps);
    EXPECT_EQ(SssChoice::finest().gaussians, kMaxProfileGaussians);
}

TEST(QualityTable, TwoCharactersAtDifferentScalesGetTheirRowsInTheirOwnSlots) {
    QualityTable table;
    table.budget = 0.01;
    // Scales of heads at 0.5 m and 2 m: 1.50 and 0.30 px/mm (pixelsPerMmAt: 360 / (2 tan 17.5°) / 1000 / (d - 0.12)).
    table.rows = {row(0.5f, 2), row(1.0f, 3), row(2.0f, 4)};
    const float nearScale = pixelsPerMmAt(0.5f);
    const float farScale = pixelsPerMmAt(2.0f);
    ASSERT_GT(nearScale, 1.0f);
    ASSERT_LT(nearScale, 2.0f);
    ASSERT_LT(farScale, 0.5f);
    const Scene scene = headsAt({0.5f, 2.0f}, table);
    auto plan = planSss(scene, {headAtDepth(0.5f), headAtDepth(2.0f)}, frontView());
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    ASSERT_EQ(plan->slots.size(), 2u);
    EXPECT_NE(plan->slotOf(0, 0), plan->slotOf(1, 0));
    const SssSlotPlan& nearSlot = plan->slots[size_t(plan->slotOf(0, 0) - 1)];
    const SssSlotPlan& farSlot = plan->slots[size_t(plan->slotOf(1, 0) - 1)];
    EXPECT_EQ(nearSlot.choice.gaussians, 4);  // 1 < 1.50 <= 2: the row tuned at 2 px/mm
    EXPECT_EQ(farSlot.choice.gaussians, 2);   // 0.25 <= 0.5: the first row
    EXPECT_EQ(nearSlot.choice.taps, 5);
    EXPECT_EQ(int(nearSlot.steps.size()), 4);  // the chain runs the choice's Gaussians
    EXPECT_NEAR(plan->characterChoices[0].pixelsPerMm, nearScale, 1e-3f * nearScale);
    EXPECT_EQ(plan->characterChoices[0].source, "table");
    EXPECT_EQ(plan->characterChoices[1].choice, farSlot.choice);
    // What the viewer and the render command print for the near head.
    CharacterReport report;
    report.name = "near";
    report.hasSss = plan->characterChoices[0].hasSss;
    report.sssChoice = plan->characterChoices[0].choice;
    report.pixelsPerMm = plan->characterChoices[0].pixelsPerMm;
    report.sssChoiceSource = plan->characterChoices[0].source;
    EXPECT_EQ(describeCharacterSss(report), "near: gaussians taps=5 gaussians=4, 1.50 px/mm (table)");
    report.hasSss = false;
    EXPECT_EQ(describeCharacterSss(report), "");

    // Without a budget both use settings.sss, each in a slot of its own
    // scale (SssSlotPlan::narrowGaussians), so that the far head skips the
    // Gaussians narrower than min_width_px at its own scale, not the near one's.
    Scene off = scene;
    off.settings.quality.errorBudget = 0.0f;
    auto plain = planSss(off, {headAtDepth(0.5f), headAtDepth(2.0f)}, frontView());
    ASSERT_TRUE(plain.ok());
    ASSERT_EQ(plain->slots.size(), 2u);
    // The skin profile's standard deviations, the square roots of d'Eon &
    // Luebke 2007's variances (0.0064 ... 7.41 mm^2).
    const float sigmasMm[] = {0.08f, 0.22f, 0.4324f, 0.753f, 1.4107f, 2.7221f};
    for (size_t head = 0; head < 2; ++head) {
        const SssSlotPlan& slot = plain->slots[size_t(plain->slotOf(head, 0) - 1)];
        EXPECT_EQ(slot.choice, SssChoice::fromSettings(off.settings.sss));
        const float scale = head == 0 ? nearScale : farScale;
        int narrow = 0;
        for (float sigma : sigmasMm) narrow += sigma * scale < off.settings.sss.minWidthPx ? 1 : 0;
        int skipped = 0;
        for (const SssGaussianStep& step : slot.steps) skipped += step.skipped ? 1 : 0;
        EXPECT_EQ(skipped, narrow) << "head " << head << " at " << scale << " px/mm";
    }
}

// Heads of two profiles at more scales than there are slots: the plan still
// fits, every head is in a slot of its own profile, and no slot skips a
// Gaussian that one of its heads needs (a slot skips by its nearest head).
TEST(QualityTable, HeadsAtMoreScalesThanSlotsShareSlotsThatSkipNoMoreThanTheNearestNeeds) {
    Scene scene;
    std::vector<Bounds> bounds;
    for (int i = 0; i < 16; ++i) {
        Character head;
        head.name = "head " + std::to_string(i);
        head.mesh.procedural = "head";
        head.material.profile = i % 2 == 0 ? "skin" : "marble";
        scene.characters.push_back(head);
        bounds.push_back(headAtDepth(0.3f + 0.45f * float(i / 2)));
    }
    auto plan = planSss(scene, bounds, frontView());
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    EXPECT_LE(plan->slots.size(), size_t(DERMIS_MAX_PROFILES));
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const SssSlotPlan& slot = plan->slots[size_t(plan->slotOf(c, 0) - 1)];
        EXPECT_EQ(slot.profile->name(), scene.characters[c].material.profile);
        const float scale = plan->characterChoices[c].pixelsPerMm;
        for (const SssGaussianStep& step : slot.steps) {
            const float widthPx = std::sqrt(slot.profile->gaussians()[size_t(step.gaussian)].varianceMm2) * scale;
            if (widthPx >= scene.settings.sss.minWidthPx) {
                EXPECT_FALSE(step.skipped) << "head " << c << ", Gaussian " << step.gaussian;
            }
        }
    }
}

// More distinct choices than slots: nobody gets a coarser choice than its
// row, the plan still fits. Broken on purpose (join the nearest COARSER slot),
// the heads nearer than their slot's row failed the rank check.
TEST(QualityTable, TooManyChoicesMergeIntoFinerSlots) {
    QualityTable table;
    table.budget = 0.01;
    const int rows = DERMIS_MAX_PROFILES + 4;
    std::vector<float> depths;
    for (int i = 0; i < rows; ++i) {
        // Row i is tuned at the scale of a head at depth 0.4 + 0.3 (rows - 1 - i): one head per row.
        const float depth = 0.4f + 0.3f * float(rows - 1 - i);
        QualityRow r = row(pixelsPerMmAt(depth) * 1.001f, 1 + i % kMaxProfileGaussians);
        r.choice.taps = 3 + 2 * (i / kMaxProfileGaussians);  // distinct choices
        table.rows.insert(table.rows.begin() + 0, r);
        depths.push_back(depth);
    }
    std::sort(table.rows.begin(), table.rows.end(),
              [](const QualityRow& a, const QualityRow& b) { return a.pixelsPerMm < b.pixelsPerMm; });
    std::vector<Bounds> bounds;
    for (float d : depths) bounds.push_back(headAtDepth(d));
    auto plan = planSss(headsAt(depths, table), bounds, frontView());
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    EXPECT_EQ(plan->slots.size(), size_t(DERMIS_MAX_PROFILES));
    size_t merged = 0;
    for (size_t c = 0; c < depths.size(); ++c) {
        const size_t own = table.rowFor(pixelsPerMmAt(depths[c]));
        ASSERT_LT(own, table.rows.size());
        const SssChoice& used = plan->slots[size_t(plan->slotOf(c, 0) - 1)].choice;
        size_t usedRow = table.rows.size();
        for (size_t r = 0; r < table.rows.size(); ++r) usedRow = table.rows[r].choice == used ? r : usedRow;
        EXPECT_GE(usedRow, own) << "character " << c;
        merged += plan->characterChoices[c].source == "merged" ? 1 : 0;
    }
    EXPECT_GE(merged, 4u);
}

TEST(QualityTune, CheapestWithinTheBudgetElseTheFinest) {
    SssChoice cheap;
    cheap.gaussians = 2;
    SssChoice middle;
    middle.gaussians = 4;
    const std::vector<bench::TuneMeasurement> measured = {{cheap, 0.03, 1.0, 5.0}, {middle, 0.008, 2.0, 6.0}};
    const QualityRow within = bench::cheapestWithin(3.0f, measured, 0.01, 4.0);
    EXPECT_EQ(within.choice, middle);
    EXPECT_DOUBLE_EQ(within.loss, 0.008);
    const QualityRow none = bench::cheapestWithin(3.0f, measured, 0.001, 4.0);
    EXPECT_EQ(none.choice, SssChoice::finest());
    EXPECT_DOUBLE_EQ(none.loss, 0.0);
    EXPECT_DOUBLE_EQ(none.sssMs, 4.0);
    // Within kTuneTimingTie (15%) of the cheapest the lower loss wins; past it, the cheaper.
    SssChoice close;
    close.gaussians = 5;
    const std::vector<bench::TuneMeasurement> tied = {{middle, 0.008, 2.0, 6.0}, {close, 0.004, 2.2, 6.0}};
    EXPECT_EQ(bench::cheapestWithin(3.0f, tied, 0.01, 4.0).choice, close);    // 2.2 <= 1.15 x 2.0
    const std::vector<bench::TuneMeasurement> apart = {{middle, 0.008, 2.0, 6.0}, {close, 0.004, 2.4, 6.0}};
    EXPECT_EQ(bench::cheapestWithin(3.0f, apart, 0.01, 4.0).choice, middle);  // 2.4 > 2.3
    // Equal losses (the same image under two names): the first candidate, whatever
    // their timings, so that a rerun or a shard picks the same name.
    // The first is taken even when its own time is outside the tie (2.6 > 1.15 x 2.0):
    // its image was measured at 2.0.
    const std::vector<bench::TuneMeasurement> same = {{middle, 0.004, 2.6, 6.0}, {close, 0.004, 2.0, 6.0}};
    EXPECT_EQ(bench::cheapestWithin(3.0f, same, 0.01, 4.0).choice, middle);
    // The finest (loss 0) within the tie of the cheapest candidate: the finest.
    EXPECT_EQ(bench::cheapestWithin(3.0f, tied, 0.01, 2.25).choice, SssChoice::finest());
    // 5 x 3 Gaussian chains, 4 separable and 4 disk sample counts, the pre-integrated table.
    EXPECT_EQ(bench::tuneCandidates().size(), 15u + 4u + 4u + 1u);
    auto percent = bench::parseBudget("1%");
    ASSERT_TRUE(percent.ok());
    EXPECT_DOUBLE_EQ(*percent, 0.01);
    auto fraction = bench::parseBudget("0.01");
    ASSERT_TRUE(fraction.ok());
    EXPECT_DOUBLE_EQ(*fraction, 0.01);
    for (const char* bad : {"0", "100%", "-1%", "x", "1%%", ""}) EXPECT_FALSE(bench::parseBudget(bad).ok()) << bad;
}
