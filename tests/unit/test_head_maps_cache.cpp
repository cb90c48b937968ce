// The procedural head's maps from the disk cache (procedural/HeadMapsCache.h)
// against the maps baked in the same process, and the cache's bound on files.
#include "procedural/HeadMapsCache.h"

#include "core/CacheDirectory.h"
#include "procedural/ProceduralTextures.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

using namespace dermis;
namespace fs = std::filesystem;

namespace {

bool sameTexels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.colourSpace == b.colourSpace &&
           std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(glm::vec4)) == 0;
}

}  // namespace

// Small maps (64 and 128 texels) keep the bakes short; the layout is the same.
TEST(HeadMapsCache, ReadMapsAreTheBakedOnesAndOldFilesMakeRoom) {
    const test::TempDir dir;
    const test::ScopedEnvironmentVariable cache("DERMIS_CACHE_DIR", dir.path().c_str());
    const auto longAgo = fs::file_time_type::clock::now() - std::chrono::hours(24);
    for (int i = 0; i < kHeadMapsCacheFilesKept; ++i) {
        const fs::path old = dir.path() / ("procedural-head-maps-old" + std::to_string(i) + ".bin");
        std::ofstream(old) << "made by an earlier build";
        fs::last_write_time(old, longAgo + std::chrono::minutes(i));
    }
    const HeadMesh head = makeHeadMesh();
    const Image albedo = makeHeadAlbedoMap(head, 64);
    const Image normal = makeHeadNormalMap(head, 128);

    ::testing::internal::CaptureStderr();
    const HeadMaps baked = loadOrBakeHeadMaps(head, 64, 128);
    const std::string log = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(baked.fromCache);
    EXPECT_NE(log.find("baked the procedural head's maps (64^2 albedo, 128^2 normals)"), std::string::npos) << log;
    ASSERT_EQ(baked.cacheFile.parent_path(), dir.path());
    EXPECT_TRUE(fs::exists(baked.cacheFile));
    EXPECT_FALSE(fs::exists(dir.path() / "procedural-head-maps-old0.bin")) << "the least recently used is removed";
    EXPECT_TRUE(fs::exists(dir.path() / "procedural-head-maps-old1.bin"));

    const HeadMaps read = loadOrBakeHeadMaps(head, 64, 128);
    EXPECT_TRUE(read.fromCache);
    EXPECT_TRUE(sameTexels(read.albedo, albedo));
    EXPECT_TRUE(sameTexels(read.normal, normal));
    EXPECT_EQ(read.albedo.colourSpace, ColourSpace::Srgb);
    EXPECT_EQ(read.normal.colourSpace, ColourSpace::Linear);

    // Other sizes are other content.
    const HeadMaps other = loadOrBakeHeadMaps(head, 32, 128);
    EXPECT_FALSE(other.fromCache);
    EXPECT_NE(other.cacheFile, read.cacheFile);
}

// A damaged file is baked again (core/CacheFile.h's checks, tested there) and
// the bake replaces it.
TEST(HeadMapsCache, ADamagedFileIsBakedAgainAndReplaced) {
    const test::TempDir dir;
    const test::ScopedEnvironmentVariable cache("DERMIS_CACHE_DIR", dir.path().c_str());
    const HeadMesh head = makeHeadMesh();
    const HeadMaps first = loadOrBakeHeadMaps(head, 32, 64);
    const auto size = fs::file_size(first.cacheFile);
    {
        std::fstream f(first.cacheFile, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(std::streamoff(size - 5));
        f.put('\x55');
    }
    ::testing::internal::CaptureStderr();
    const HeadMaps again = loadOrBakeHeadMaps(head, 32, 64);
    const std::string log = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(again.fromCache);
    EXPECT_NE(log.find("ignoring the procedural head maps cache"), std::string::npos) << log;
    EXPECT_TRUE(sameTexels(again.normal, first.normal));
    EXPECT_TRUE(loadOrBakeHeadMaps(head, 32, 64).fromCache);
}
