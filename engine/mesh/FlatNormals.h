#pragma once
// Flat shading for a mesh that has no normals of its own. glTF 2.0 §3.7.2.1:
// "When normals are not specified, client implementations MUST calculate
// flat normals". Each triangle gets three vertices of its own, copies of its
// corners, all with the triangle's normal (its winding's, counter-clockwise
// in front), so no two triangles share a normal.

#include "mesh/Mesh.h"

#include <cstdint>
#include <vector>

namespace dermis {

struct UnweldedMesh {
    MeshData mesh;                       // three vertices per triangle; indices 0, 1, 2, ...
    std::vector<uint32_t> sourceVertex;  // per vertex of `mesh`, the input vertex it copies
    std::vector<bool> degenerate;        // per vertex: its triangle has no area; the normal is left as the input's
};

UnweldedMesh unweldWithFaceNormals(const MeshData& mesh);

}  // namespace dermis
