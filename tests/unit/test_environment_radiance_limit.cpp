// A map brighter than Dermis can sum is refused in one line naming the file,
// the radiance and the intensity (import/EnvironmentSource.cpp): 1.7e38 in an
// .hdr once rendered the character at exactly 0, the overflowed light zeroed.
#include "TestSupport.h"

#include "core/ImageResample.h"
#include "core/Limits.h"
#include "import/EnvironmentSource.h"

#include <gtest/gtest.h>

using namespace dermis;

namespace {

Environment mapOf(const test::TempDir& dir, float radiance, float intensity) {
    const std::string path = dir.file("map.exr");
    EXPECT_TRUE(saveImage(path, makeImage(16, 8, ColourSpace::Linear, glm::vec4(radiance, radiance, radiance, 1.0f))));
    Environment environment;
    environment.source = path;
    environment.intensity = intensity;
    return environment;
}

}  // namespace

TEST(EnvironmentRadianceLimit, MapsAboveTheSummableRadianceAreRefusedInOneLine) {
    test::TempDir dir;
    auto huge = loadEnvironmentSource(mapOf(dir, 1.7e38f, 1.0f));
    ASSERT_FALSE(huge);
    const std::string message = huge.error().message();
    EXPECT_NE(message.find("map.exr: radiance up to 1.7e+38 x intensity 1 is above 1e+20"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
    // The product counts: a bright map under a large intensity too.
    EXPECT_FALSE(loadEnvironmentSource(mapOf(dir, 1e15f, 1e6f)));
    // At the limit it loads (a real sun is 1e3 to 1e5).
    EXPECT_TRUE(loadEnvironmentSource(mapOf(dir, 1e15f, 1e5f)));
    EXPECT_TRUE(loadEnvironmentSource(mapOf(dir, 65504.0f, 1.0f)));
}
