#pragma once
// 64-bit hashes of content for disk caches' keys (not cryptographic): FNV-1a
// (Fowler, Noll & Vo) over bytes, and a faster word-wise form for large data.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

struct Image;

constexpr uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ULL;
constexpr uint64_t kFnvPrime = 0x100000001b3ULL;

// FNV-1a, byte by byte: the SH transfer cache's key (its files are named by it).
inline uint64_t fnv1a(const void* bytes, size_t size, uint64_t hash = kFnvOffsetBasis) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ p[i]) * kFnvPrime;
    return hash;
}

// A running hash of many pieces: FNV-1a's step over 8-byte words (eight times
// fewer multiplies on textures of hundreds of MB), each piece's length mixed in
// so that a boundary cannot move unseen, and a final avalanche.
class ContentHash {
public:
    ContentHash& bytes(const void* data, size_t size);
    template <class T>
    ContentHash& values(const std::vector<T>& v) {
        return bytes(v.data(), v.size() * sizeof(T));
    }
    ContentHash& text(const std::string& s) { return bytes(s.data(), s.size()); }
    ContentHash& number(uint64_t n) { return bytes(&n, sizeof n); }
    // Its size and texels (the colour space is not part of the content).
    ContentHash& image(const Image& image);
    uint64_t value() const;

private:
    uint64_t mHash = kFnvOffsetBasis;
};

// The running program's own executable file, hashed once per process: a cache
// key that holds it goes stale with any rebuild. 0 when it cannot be read.
uint64_t programContentHash();

// A 64-bit hash as 16 lower-case hex digits: cache file names, identities.
std::string hex16(uint64_t value);

}  // namespace dermis
