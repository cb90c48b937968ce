#pragma once
// A character's geometry and materials as they leave a loader: one merged
// triangle mesh (node transforms already applied; with a rig, posed in its
// rest pose), its index ranges per material (submeshes), per-vertex colours,
// and what moves its vertices (anim/Rig.h; empty for a static model). An
// empty Image means the material has no such map.

#include "anim/Rig.h"
#include "core/Image.h"
#include "mesh/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

// One material of the file (glTF 2.0 §3.9), plus the grey maps a scene adds.
struct ModelMaterial {
    std::string name;                     // the glTF material's name; "" for the default material
    glm::vec4 baseColourFactor{1.0f};     // linear; multiplies the albedo map and the vertex colour
    float roughnessFactor = 1.0f;         // multiplies the metallic-roughness map's G
    Image albedoMap;                      // sRGB colour
    Image normalMap;                      // tangent space, linear, +Y up (OpenGL style), encoded as n * 0.5 + 0.5
    Image metallicRoughnessMap;           // glTF convention: G = roughness, B = metallic, linear
    Image roughnessMap;                   // the scene's roughness_map: R = Beckmann m, linear
    Image specularMap;                    // the scene's specular_map: R multiplies rho_s, linear
};

// The triangles [firstIndex, firstIndex + indexCount) of the merged mesh use `material`.
struct Submesh {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int material = 0;  // index into Model::materials
};

struct Model {
    MeshData mesh;
    std::vector<glm::vec4> colours;          // COLOR_0 per merged vertex (linear RGBA); empty = all white
    std::vector<ModelMaterial> materials{1};  // never empty
    std::vector<Submesh> submeshes;          // in index order; empty = the whole mesh uses materials[0]
    Rig rig;

    // The submeshes, or one covering the whole mesh with materials[0].
    std::vector<Submesh> drawRanges() const;
};

// Writes positions, normals and tangents (a pose of the rig, or its bind
// vertices) into the mesh's vertices, keeping their UVs; the counts match.
void setVertexFrames(MeshData& mesh, const SkinnedVertices& frames);

}  // namespace dermis
