#include "core/ContentHash.h"

#include "core/Image.h"

#include <cstdio>
#include <cstring>
#include <fstream>

namespace dermis {

ContentHash& ContentHash::bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t word = 0;
        std::memcpy(&word, p + i, sizeof word);
        mHash = (mHash ^ word) * kFnvPrime;
    }
    for (; i < size; ++i) mHash = (mHash ^ p[i]) * kFnvPrime;
    mHash = (mHash ^ uint64_t(size)) * kFnvPrime;
    return *this;
}

ContentHash& ContentHash::image(const Image& image) {
    return number(uint64_t(image.width)).number(uint64_t(image.height)).values(image.texels);
}

uint64_t ContentHash::value() const {
    // The splitmix64 finaliser (Steele, Lea & Flood 2014): every input bit reaches every output bit.
    uint64_t z = mHash;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

uint64_t programContentHash() {
    static const uint64_t hash = [] {
        std::ifstream in("/proc/self/exe", std::ios::binary);
        if (!in) return uint64_t(0);
        ContentHash content;
        std::vector<char> chunk(1 << 20);
        while (in) {
            in.read(chunk.data(), std::streamsize(chunk.size()));
            if (in.gcount() > 0) content.bytes(chunk.data(), size_t(in.gcount()));
        }
        return content.value();
    }();
    return hash;
}

std::string hex16(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

}  // namespace dermis
