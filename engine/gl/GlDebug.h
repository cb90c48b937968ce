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

struct DrainedGlErrors {
    uint64_t count = 0;
    bool outOfMemory = false;  // one of them was GL_OUT_OF_MEMORY: a texture or buffer was not allocated
};
DrainedGlErrors drainGlErrorsNoting();  // drainGlErrors, also saying whether the driver ran out of memory

}  // namespace dermis::gl
