#pragma once
// The procedural test shapes, in metres, with normals, tangents and UVs.

#include "mesh/Mesh.h"

namespace dermis {

// 1 m x 1 m in the XZ plane centred on the origin, normal +Y; u along +X,
// v along +Z (so the image's top edge is at -Z), 32 x 32 cells.
MeshData makePlaneMesh();

// Radius 0.1 m about the origin; u along longitude (0 and 1 at the back,
// -Z, 0.5 at the front), v along latitude (0 at the north pole, +Y). The
// seam column is duplicated.
MeshData makeSphereMesh();

// A closed solid: x in [0, 0.2] m, z in [-0.05, 0.05] m, and between
// y = -t(x)/2 and +t(x)/2 with t = 1 mm + (19 mm / 0.2 m) x. Its six faces
// are flat-shaded (vertices split per face) and atlased side by side in UV at
// one common scale.
MeshData makeWedgeMesh();

constexpr float kSphereRadiusM = 0.1f;
constexpr float kWedgeLengthM = 0.2f;
constexpr float kWedgeDepthM = 0.1f;
constexpr float kWedgeThinMm = 1.0f;
constexpr float kWedgeThickMm = 20.0f;

}  // namespace dermis
