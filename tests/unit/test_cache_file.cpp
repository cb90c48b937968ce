// The disk caches' file (core/CacheFile.h): a round trip, every check a
// reader makes (each defect planted in a written file), and the
// least-recently-used clean-up.
#include "core/CacheFile.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <vector>

using namespace dermis;
namespace fs = std::filesystem;

namespace {

const CacheFileKind kKind{{'D', 'R', 'M', 'S', 'T', 'E', 'S', 'T'}, 3, "test"};
constexpr uint64_t kKey = 0x0123456789abcdefULL;

struct TwoParts {
    std::vector<float> floats = std::vector<float>(1000);
    std::vector<uint32_t> words = std::vector<uint32_t>(37);
    TwoParts() {
        std::iota(floats.begin(), floats.end(), 0.25f);
        std::iota(words.begin(), words.end(), 7u);
    }
    std::vector<ConstBytes> constParts() const {
        return {{floats.data(), floats.size() * sizeof(float)}, {words.data(), words.size() * sizeof(uint32_t)}};
    }
    std::vector<MutableBytes> mutableParts() {
        return {{floats.data(), floats.size() * sizeof(float)}, {words.data(), words.size() * sizeof(uint32_t)}};
    }
};

// The reader's message for `file`, or "" when it reads.
std::string readError(const fs::path& file, const CacheFileKind& kind = kKind, uint64_t key = kKey) {
    TwoParts into;
    std::fill(into.floats.begin(), into.floats.end(), 0.0f);
    Status read = readCacheFile(file, kind, key, into.mutableParts());
    return read ? std::string() : read.error().message();
}

void setByte(const fs::path& file, std::streamoff offset, char value) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(offset);
    f.put(value);
}

}  // namespace

TEST(CacheFile, WhatIsWrittenReadsBackWithNothingLeftBeside) {
    const test::TempDir dir;
    const fs::path file = dir.path() / "sub" / cacheFileName("test-", kKey);
    EXPECT_EQ(file.filename(), "test-0123456789abcdef.bin");
    const TwoParts written;
    ASSERT_TRUE(writeCacheFile(file, kKind, kKey, written.constParts()));
    EXPECT_EQ(fs::file_size(file), 48 + 1000 * 4 + 37 * 4) << "the header, then the payload";
    TwoParts read;
    std::fill(read.floats.begin(), read.floats.end(), 0.0f);
    std::fill(read.words.begin(), read.words.end(), 0u);
    ASSERT_TRUE(readCacheFile(file, kKind, kKey, read.mutableParts()));
    EXPECT_EQ(read.floats, written.floats);
    EXPECT_EQ(read.words, written.words);
    EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator()), 1) << "no temporary";
}

// Each planted defect must be named; without the check it names, the file
// would load short, long, stale or wrong.
TEST(CacheFile, EveryDefectIsNamed) {
    const test::TempDir dir;
    const fs::path file = dir.path() / "f.bin";
    const TwoParts written;
    const auto rewrite = [&] { ASSERT_TRUE(writeCacheFile(file, kKind, kKey, written.constParts())); };
    const auto size = std::streamoff(48 + 1000 * 4 + 37 * 4);

    rewrite();
    EXPECT_EQ(readError(file), "");
    EXPECT_NE(readError(dir.path() / "missing.bin").find("cannot be opened"), std::string::npos);

    fs::resize_file(file, 20);
    EXPECT_NE(readError(file).find("shorter than its header"), std::string::npos) << readError(file);

    rewrite();
    setByte(file, 4, 'X');
    EXPECT_NE(readError(file).find("not a test cache file"), std::string::npos) << readError(file);

    rewrite();
    EXPECT_NE(readError(file, CacheFileKind{kKind.magic, 4, "test"}).find("version 3, expected 4"), std::string::npos);
    EXPECT_NE(readError(file, kKind, kKey + 1).find("another key"), std::string::npos);

    fs::resize_file(file, uintmax_t(size - 1));
    EXPECT_NE(readError(file).find("truncated"), std::string::npos) << readError(file);

    rewrite();
    { std::ofstream(file, std::ios::binary | std::ios::app).put('\0'); }
    EXPECT_NE(readError(file).find("longer than its payload"), std::string::npos) << readError(file);

    rewrite();
    setByte(file, size - 3, '\x7f');
    EXPECT_NE(readError(file).find("corrupt"), std::string::npos) << readError(file);

    // A payload of another layout: the same bytes read as one part of the
    // wrong size.
    rewrite();
    std::vector<float> fewer(999);
    Status short_ = readCacheFile(file, kKind, kKey, {{fewer.data(), fewer.size() * sizeof(float)}});
    ASSERT_FALSE(short_);
    EXPECT_NE(short_.error().message().find("bytes of payload, expected 3996"), std::string::npos) << short_.error().message();
}

TEST(CacheFile, AWarningForAFileThatCannotBeUsedAndNoneForOneThatIsMissing) {
    const test::TempDir dir;
    const fs::path file = dir.path() / "f.bin";
    TwoParts into;
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(readCacheFileOrWarn(file, kKind, kKey, into.mutableParts()));
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");

    const TwoParts written;
    writeCacheFileOrWarn(file, kKind, kKey, written.constParts());
    fs::resize_file(file, 100);
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(readCacheFileOrWarn(file, kKind, kKey, into.mutableParts()));
    const std::string log = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("warning: ignoring the test cache: "), std::string::npos) << log;
    EXPECT_NE(log.find("; recomputing"), std::string::npos) << log;

    // A regular file where the directory should be: nothing can be made under it, even as root.
    std::ofstream(dir.path() / "plain") << "x";
    ::testing::internal::CaptureStderr();
    writeCacheFileOrWarn(dir.path() / "plain" / "f.bin", kKind, kKey, written.constParts());
    const std::string unwritable = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(unwritable.find("warning: test not cached: "), std::string::npos) << unwritable;
}

TEST(CacheFile, OnlyTheMostRecentlyUsedFilesOfAPrefixAreKept) {
    const test::TempDir dir;
    const auto now = fs::file_time_type::clock::now();
    // Five files of the prefix, the first written longest ago, and three that
    // are not the prefix's .bin files.
    for (int i = 0; i < 5; ++i) {
        const fs::path file = dir.path() / ("maps-" + std::to_string(i) + ".bin");
        std::ofstream(file) << i;
        fs::last_write_time(file, now - std::chrono::hours(10 - i));
    }
    for (const char* other : {"other-0.bin", "maps-9.bin.tmp123-0", "maps-notes.json"}) {
        std::ofstream(dir.path() / other) << "x";
        fs::last_write_time(dir.path() / other, now - std::chrono::hours(100));
    }
    // Reading the oldest marks it used.
    const TwoParts written;
    const fs::path used = dir.path() / "maps-0.bin";
    ASSERT_TRUE(writeCacheFile(used, kKind, kKey, written.constParts()));
    fs::last_write_time(used, now - std::chrono::hours(20));
    TwoParts into;
    ASSERT_TRUE(readCacheFileOrWarn(used, kKind, kKey, into.mutableParts()));

    EXPECT_EQ(removeLeastRecentlyUsed(dir.path(), "maps-", 3), 2);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir.path())) left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"maps-0.bin", "maps-3.bin", "maps-4.bin", "maps-9.bin.tmp123-0",
                                              "maps-notes.json", "other-0.bin"}));
}
