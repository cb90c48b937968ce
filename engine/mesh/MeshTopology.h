#pragma once
// Whether a mesh's back faces can ever show from outside it, so that the
// G-buffer may cull them (passes/GBufferPass.cpp).

#include "mesh/Mesh.h"

namespace dermis {

// True when, with vertices welded by exact position (seams and flat-shaded
// faces duplicate them), every non-degenerate triangle edge (a, b) appears
// once and its reverse (b, a) once, and the signed volume is positive: every
// part is closed, consistently wound and counter-clockwise seen from outside.
// A ray from a viewpoint outside every part that reaches a back face then
// left that part there, so it entered it earlier through a front face of the
// same part: the back face is hidden, also where parts intersect.
bool isClosedOutward(const MeshData& mesh);

}  // namespace dermis
