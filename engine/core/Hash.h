#pragma once
// A 32-bit integer mixing hash: the lowbias32 finaliser (Wellons), xor-shift-
// multiply rounds with good avalanche (any change of the input changes about
// half the output bits). For deterministic noise and jitter.

#include <cstdint>

namespace dermis {

constexpr uint32_t lowbias32(uint32_t h) {
    h ^= h >> 16;
    h *= 0x7feb352dU;
    h ^= h >> 15;
    h *= 0x846ca68bU;
    h ^= h >> 16;
    return h;
}

}  // namespace dermis
