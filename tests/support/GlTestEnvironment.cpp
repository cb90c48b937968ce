#include "GlTestEnvironment.h"

namespace dermis::test {

std::unique_ptr<gl::Context> GlTest::sContext;

void GlTest::SetUpTestSuite() {
    if (sContext) return;
    auto context = gl::createHeadlessContext({gl::Backend::Auto, true});
    if (context.ok()) sContext = std::move(*context);
}

void GlTest::TearDownTestSuite() { sContext.reset(); }

void GlTest::SetUp() {
    ASSERT_TRUE(sContext) << "no headless OpenGL 4.5 context could be created";
    gl::drainGlErrors();
    mErrorsBefore = gl::debugErrorCount();
}

void GlTest::TearDown() {
    if (!sContext) return;
    gl::drainGlErrors();
    EXPECT_EQ(gl::debugErrorCount(), mErrorsBefore) << "GL error during the test: " << gl::lastDebugError();
}

}  // namespace dermis::test
