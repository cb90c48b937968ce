#pragma once
// Whether a mesh's back faces can ever show from outside it, so that the
// G-buffer may cull them (passes/GBufferPass.cpp).

#include "mesh/Mesh.h"

#include <cstdint>
#include <vector>

namespace dermis {

// Points welded by exact position (bit-equal coordinates, as seams and
// flat-shaded faces duplicate a vertex): ids[i] is point i's welded id,
// numbered from 0 in the order first seen; count is how many there are.
struct WeldedPoints {
    std::vector<uint32_t> ids;
    size_t count = 0;
};
WeldedPoints weldByPosition(const std::vector<glm::vec3>& points);

// True when, with vertices welded by exact position (seams and flat-shaded
// faces duplicate them), every non-degenerate triangle edge (a, b) appears
// once and its reverse (b, a) once, and the signed volume is positive: every
// part is closed, consistently wound and counter-clockwise seen from outside.
// A ray from a viewpoint outside every part that reaches a back face then
// left that part there, so it entered it earlier through a front face of the
// same part: the back face is hidden, also where parts intersect.
bool isClosedOutward(const MeshData& mesh);

}  // namespace dermis
