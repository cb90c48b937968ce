#pragma once
// Deterministic fuzz-style input for the loader tests: prefixes of a valid
// file and seeded byte mutations of it. No coverage guidance; the point is
// that every loader survives the same few hundred broken inputs on every run.
// std::mt19937 is fully specified by the standard, and only its raw output is
// used (no distributions), so a seed gives the same mutants everywhere.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace dermis::fuzz {

// Lengths to cut a file of `size` bytes at: every length up to `dense` (the
// headers, where most parsing decisions are made), then `spread` lengths
// evenly through the rest. All are shorter than the file.
inline std::vector<size_t> truncationLengths(size_t size, size_t dense = 64, size_t spread = 96) {
    std::vector<size_t> lengths;
    for (size_t length = 0; length < size && length <= dense; ++length) lengths.push_back(length);
    if (size <= dense + 1) return lengths;
    for (size_t i = 1; i <= spread; ++i) {
        const size_t length = dense + (size - 1 - dense) * i / spread;
        if (length > lengths.back()) lengths.push_back(length);
    }
    return lengths;
}

template <class Bytes>
Bytes truncated(const Bytes& bytes, size_t length) {
    return Bytes(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(length));
}

// Applies 1 to kMaxEdits random edits per mutant: overwrite a byte (with a
// random value or one from `alphabet`), flip a bit, insert, erase a run, copy
// a run elsewhere, or write a boundary value (0, 0x7fffffff, 0xffffffff, ...)
// as 4 little-endian bytes, which is what turns a length or count field into
// a huge one.
class Mutator {
public:
    static constexpr int kMaxEdits = 6;

    explicit Mutator(uint32_t seed, std::string alphabet = {}) : mRandom(seed), mAlphabet(std::move(alphabet)) {}

    template <class Bytes>
    Bytes mutate(const Bytes& original) {
        Bytes bytes = original;
        const int edits = 1 + static_cast<int>(next(kMaxEdits));
        for (int e = 0; e < edits && !bytes.empty(); ++e) {
            const size_t at = next(bytes.size());
            switch (next(7)) {
                case 0: bytes[at] = static_cast<typename Bytes::value_type>(pickByte()); break;
                case 1: bytes[at] = static_cast<typename Bytes::value_type>(bytes[at] ^ (1u << next(8))); break;
                case 2: bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), 1 + next(4),
                                     static_cast<typename Bytes::value_type>(pickByte()));
                    break;
                case 3: eraseRun(bytes, at); break;
                case 4: copyRun(bytes, at); break;
                default: writeBoundary(bytes, at); break;
            }
        }
        return bytes;
    }

    // A raw random number below `bound` (> 0).
    size_t next(size_t bound) { return static_cast<size_t>(mRandom()) % bound; }

private:
    unsigned pickByte() {
        if (!mAlphabet.empty() && next(2) == 0) return static_cast<unsigned char>(mAlphabet[next(mAlphabet.size())]);
        return mRandom() & 0xffu;
    }

    template <class Bytes>
    void eraseRun(Bytes& bytes, size_t at) {
        const size_t count = std::min(bytes.size() - at, 1 + next(8));
        bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                    bytes.begin() + static_cast<std::ptrdiff_t>(at + count));
    }

    template <class Bytes>
    void copyRun(Bytes& bytes, size_t at) {
        const size_t from = next(bytes.size());
        const size_t count = std::min(bytes.size() - from, next(40));
        const Bytes run(bytes.begin() + static_cast<std::ptrdiff_t>(from),
                        bytes.begin() + static_cast<std::ptrdiff_t>(from + count));
        bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), run.begin(), run.end());
    }

    template <class Bytes>
    void writeBoundary(Bytes& bytes, size_t at) {
        static constexpr uint32_t kBoundaries[] = {0u,          1u,          0x7fu,       0x80u,      0xffu,
                                                   0xffffu,     0x10000u,    0x7fffffffu, 0x80000000u,
                                                   0xfffffffeu, 0xffffffffu, 100000u};
        const uint32_t value = kBoundaries[next(std::size(kBoundaries))];
        for (size_t i = 0; i < 4 && at + i < bytes.size(); ++i)
            bytes[at + i] = static_cast<typename Bytes::value_type>((value >> (8 * i)) & 0xffu);
    }

    std::mt19937 mRandom;
    std::string mAlphabet;
};

}  // namespace dermis::fuzz
