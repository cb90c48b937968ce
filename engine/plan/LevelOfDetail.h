#pragma once
// Which level of detail a character draws this frame (mesh/MeshLod.h,
// settings.lod): the coarsest level whose error against the full mesh,
// projected at the character's nearest view depth, is at most
// settings.lod.max_error_px pixels. Hysteresis keeps a character from
// flickering between two levels as it moves: it goes to a coarser level only
// once that level's error is within kLodHysteresis of the limit, and back to
// a finer one as soon as its level's error passes the limit.

#include <vector>

namespace dermis {

// A coarser level must project to at most this share of the limit to be taken.
constexpr float kLodHysteresis = 0.75f;

// errorsObject: each level's error (object units), finest first, level 0 (the
// full mesh) not listed; pixelsPerObjectUnit at the character's nearest
// depth; previousLevel: last frame's, or -1 for none. Returns the level, 0
// for the full mesh. maxErrorPx <= 0 always gives 0.
int chooseLodLevel(const std::vector<float>& errorsObject, float pixelsPerObjectUnit, float maxErrorPx, int previousLevel);

}  // namespace dermis
