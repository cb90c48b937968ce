// Where the program finds its shaders, content and scripts
// (core/DataDirectory.h). The installed cases (a program beside
// share/dermis, the .deb) are tests/install/check_install.cmake's; here the
// environment variables and the build tree's fallback.
#include "core/DataDirectory.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace dermis;

namespace {

const std::string kSourceTree = std::filesystem::path(DERMIS_SOURCE_SHADER_DIR).parent_path().string();

}  // namespace

TEST(DataDirectory, TheBuildTreeReadsTheSourceTree) {
    const test::ScopedEnvironmentVariable noShaders("DERMIS_SHADER_DIR", nullptr);
    const test::ScopedEnvironmentVariable noData("DERMIS_DATA_DIR", nullptr);
    EXPECT_EQ(dataDirectory(DataKind::Shaders), kSourceTree + "/shaders");
    EXPECT_EQ(dataDirectory(DataKind::Content), kSourceTree + "/content");
    EXPECT_EQ(dataDirectory(DataKind::Tools), kSourceTree + "/tools");
}

TEST(DataDirectory, DataDirWinsForTheFoldersItHoldsAndShaderDirWinsOverIt) {
    test::TempDir data;
    std::filesystem::create_directories(data.path() / "shaders");
    std::filesystem::create_directories(data.path() / "content");
    const test::ScopedEnvironmentVariable noShaders("DERMIS_SHADER_DIR", nullptr);
    const test::ScopedEnvironmentVariable dataDir("DERMIS_DATA_DIR", data.path().c_str());
    EXPECT_EQ(dataDirectory(DataKind::Shaders), data.file("shaders"));
    EXPECT_EQ(dataDirectory(DataKind::Content), data.file("content"));
    // Not in the data folder: the next rule (the source tree) answers.
    EXPECT_EQ(dataDirectory(DataKind::Tools), kSourceTree + "/tools");

    test::TempDir shaders;
    const test::ScopedEnvironmentVariable shaderDir("DERMIS_SHADER_DIR", shaders.path().c_str());
    EXPECT_EQ(dataDirectory(DataKind::Shaders), shaders.path().string());
    EXPECT_EQ(dataDirectory(DataKind::Content), data.file("content"));
}

TEST(DataDirectory, CandidatesComeInTheDocumentedOrder) {
    const test::ScopedEnvironmentVariable shaderDir("DERMIS_SHADER_DIR", "/a");
    const test::ScopedEnvironmentVariable dataDir("DERMIS_DATA_DIR", "/b");
    const std::vector<std::string> candidates = dataDirectoryCandidates(DataKind::Shaders);
    ASSERT_EQ(candidates.size(), 6u);
    EXPECT_EQ(candidates[0], "/a");
    EXPECT_EQ(candidates[1], "/b/shaders");
    // The running test program is build/tests/dermis_unit_tests.
    EXPECT_EQ(candidates[2], std::string(DERMIS_BUILD_DIR) + "/share/dermis/shaders");
    EXPECT_EQ(candidates[3], kSourceTree + "/shaders");
    EXPECT_EQ(candidates[5], "/usr/share/dermis/shaders");
    EXPECT_EQ(dataDirectoryCandidates(DataKind::Tools).size(), 5u) << "$DERMIS_SHADER_DIR names shaders only";
}
