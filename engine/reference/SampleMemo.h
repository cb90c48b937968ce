#pragma once
// Each sample point of the subsurface integral shaded once, whichever x_o
// gathers from it. The integrator splits cells per x_o, but deterministically
// (SurfaceCells.h: a cell's corners are the same bits whichever x_o asked for
// it), so a sample is named exactly by its triangle and the bits of its
// barycentric weights, and its value is a function of that name alone
// (ReferenceLighting seeds its environment rays by the point's position). A
// memo from name to value therefore changes no result, only the time: the
// image stays bit-identical for any thread count and any memo size.
//
// The memo is bounded: per shard it keeps two open-addressing tables (linear
// probing), a current and a previous generation; when the current one is as
// full as it may grow, it becomes the previous and the older is dropped (the
// pixels are taken row by row, so the samples a row shares with the next are
// recent). A value found in the previous generation moves to the current.
// Entries can be read out and put back (as if computed).

#include "reference/SampleValues.h"

#include <glm/glm.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace dermis::reference {

struct SampleKey {
    uint32_t triangle = 0;
    uint32_t b1Bits = 0;  // the float bits of the barycentric weights
    uint32_t b2Bits = 0;
    bool operator==(const SampleKey& other) const {
        return triangle == other.triangle && b1Bits == other.b1Bits && b2Bits == other.b2Bits;
    }
};

struct SampleEntry {
    glm::vec3 value{0.0f};
    LightVisibility visibility;
};

// Entries kept at most (both generations of every shard), 56 bytes each in tables
// at most half full (short probe sequences): about 1 GB.
constexpr size_t kDefaultSampleMemoCapacity = 8'000'000;

class SampleMemo final : public SampleValues {
public:
    // `inner` must outlive the memo. `capacity`: entries kept at most (both generations).
    explicit SampleMemo(const SampleValues& inner, size_t capacity = kDefaultSampleMemoCapacity);

    glm::vec3 valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const override;

    // Values asked for, and those of them already known.
    size_t lookups() const { return mLookups.load(); }
    size_t hits() const { return mHits.load(); }
    size_t size() const;
    // Every entry held, in no particular order; and entries put in (as if computed).
    std::vector<std::pair<SampleKey, SampleEntry>> entries() const;
    void insert(const std::vector<std::pair<SampleKey, SampleEntry>>& entries);

    static SampleKey keyOf(uint32_t triangle, const glm::vec2& b);

private:
    struct Slot {
        SampleKey key;
        uint32_t occupied = 0;
        SampleEntry entry;
    };
    struct Table {
        std::vector<Slot> slots;  // a power of two, or empty
        size_t count = 0;
    };
    struct Shard {
        std::mutex mutex;
        Table current;
        Table previous;
    };
    static constexpr size_t kShards = 64;

    static uint64_t hashOf(const SampleKey& key);
    Shard& shardOf(uint64_t hash) const;
    static const SampleEntry* find(const Table& table, const SampleKey& key, uint64_t hash);
    void store(Shard& shard, const SampleKey& key, uint64_t hash, const SampleEntry& entry) const;

    const SampleValues* mInner;
    size_t mMaxSlots;  // per table: a power of two
    std::unique_ptr<std::array<Shard, kShards>> mShards;
    mutable std::atomic<size_t> mLookups{0};
    mutable std::atomic<size_t> mHits{0};
};

}  // namespace dermis::reference
