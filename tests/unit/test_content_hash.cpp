// The disk caches' keys (core/ContentHash.h): FNV-1a against its published
// test vectors, and the running hash's sensitivity to every byte and to where
// one piece ends and the next begins.
#include "core/ContentHash.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace dermis;

TEST(ContentHash, FnvMatchesThePublishedVectors) {
    // Landon Curt Noll's FNV test suite: FNV-1a 64 of "" is the offset basis, of "a" and "foobar":
    EXPECT_EQ(fnv1a("", 0), 0xcbf29ce484222325ULL);
    EXPECT_EQ(fnv1a("a", 1), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(fnv1a("foobar", 6), 0x85944171f73967e8ULL);
}

TEST(ContentHash, EveryByteAndEveryBoundaryCounts) {
    // 7, 8 and 17 bytes: the tail alone, one word, words and a tail.
    for (size_t size : {7u, 8u, 17u}) {
        std::vector<unsigned char> data(size, 0x5a);
        const uint64_t base = ContentHash().bytes(data.data(), size).value();
        for (size_t i = 0; i < size; ++i) {
            std::vector<unsigned char> changed = data;
            changed[i] ^= 1;
            EXPECT_NE(ContentHash().bytes(changed.data(), size).value(), base) << "byte " << i << " of " << size;
        }
    }
    EXPECT_NE(ContentHash().text("ab").text("c").value(), ContentHash().text("a").text("bc").value());
    EXPECT_NE(ContentHash().text("").value(), ContentHash().value());
    EXPECT_EQ(ContentHash().text("abc").value(), ContentHash().text("abc").value());
}

TEST(ContentHash, TheProgramHasOneHash) {
    const uint64_t program = programContentHash();
    EXPECT_NE(program, 0u) << "/proc/self/exe could not be read";
    EXPECT_EQ(programContentHash(), program);
}
