#include "reference/SampleMemo.h"

#include "core/Hash.h"

#include <algorithm>
#include <cstring>

namespace dermis::reference {
namespace {

constexpr size_t kFirstSlots = 1024;
// A table grows (doubling) or, at its largest, turns over when it is this full.
constexpr double kMaxLoad = 0.5;

uint32_t bitsOf(float f) {
    uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

}  // namespace

SampleMemo::SampleMemo(const SampleValues& inner, size_t capacity)
    : mInner(&inner), mShards(std::make_unique<std::array<Shard, kShards>>()) {
    const double perTable = double(std::max<size_t>(capacity, 2 * kShards)) / double(2 * kShards);
    mMaxSlots = kFirstSlots;
    while (double(mMaxSlots) * kMaxLoad < perTable) mMaxSlots *= 2;
}

SampleKey SampleMemo::keyOf(uint32_t triangle, const glm::vec2& b) { return SampleKey{triangle, bitsOf(b.x), bitsOf(b.y)}; }

uint64_t SampleMemo::hashOf(const SampleKey& key) {
    const uint32_t low = lowbias32(lowbias32(lowbias32(key.triangle) ^ key.b1Bits) ^ key.b2Bits);
    return (uint64_t(lowbias32(low ^ 0x5bd1e995u)) << 32) | low;
}

SampleMemo::Shard& SampleMemo::shardOf(uint64_t hash) const { return (*mShards)[(hash >> 40) % kShards]; }

const SampleEntry* SampleMemo::find(const Table& table, const SampleKey& key, uint64_t hash) {
    if (table.slots.empty()) return nullptr;
    const size_t mask = table.slots.size() - 1;
    for (size_t i = size_t(hash) & mask;; i = (i + 1) & mask) {
        const Slot& slot = table.slots[i];
        if (!slot.occupied) return nullptr;
        if (slot.key == key) return &slot.entry;
    }
}

void SampleMemo::store(Shard& shard, const SampleKey& key, uint64_t hash, const SampleEntry& entry) const {
    Table& table = shard.current;
    if (table.slots.empty()) table.slots.resize(kFirstSlots);
    if (double(table.count + 1) > kMaxLoad * double(table.slots.size())) {
        if (table.slots.size() < mMaxSlots) {
            Table grown;
            grown.slots.resize(table.slots.size() * 2);
            const size_t mask = grown.slots.size() - 1;
            for (const Slot& slot : table.slots) {
                if (!slot.occupied) continue;
                size_t i = size_t(hashOf(slot.key)) & mask;
                while (grown.slots[i].occupied) i = (i + 1) & mask;
                grown.slots[i] = slot;
            }
            grown.count = table.count;
            table = std::move(grown);
        } else {
            // The full table becomes the previous generation; the older one, emptied, the current.
            std::swap(shard.current, shard.previous);
            table.slots.assign(mMaxSlots, Slot{});
            table.count = 0;
        }
    }
    const size_t mask = table.slots.size() - 1;
    for (size_t i = size_t(hash) & mask;; i = (i + 1) & mask) {
        Slot& slot = table.slots[i];
        if (slot.occupied && !(slot.key == key)) continue;
        if (!slot.occupied) ++table.count;
        slot = Slot{key, 1, entry};
        return;
    }
}

glm::vec3 SampleMemo::valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const {
    const SampleKey key = keyOf(triangle, b);
    const uint64_t hash = hashOf(key);
    Shard& shard = shardOf(hash);
    ++mLookups;
    {
        const std::lock_guard<std::mutex> lock(shard.mutex);
        const SampleEntry* found = find(shard.current, key, hash);
        SampleEntry promoted;
        if (!found) {
            if (const SampleEntry* old = find(shard.previous, key, hash)) {
                promoted = *old;  // recently used: kept into the next generation
                store(shard, key, hash, promoted);
                found = &promoted;
            }
        }
        if (found) {
            ++mHits;
            if (visibility) *visibility = found->visibility;
            return found->value;
        }
    }
    // Computed outside the lock; two threads may compute one key at once, and get the same value.
    SampleEntry entry;
    entry.value = mInner->valueAt(triangle, b, &entry.visibility);
    if (visibility) *visibility = entry.visibility;
    const std::lock_guard<std::mutex> lock(shard.mutex);
    store(shard, key, hash, entry);
    return entry.value;
}

size_t SampleMemo::size() const {
    size_t count = 0;
    for (Shard& shard : *mShards) {
        const std::lock_guard<std::mutex> lock(shard.mutex);
        count += shard.current.count + shard.previous.count;
    }
    return count;
}

std::vector<std::pair<SampleKey, SampleEntry>> SampleMemo::entries() const {
    std::vector<std::pair<SampleKey, SampleEntry>> out;
    for (Shard& shard : *mShards) {
        const std::lock_guard<std::mutex> lock(shard.mutex);
        for (const Table* table : {&shard.previous, &shard.current}) {
            for (const Slot& slot : table->slots) {
                if (slot.occupied) out.emplace_back(slot.key, slot.entry);
            }
        }
    }
    return out;
}

void SampleMemo::insert(const std::vector<std::pair<SampleKey, SampleEntry>>& entries) {
    for (const auto& [key, entry] : entries) {
        const uint64_t hash = hashOf(key);
        Shard& shard = shardOf(hash);
        const std::lock_guard<std::mutex> lock(shard.mutex);
        store(shard, key, hash, entry);
    }
}

}  // namespace dermis::reference
