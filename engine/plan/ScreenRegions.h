#pragma once
// Disjoint pixel rectangles that cover a set of rectangles: the screen-space
// SSS blurs cover these regions (in one draw) instead of the union's bounding box,
// so that characters spread over the frame cost their own rectangles, not the
// frame (32 small characters sharing one's pixels: docs/animation.md,
// "Cost"). Disjoint, because the blurs accumulate by blending: a pixel drawn
// twice would be added twice.

#include "gpu/UniformBlocks.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

// Above this many regions, or when the regions' area is more than this
// share of their bounding box, the bounding box is returned instead: one
// draw costs less than many that save little.
constexpr size_t kMaxScreenRegions = DERMIS_MAX_SCREEN_REGIONS;  // one draw covers them (FrameContext.h)
constexpr float kRegionAreaShareForOneBox = 0.7f;

// Rectangles are (x, y, width, height) in pixels; empty ones are ignored.
// The result covers exactly the union of `rects` (or their bounding box, as
// above), its rectangles do not overlap, and it is empty when they all are.
std::vector<glm::ivec4> disjointCover(const std::vector<glm::ivec4>& rects);

}  // namespace dermis
