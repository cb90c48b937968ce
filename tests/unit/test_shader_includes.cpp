// The shader loader's includes (gl/ShaderProgram.h): a generated include (text
// the caller makes, such as the lighting pass's dispatch over the SSS
// techniques, render/LightingScatter.h) is found before the shader folder and
// its own #includes are expanded like a file's, each file once.
#include "gl/ShaderProgram.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

int occurrences(const std::string& text, const std::string& what) {
    int count = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
    return count;
}

// A shader folder of its own, set as $DERMIS_SHADER_DIR while the test runs.
class ShaderFolder : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() / ("dermis_shader_includes_" + std::to_string(::getpid()));
        fs::remove_all(mDir);
        writeFile(mDir / "main.frag", "#include \"Generated.glsl\"\nvoid main() {}\n");
        writeFile(mDir / "include" / "Shared.glsl", "float sharedValue;\n");
        writeFile(mDir / "include" / "Generated.glsl", "float fromTheFolder;\n");
        const char* previous = std::getenv("DERMIS_SHADER_DIR");
        mPrevious = previous ? previous : "";
        mHadPrevious = previous != nullptr;
        ::setenv("DERMIS_SHADER_DIR", mDir.c_str(), 1);
    }
    void TearDown() override {
        if (mHadPrevious) {
            ::setenv("DERMIS_SHADER_DIR", mPrevious.c_str(), 1);
        } else {
            ::unsetenv("DERMIS_SHADER_DIR");
        }
        fs::remove_all(mDir);
    }
    fs::path mDir;
    std::string mPrevious;
    bool mHadPrevious = false;
};

TEST_F(ShaderFolder, GeneratedIncludeComesFirstAndExpandsItsIncludesOnce) {
    const dermis::gl::GeneratedInclude generated{
        "Generated.glsl", "#include \"Shared.glsl\"\nfloat generatedValue;\n#include \"Shared.glsl\"\n"};
    const auto source = dermis::gl::loadShaderSource("main.frag", {{"ANSWER", "42"}}, {generated});
    ASSERT_TRUE(source.ok()) << source.error().message();
    EXPECT_EQ(occurrences(*source, "float generatedValue;"), 1) << *source;
    EXPECT_EQ(occurrences(*source, "float sharedValue;"), 1) << *source;
    EXPECT_EQ(occurrences(*source, "fromTheFolder"), 0) << *source;
    EXPECT_EQ(occurrences(*source, "#include"), 0) << *source;
    EXPECT_EQ(occurrences(*source, "#define ANSWER 42"), 1) << *source;
}

TEST_F(ShaderFolder, WithoutTheGeneratedIncludeTheFolderIsRead) {
    const auto source = dermis::gl::loadShaderSource("main.frag", {});
    ASSERT_TRUE(source.ok()) << source.error().message();
    EXPECT_EQ(occurrences(*source, "float fromTheFolder;"), 1) << *source;
}

TEST_F(ShaderFolder, AMissingIncludeOfAGeneratedOneIsNamed) {
    const dermis::gl::GeneratedInclude generated{"Generated.glsl", "#include \"Missing.glsl\"\n"};
    const auto source = dermis::gl::loadShaderSource("main.frag", {}, {generated});
    ASSERT_FALSE(source.ok());
    EXPECT_NE(source.error().message().find("Missing.glsl"), std::string::npos) << source.error().message();
}

}  // namespace
