#pragma once
// Shared state of the benchmark process: one headless GL context, scenes
// loaded once, and the figures the summary at the end compares.

#include "gl/GlContext.h"
#include "frame/Renderer.h"
#include "scene/Scene.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dermis::bench {

gl::Context& context();  // created on first use; aborts with a message when none can be made

// Loads content/scenes/<name> once and keeps it alive for the process.
const Scene& contentScene(const std::string& name);

// Renders one frame and returns the summed GPU ms of passes whose names
// start with `prefix` ("" = the whole frame). Stalls to read the timers,
// which is fine in a benchmark.
double renderAndTime(Renderer& renderer, int width, int height, const std::string& prefix);
// The same at frame time timeS (animated characters), one sum per prefix.
std::vector<double> renderAndTimeAt(Renderer& renderer, int width, int height, float timeS,
                                    const std::vector<std::string>& prefixes);

// One frame of `aov` read back (an empty image if the frame or the read fails).
Image renderAov(Renderer& renderer, int width, int height, Aov aov);
// measure::sssMask, empty when the frame fails.
std::vector<uint8_t> sssPixelMask(Renderer& renderer, int width, int height);

// Figures recorded by benchmarks (median GPU ms per named measurement) for
// the comparisons printed after the run.
std::map<std::string, double>& recorded();

}  // namespace dermis::bench
