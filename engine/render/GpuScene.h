#pragma once
// Everything of a scene that lives on the GPU: one mesh and its maps per
// character. Built once from a Scene; where the characters are this frame is
// the frame plan's (plan/FramePlan.h).

#include "core/Image.h"
#include "core/Result.h"
#include "gl/GlObjects.h"
#include "mesh/Mesh.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace dermis {

// Attribute location of the per-vertex colour (COLOR_0), a second vertex
// stream beside the Vertex buffer so the skinning pass's layout stays Vertex.
constexpr GLuint kColourLocation = 7;

struct GpuMesh {
    gl::VertexArray vertexArray;
    gl::Buffer vertexBuffer;
    gl::Buffer colourBuffer;  // vec4 per vertex, white where the file has no COLOR_0
    bool vertexColours = false;  // some vertex's colour is not white (then the G-buffer reads them)
    gl::Buffer indexBuffer;   // the full mesh's triangles, then each level of detail's
    GLsizei indexCount = 0;   // the full mesh's
    Bounds objectBounds;
};

// What the skinning pass (passes/SkinningPass.cpp) reads to write an animated
// character's GpuMesh vertex buffer: the rig's bind vertices (with their UV
// derivatives) and influences, its morph deltas, and the palette and morph
// weights it rewrites per pose; and where it writes the deformed UV
// derivatives the texture-space stretch map reads (render/TsMeshes.h).
// Buffer layouts: shaders/skinning.comp.
struct GpuRig {
    gl::Buffer source;
    gl::Buffer influences;
    gl::Buffer morphDeltas;   // a 1-float buffer when the rig has no morph targets
    gl::Buffer palette;       // dynamic
    gl::Buffer morphWeights;  // dynamic; 1 float when there are none
    gl::Buffer derivatives;   // dP/du, dP/dv per vertex (object units), written by the skinning pass
    GLsizei vertexCount = 0;
    GLsizei paletteEntries = 0;
    GLsizei morphSlots = 0;
    bool empty() const { return vertexCount == 0; }
};

// One material's maps and factors (mesh/Model.h ModelMaterial); an empty
// texture is a map it does not have.
struct GpuMaterial {
    std::string name;  // the glTF material name: Character::materials looks it up (or "#index")
    size_t index = 0;  // in Model::materials
    glm::vec4 baseColourFactor{1.0f};
    float roughnessFactor = 1.0f;
    gl::Texture albedoMap;
    gl::Texture normalMap;
    gl::Texture metallicRoughnessMap;
    gl::Texture roughnessMap;  // the scene's roughness_map; replaces the metallic-roughness map
    gl::Texture specularMap;
    float scatter = -1.0f;       // ModelMaterial::scatter (import/MaterialScattering.h); < 0: the scene material's
    float thicknessMm = 0.0f;    // ModelMaterial::thicknessMm
    gl::Texture scatterMap;      // R = s
    gl::Texture thicknessMap;    // R multiplies thicknessMm
    // LEAN maps baked from the normal map (lean/LeanBake.h), empty without
    // one: (B.x, B.y, M.xx, M.yy) RGBA16F and (M.xy, base variance) RG16F,
    // with the baked mip chain.
    gl::Texture leanMap1;
    gl::Texture leanMap2;
};

// The triangles [firstIndex, firstIndex + indexCount) of the mesh use materials[material].
struct GpuSubmesh {
    GLsizei firstIndex = 0;
    GLsizei indexCount = 0;
    size_t material = 0;

    void draw() const;  // with the vertex array bound
};

// A normal map and the LEAN maps baked from it.
struct GpuNormalMaps {
    gl::Texture normalMap;
    gl::Texture leanMap1;
    gl::Texture leanMap2;
};

// A level of detail (mesh/MeshLod.h): its triangles in the mesh's index buffer.
struct GpuLod {
    GpuSubmesh whole;                   // all of them (material unused)
    std::vector<GpuSubmesh> submeshes;  // per submesh of the full mesh, same order
    // Per material, its normal map in this level's frame (mesh/LodNormalMaps.h);
    // empty textures: the material's own. Shared by the characters that share the model.
    std::shared_ptr<std::vector<GpuNormalMaps>> normalMaps;
};

struct GpuCharacter {
    std::string name;
    GpuMesh mesh;
    GpuRig rig;  // empty for a static character
    // Shared by the characters that share a model (render/SceneLoading.h).
    std::shared_ptr<std::vector<GpuMaterial>> materials;
    std::vector<GpuSubmesh> submeshes;  // cover the whole mesh, in index order
    std::vector<GpuLod> lods;           // levels of detail 1, 2, ... (CharacterPlacement::lod)
    bool closedOutward = false;         // mesh/MeshTopology.h: no back face shows from outside it

    bool hasLeanMaps() const;  // some material has a normal map
    const GpuMaterial& material(size_t index) const { return (*materials)[index]; }
    // The triangles to draw at level of detail `lod` (0: the full mesh; past the last level, the last).
    const std::vector<GpuSubmesh>& submeshesAt(int lod) const;
    GpuSubmesh wholeMeshAt(int lod) const;
    // The level's normal maps for `material`, or null where it draws the material's own.
    const GpuNormalMaps* lodNormalMapsAt(int lod, size_t material) const;
};

class GpuScene {
public:
    // Loads every character's model (procedural or glTF) and uploads it.
    static Result<GpuScene> create(const Scene& scene);
    // Uploads models already loaded (render/SceneLoading.h), one per
    // character; characters that share a model share its materials' maps.
    static Result<GpuScene> create(const Scene& scene, const SceneModels& models);
    static Result<GpuScene> create(const Scene& scene, const std::vector<Model>& models);

    std::vector<GpuCharacter>& characters() { return mCharacters; }
    const std::vector<GpuCharacter>& characters() const { return mCharacters; }

private:
    std::vector<GpuCharacter> mCharacters;
};

// A material's maps, and the LEAN maps baked from its normal map.
Result<GpuMaterial> uploadMaterial(const ModelMaterial& material);
// A normal map, and the LEAN maps baked from it (lean/LeanBake.h).
Result<GpuNormalMaps> uploadNormalMaps(const Image& normals, const std::string& owner);

// Uploads with a full mip chain; sRGB images get an sRGB 8-bit format, data
// maps RGBA16F.
gl::Texture uploadImage(const Image& image, const std::string& label);

}  // namespace dermis
