#pragma once
// A character's geometry and materials as they leave a loader: one merged
// triangle mesh (node transforms already applied; with a rig, posed in its
// rest pose), its index ranges per material (submeshes), per-vertex colours,
// and what moves its vertices (anim/Rig.h; empty for a static model). An
// empty Image means the material has no such map.

#include "anim/Rig.h"
#include "core/Image.h"
#include "core/ImageSampling.h"
#include "mesh/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
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
    // The file's samplers of its maps (the scene's own maps repeat).
    TextureWraps albedoWrap, normalWrap, metallicRoughnessWrap, scatterWrap, thicknessWrap;

    // What the file says about the surface beneath (glTF 2.0 §3.9.6 and the
    // KHR_materials_* extensions), for import/MaterialScattering.h to decide
    // whether the material scatters.
    std::string alphaMode = "OPAQUE";     // "OPAQUE", "MASK" or "BLEND"
    float diffuseTransmission = -1.0f;    // KHR_materials_diffuse_transmission's factor; < 0: the file has none
    Image diffuseTransmissionMap;         // its texture's A, moved to R (linear); decideScattering moves it to scatterMap
    float transmission = 0.0f;            // KHR_materials_transmission's factor (glass)
    float thicknessFactor = 0.0f;         // KHR_materials_volume, in the mesh's units; 0: none
    Image thicknessMap;                   // its texture's G, moved to R (linear)

    // How the material scatters, decided at load (import/MaterialScattering.h).
    // A diffusion profile name or "none" (opaque); "" until decided (a model
    // made without the loader): the scene material's profile and scatter apply.
    std::string profile;
    float scatter = 1.0f;                 // s = scatter x scatterMap's R (docs/materials.md)
    Image scatterMap;                     // R = the scattering share, linear; empty: 1
    float thicknessMm = 0.0f;             // the transmittance's thickness x thicknessMap's R; 0: from the shadow maps
    std::string scatterReason;            // why, for the load log and reports
};

// The triangles [firstIndex, firstIndex + indexCount) of the merged mesh use `material`.
struct Submesh {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int material = 0;  // index into Model::materials
};

// A coarser triangle list over the model's own vertices (mesh/MeshLod.h).
struct LodLevel {
    std::vector<uint32_t> indices;  // triangle list over the model's vertices
    std::vector<Submesh> ranges;    // one per draw range of the full mesh, same order, into `indices`
    // How far the surface moved from the full mesh's, object units: the
    // sampled Hausdorff distance between the two surfaces (mesh/MeshLod.h).
    float errorObject = 0.0f;
    // Per Model::materials entry, the material's normal map re-expressed in
    // this level's tangent frame (mesh/LodNormalMaps.h); an empty Image: the
    // material's own map (it has none, or no levels' maps were baked).
    std::vector<Image> normalMaps;
    size_t triangleCount() const { return indices.size() / 3; }
};

struct Model {
    MeshData mesh;
    std::vector<glm::vec4> colours;          // COLOR_0 per merged vertex (linear RGBA); empty = all white
    std::vector<ModelMaterial> materials{1};  // never empty
    std::vector<Submesh> submeshes;          // in index order; empty = the whole mesh uses materials[0]
    Rig rig;
    std::vector<LodLevel> lods;  // levels of detail, finest first (mesh/MeshLod.h); empty: none

    // The submeshes, or one covering the whole mesh with materials[0].
    std::vector<Submesh> drawRanges() const;
};

// One model per scene character; characters that repeat a model share it.
using SceneModels = std::vector<std::shared_ptr<const Model>>;
// Each model shared by no one else.
SceneModels shareModels(std::vector<Model> models);

// Writes positions, normals and tangents (a pose of the rig, or its bind
// vertices) into the mesh's vertices, keeping their UVs; the counts match.
void setVertexFrames(MeshData& mesh, const SkinnedVertices& frames);

}  // namespace dermis
