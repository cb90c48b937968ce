#pragma once
// glTF test content built in code with tinygltf, so tests and docs need no
// third-party files.
//
// The bending cylinder: a skinned, animated tube along +Y, two bones and a
// morph target, made to check skinning against closed forms.
//   - bone "root" at the origin; bone "bend" its child at y = kJointYM.
//   - weights: the "bend" weight rises smoothly (smoothstep) from 0 at
//     kJointYM - kBlendM to 1 at kJointYM + kBlendM; "root" has the rest.
//   - clip "bend", LINEAR: "bend" rotates about +Z by 0 deg at 0 s, kBendDeg
//     at 1 s, 0 at 2 s; the morph weight goes 0, 1, 0 at the same times.
//   - morph target "bulge": each vertex moves outwards by kBulgeM x
//     max(0, 1 - |y - kJointYM| / kBulgeHalfWidthM).
//   - the mesh node has a translation, which glTF 2.0 §3.7.3 says a skinned
//     mesh ignores.

#include <string>

namespace dermis::test {

struct BendingCylinder {
    static constexpr float kLengthM = 0.2f;
    static constexpr float kRadiusM = 0.03f;
    static constexpr float kJointYM = 0.1f;
    static constexpr float kBlendM = 0.02f;
    static constexpr float kBendDeg = 90.0f;
    static constexpr float kBulgeM = 0.01f;
    static constexpr float kBulgeHalfWidthM = 0.03f;
    static constexpr int kRings = 41;     // vertex rings along the axis
    static constexpr int kSegments = 32;  // around it (plus a seam column)
};

// Writes the bending cylinder as a .gltf with its buffer embedded; false and
// a message on failure. uvScale < 1 packs its UVs into the corner square of
// that side, as an atlas chart: uvScale^2 of the UV square is covered.
bool writeBendingCylinder(const std::string& path, std::string* error = nullptr, float uvScale = 1.0f);

}  // namespace dermis::test
