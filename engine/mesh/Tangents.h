#pragma once
// Per-vertex tangent frames for normal mapping, MikkTSpace-style: per-triangle
// tangents from UV derivatives, accumulated per vertex weighted by corner
// angle, Gram-Schmidt orthogonalised against the vertex normal, with the
// bitangent sign in w. Degenerate UVs or triangles give a finite tangent
// (any unit vector orthogonal to the normal), never NaN.

#include "mesh/Mesh.h"

namespace dermis {

void generateTangents(MeshData& mesh);

// Normals from geometry, area-and-angle weighted, for meshes that lack them.
void generateNormals(MeshData& mesh);

}  // namespace dermis
