#pragma once
// The procedural head's ears: thin cupped plates, each a closed surface
// (outer face and inner face meeting at a rounded rim) whose front part is
// buried in the side of the skull. Each face is its own UV chart, a planar
// projection onto the ear's plane.

#include "mesh/Mesh.h"

namespace dermis {

// The size (width, height) in metres of the planar region each face chart
// covers; at uvPerM UV units per metre a chart is uvPerM times this.
glm::vec2 earChartSizeM();

// Appends the right (side = +1) or left (side = -1) ear with its outer and
// inner face charts placed with their top-left corners (minimum u and v) at
// the given UVs.
void appendEar(MeshData& mesh, float side, const glm::vec2& outerChartUv, const glm::vec2& innerChartUv, float uvPerM);

}  // namespace dermis
