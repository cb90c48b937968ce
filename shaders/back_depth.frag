// The back-depth pass (passes/ThinEdgePasses.cpp, include/ThinEdges.glsl):
// the characters' back faces; the depth test keeps the nearest. It writes the
// face's view-space normal (the vertices' normal, interpolated), which tells
// a part's far side (facing away from the front) from the wall of a thick
// body's corner that a slanted view ray leaves through.
#include "Common.glsl"

in vec3 vViewNormal;
layout(location = 0) out vec2 oBackNormal;

void main() { oBackNormal = sanitiseRange(encodeNormal(safeNormalize(vViewNormal, vec3(0.0, 0.0, -1.0))), -1.0, 1.0); }
