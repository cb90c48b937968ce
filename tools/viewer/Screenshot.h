#pragma once
// Screenshots of the whole window, panels included: the back buffer, read
// after the UI is drawn and before the buffers are swapped.

#include "core/Image.h"
#include "core/Result.h"

#include <string>

namespace dermis::viewer {

// The default framebuffer's back buffer, rows top first, values in [0, 1].
Image readBackBuffer(int width, int height);

// Reads the back buffer and writes it as a PNG.
Status saveScreenshot(const std::string& path, int width, int height);

}  // namespace dermis::viewer
