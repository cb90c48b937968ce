#pragma once
// The procedural head's mesh: a skull, face and neck traced from a signed
// distance field along rays from the head's centre (one UV chart, cut at the
// back), and two thin ears (two charts each), packed into [0,1]^2 with gutters.

#include "mesh/Mesh.h"

#include <cstddef>

namespace dermis {

struct HeadMesh {
    MeshData mesh;
    size_t skullTriangleCount = 0;  // triangles [0, this) are skull, the rest ears
};

HeadMesh makeHeadMesh();

}  // namespace dermis
