// A bench row through the shards' JSON (bench/BenchRowJson.h): every field
// back with the same bits, numbers that are not finite included, and a bad
// field named by its key.
#include "bench/BenchRowJson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace {

using dermis::bench::BenchRow;
using dermis::bench::ErrorCause;
using dermis::bench::ErrorRegion;

BenchRow sampleRow() {
    BenchRow row;
    row.id = 7;
    row.mode = "ss";
    row.technique = "disk";
    row.label = "disk_samples=16";
    row.isDefault = true;
    row.width = 64;
    row.height = 36;
    row.frames = 3;
    row.frameGpuMs = 1.0 / 3.0;  // no short decimal: the digits must survive
    row.sssGpuMs = 0.1 + 0.2;
    row.wallMs = std::numeric_limits<double>::infinity();
    row.relativeRmse = std::nextafter(0.05, 1.0);
    row.maxAbsDifference = 0.734;
    row.psnrDb = std::numeric_limits<double>::quiet_NaN();
    dermis::ImageDifference difference;
    difference.pixels = 612;
    difference.rmse = 0.0236;
    difference.relativeRmse = 1e-300;
    difference.maxAbsDifference = -std::numeric_limits<double>::infinity();
    difference.peak = 1.37;
    difference.psnrDb = 35.27;
    row.errors.table[size_t(ErrorCause::Scatter)][size_t(ErrorRegion::All)] = difference;
    row.overrides = {"mode=ss", "sss.technique=disk"};
    dermis::PassSummary pass;
    pass.name = "sss disk";
    pass.executed = true;
    pass.executedFrames = 3;
    pass.frames = 4;
    pass.culledBecause = "no SSS pixel";
    pass.gpuMs = 2.0 / 7.0;
    pass.cpuMs = 0.0;
    pass.gpuP5Ms = 0.25;
    pass.gpuP95Ms = 1.0 / 9.0;
    pass.cpuP5Ms = 1e-9;
    pass.cpuP95Ms = 5.5;
    pass.samples = 3;
    row.passes = {pass};
    return row;
}

// Same bits, or both NaN.
void expectSame(double expected, double actual, const char* what) {
    if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(actual)) << what;
    } else {
        EXPECT_EQ(std::memcmp(&expected, &actual, sizeof expected), 0) << what << ": " << expected << " became " << actual;
    }
}

}  // namespace

TEST(BenchRowJson, EveryFieldComesBackWithTheSameBits) {
    const BenchRow row = sampleRow();
    // Through the text, as a shard's note carries it.
    const nlohmann::json json = nlohmann::json::parse(dermis::bench::benchRowToJson(row).dump());
    auto back = dermis::bench::benchRowFromJson(json, "note.json: /rows/0");
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->id, 7);
    EXPECT_EQ(back->mode, "ss");
    EXPECT_EQ(back->technique, "disk");
    EXPECT_EQ(back->label, "disk_samples=16");
    EXPECT_TRUE(back->isDefault);
    EXPECT_EQ(back->width, 64);
    EXPECT_EQ(back->height, 36);
    EXPECT_EQ(back->frames, 3);
    expectSame(row.frameGpuMs, back->frameGpuMs, "frame_gpu_ms");
    expectSame(row.sssGpuMs, back->sssGpuMs, "sss_gpu_ms");
    expectSame(row.wallMs, back->wallMs, "wall_ms");
    expectSame(row.relativeRmse, back->relativeRmse, "relative_rmse");
    expectSame(row.maxAbsDifference, back->maxAbsDifference, "max_abs_difference");
    expectSame(row.psnrDb, back->psnrDb, "psnr_db");
    EXPECT_EQ(back->overrides, row.overrides);
    for (size_t cause = 0; cause < row.errors.table.size(); ++cause) {
        for (size_t region = 0; region < row.errors.table[cause].size(); ++region) {
            const auto& expected = row.errors.table[cause][region];
            const auto& actual = back->errors.table[cause][region];
            ASSERT_EQ(actual.has_value(), expected.has_value()) << cause << " " << region;
            if (!expected) continue;
            EXPECT_EQ(actual->pixels, expected->pixels);
            expectSame(expected->rmse, actual->rmse, "rmse");
            expectSame(expected->relativeRmse, actual->relativeRmse, "relative_rmse");
            expectSame(expected->maxAbsDifference, actual->maxAbsDifference, "max_abs_difference");
            expectSame(expected->peak, actual->peak, "peak");
            expectSame(expected->psnrDb, actual->psnrDb, "psnr_db");
        }
    }
    ASSERT_EQ(back->passes.size(), 1u);
    const dermis::PassSummary& pass = back->passes[0];
    EXPECT_EQ(pass.name, "sss disk");
    EXPECT_TRUE(pass.executed);
    EXPECT_EQ(pass.executedFrames, 3u);
    EXPECT_EQ(pass.frames, 4u);
    EXPECT_EQ(pass.culledBecause, "no SSS pixel");
    expectSame(row.passes[0].gpuMs, pass.gpuMs, "pass gpu_ms");
    expectSame(row.passes[0].cpuMs, pass.cpuMs, "pass cpu_ms");
    expectSame(row.passes[0].gpuP5Ms, pass.gpuP5Ms, "pass gpu_p5_ms");
    expectSame(row.passes[0].gpuP95Ms, pass.gpuP95Ms, "pass gpu_p95_ms");
    expectSame(row.passes[0].cpuP5Ms, pass.cpuP5Ms, "pass cpu_p5_ms");
    expectSame(row.passes[0].cpuP95Ms, pass.cpuP95Ms, "pass cpu_p95_ms");
    EXPECT_EQ(pass.samples, 3u);
}

TEST(BenchRowJson, ABadFieldIsNamedByItsKey) {
    struct Case {
        const char* pointer;
        nlohmann::json value;
        const char* message;
    };
    const Case cases[] = {
        {"/frame_gpu_ms", "fast", "note.json: /rows/0/frame_gpu_ms: expected a number, \"nan\", \"inf\" or \"-inf\""},
        {"/errors/scatter/all/pixels", -1.5, "note.json: /rows/0/errors/scatter/all/pixels: expected an integer"},
        {"/passes/0/executed", 1, "note.json: /rows/0/passes/0/executed: expected true or false"},
        {"/overrides/1", 3, "note.json: /rows/0/overrides/1: expected a string"},
    };
    for (const Case& c : cases) {
        nlohmann::json json = nlohmann::json::parse(dermis::bench::benchRowToJson(sampleRow()).dump());
        json[nlohmann::json::json_pointer(c.pointer)] = c.value;
        auto back = dermis::bench::benchRowFromJson(json, "note.json: /rows/0");
        ASSERT_FALSE(back.ok()) << c.pointer;
        EXPECT_EQ(back.error().message(), c.message);
    }
    nlohmann::json missing = nlohmann::json::parse(dermis::bench::benchRowToJson(sampleRow()).dump());
    missing.erase("label");
    auto back = dermis::bench::benchRowFromJson(missing, "note.json: /rows/0");
    ASSERT_FALSE(back.ok());
    EXPECT_EQ(back.error().message(), "note.json: /rows/0/label: missing");
}
