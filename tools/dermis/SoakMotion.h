#pragma once
// How `dermis soak` changes its scene. Everything repeats with a period of
// 2K frames (K = --change-every): the camera orbits the target once about the
// vertical axis, the first light turns once the other way, and a copy of the
// first character stands beside it during the second half of each period.
// Frames one period apart render the same scene, so their memory can be
// compared like for like.

#include "scene/Scene.h"

namespace dermis::cli {

// The scene `frame` frames in: `base` with its camera and first light turned.
// Characters are not touched (soakCopyPresent says when the copy is there).
void applySoakMotion(const Scene& base, int frame, int periodFrames, Scene& scene);
bool soakCopyPresent(int frame, int periodFrames);
// `original` moved by `offsetM` along world x, named "<name> copy".
Character soakCopy(const Character& original, float offsetM);

}  // namespace dermis::cli
