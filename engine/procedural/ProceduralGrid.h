#pragma once
// The building block of every procedural mesh: a rectangular grid of vertices
// from a parametric function, two triangles per cell.

#include "mesh/Mesh.h"

#include <functional>

namespace dermis {

// Appends (columns + 1) x (rows + 1) vertices, vertexAt(column, row), and two
// triangles per cell. The triangles are wound counter-clockwise seen from the
// side that cross(dP/drow, dP/dcolumn) points to; with u growing along columns
// and v along rows (glTF: v down the image), that is the side from which the
// texture reads unmirrored. Triangles with two coincident corners (a grid row
// collapsed to a pole) are left out.
void appendGrid(MeshData& mesh, int columns, int rows, const std::function<Vertex(int column, int row)>& vertexAt);

}  // namespace dermis
