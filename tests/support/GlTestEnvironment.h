#pragma once
// A headless GL 4.5 context with debug output for render tests. Every test
// that uses it checks that the GL reported no error while it ran.

#include "gl/GlContext.h"
#include "gl/GlDebug.h"

#include <gtest/gtest.h>

#include <memory>

namespace dermis::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    static void TearDownTestSuite();
    void SetUp() override;
    void TearDown() override;  // fails the test on any GL error it caused

    static std::unique_ptr<gl::Context> sContext;
    uint64_t mErrorsBefore = 0;
};

}  // namespace dermis::test
