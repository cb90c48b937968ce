#pragma once
// KHR_debug output. Errors reported by the driver are counted, so a test can
// assert that the frame it rendered caused none.

#include <cstdint>
#include <string>

namespace dermis::gl {

void enableDebugOutput();
uint64_t debugErrorCount();        // GL_DEBUG_TYPE_ERROR messages since start
std::string lastDebugError();      // the latest one, for test failure messages
uint64_t drainGlErrors();          // glGetError until clean; returns how many it saw (also counted)

}  // namespace dermis::gl
