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

#include <glm/glm.hpp>

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

// The multi-material strip: three flat primitives side by side in the y = 0
// plane (normal +Y), each its own factor-only glTF material and each split
// at its middle into two halves of constant COLOR_0, a step in albedo (the
// colour changes across a band kStepBandM wide; one UV chart per primitive):
//   primitive 0 "Skin"  x in [-30, -10] mm, step at -20 mm, COLOR_0 VEC4 float
//   primitive 1 "Cloth" x in [-10,  10] mm, step at   0 mm, COLOR_0 VEC3 normalised unsigned byte
//   primitive 2 "Wax"   x in [ 10,  30] mm, step at  20 mm, COLOR_0 VEC3 normalised unsigned short
// z in [-20, 20] mm. Each primitive's UVs are its own third of the square
// (u in [i/3, (i+1)/3]), so texture space can hold all three.
struct MultiMaterialStrip {
    static constexpr int kPrimitives = 3;
    static constexpr float kWidthM = 0.02f;      // of one primitive, along x
    static constexpr float kHalfDepthM = 0.02f;  // along z
    static constexpr float kStepBandM = 1e-4f;
    static constexpr const char* kNames[kPrimitives] = {"Skin", "Cloth", "Wax"};
    static constexpr glm::vec4 kFactors[kPrimitives] = {
        {0.9f, 0.7f, 0.6f, 1.0f}, {0.3f, 0.5f, 0.8f, 1.0f}, {0.8f, 0.8f, 0.7f, 1.0f}};
    // [primitive][half]: the colour of its -x half, then its +x half; exact in their formats.
    static constexpr glm::vec3 kColours[kPrimitives][2] = {{{1.0f, 0.8f, 0.7f}, {0.5f, 0.4f, 0.3f}},
                                                           {{1.0f, 1.0f, 1.0f}, {0.2f, 0.6f, 0.4f}},
                                                           {{1.0f, 1.0f, 1.0f}, {0.25f, 0.5f, 0.75f}}};
    static float leftXM(int primitive) { return -0.03f + kWidthM * float(primitive); }
};

// Writes the multi-material strip as a .gltf with its buffer embedded.
bool writeMultiMaterialStrip(const std::string& path, std::string* error = nullptr);

// An avatar as avatar services ship one (Ready Player Me's material names):
// the procedural head (procedural/ProceduralHead.h) in metres, facing +z, its
// triangles split into skin, a scalp of hair, the visible eyeball between the
// lids and a collar of cloth. No scene entry says which is skin: the names do
// (import/MaterialScattering.h). With maps, the skin carries the head's
// albedo and normal maps (PNG files beside the .gltf); without, factors only.
struct Avatar {
    static constexpr int kMaterials = 4;
    static constexpr const char* kNames[kMaterials] = {"Wolf3D_Skin", "Wolf3D_Hair", "Wolf3D_Eye", "Wolf3D_Outfit_Top"};
    // baseColorFactor (linear); the skin's is white under its map, skin-coloured without one.
    static constexpr glm::vec3 kFactors[kMaterials] = {
        {0.80f, 0.58f, 0.48f}, {0.06f, 0.035f, 0.02f}, {0.80f, 0.78f, 0.74f}, {0.10f, 0.16f, 0.40f}};
    // Which material a triangle of the head takes, by its centroid (metres).
    static int materialAt(const glm::vec3& centroidM);
};
bool writeAvatar(const std::string& path, std::string* error = nullptr, bool withMaps = false);

}  // namespace dermis::test
