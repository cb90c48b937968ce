// SampleMemo returns exactly what the source it wraps computes, whether the
// value is new, in the current generation or moved up from the previous one,
// and however small its capacity; it counts what it reuses.
#include "reference/SampleMemo.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>

using namespace dermis::reference;

namespace {

// A source whose value and visibility are functions of the name, counting its calls.
class CountingValues final : public SampleValues {
public:
    glm::vec3 valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const override {
        ++calls;
        if (visibility) {
            visibility->tested = triangle;
            visibility->visible = uint64_t(b.x * 1000.0f);
            visibility->blocked = uint64_t(b.y * 1000.0f);
        }
        return glm::vec3(float(triangle), b.x, b.y);
    }
    mutable std::atomic<size_t> calls{0};
};

}  // namespace

TEST(SampleMemo, ReturnsTheSourcesValuesAndReusesThem) {
    CountingValues source;
    SampleMemo memo(source, 1'000'000);
    for (int round = 0; round < 3; ++round) {
        for (uint32_t t = 0; t < 500; ++t) {
            const glm::vec2 b(0.25f + 1e-4f * float(t % 7), 0.5f);
            LightVisibility visibility;
            EXPECT_EQ(memo.valueAt(t, b, &visibility), glm::vec3(float(t), b.x, b.y));
            EXPECT_EQ(visibility.tested, t);
            EXPECT_EQ(visibility.visible, uint64_t(b.x * 1000.0f));
        }
    }
    EXPECT_EQ(source.calls.load(), 500u);  // each name computed once
    EXPECT_EQ(memo.lookups(), 1500u);
    EXPECT_EQ(memo.hits(), 1000u);
    EXPECT_EQ(memo.size(), 500u);
    // Names differ by a bit of a weight: 0.5 and the next float are two samples.
    memo.valueAt(1, glm::vec2(0.5f, std::nextafter(0.5f, 1.0f)), nullptr);
    EXPECT_EQ(source.calls.load(), 501u);
}

TEST(SampleMemo, ASmallCapacityForgetsButNeverLies) {
    CountingValues source;
    SampleMemo memo(source, 1);  // the smallest tables: generations turn over often
    for (int round = 0; round < 2; ++round) {
        for (uint32_t t = 0; t < 2'000'000; t += 7) {
            const glm::vec2 b(0.1f, 0.2f + 1e-6f * float(t % 1000));
            ASSERT_EQ(memo.valueAt(t, b, nullptr), glm::vec3(float(t), b.x, b.y)) << t;
        }
    }
    EXPECT_LT(memo.size(), 2'000'000u / 7);          // some were dropped (a shard's table holds 512)
    EXPECT_GT(source.calls.load(), 2'000'000u / 7);  // and computed again
    // Put back from outside (the entries a cache kept), they are found without the source.
    SampleMemo copy(source, 1'000'000);
    copy.insert(memo.entries());
    const size_t before = source.calls.load();
    for (const auto& [key, entry] : memo.entries()) {
        glm::vec2 b;
        std::memcpy(&b.x, &key.b1Bits, 4);
        std::memcpy(&b.y, &key.b2Bits, 4);
        ASSERT_EQ(copy.valueAt(key.triangle, b, nullptr), entry.value);
    }
    EXPECT_EQ(source.calls.load(), before);
}
