#pragma once
// One character's surface in world space (metres) with its materials, as the
// G-buffer pass sees it (shaders/gbuffer.vert, gbuffer.frag): per triangle
// its model material; albedo = the scene material's albedo x baseColorFactor
// x albedo map (decoded to linear) x COLOR_0, clamped to [0, 1]; the
// scattering share s = scatter x the scatter map's R (docs/materials.md); the interpolated normal,
// flipped on back faces and perturbed by the tangent-space normal map. Maps are
// read from mip pyramids: trilinearly at a pixel's footprint for the points a
// camera sees, bilinearly at level 0 for the integral's samples.

#include "core/ContentHash.h"
#include "core/Result.h"
#include "mesh/Model.h"
#include "reference/MipPyramid.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dermis::reference {

struct SurfacePoint {
    glm::vec3 positionM{0.0f};
    glm::vec3 geometricNormal{0.0f, 0.0f, 1.0f};  // unit; the counter-clockwise side is the front
    glm::vec3 shadingNormal{0.0f, 0.0f, 1.0f};    // unit
    // Rays towards the lights and the environment leave from positionM + rayLiftM:
    // lifted onto the smooth surface that the vertex normals describe (Hanika
    // 2021), so that a coarse mesh's flat triangles do not shadow themselves
    // where the interpolated normal still faces the light (the shadow terminator).
    glm::vec3 rayLiftM{0.0f};
    glm::vec3 smoothNormal{0.0f, 0.0f, 1.0f};  // unit: the interpolated normal, before the normal map
    // The point's triangle among all the triangles that rays are traced against
    // (the scene's, in the renderer's order): its own facets do not shadow it
    // near the terminator (ReferenceLighting.cpp). kNoTracedTriangle for a point
    // made by hand: every triangle may shadow it.
    static constexpr uint32_t kNoTracedTriangle = 0xFFFFFFFFu;
    uint32_t tracedTriangle = kNoTracedTriangle;
    glm::vec3 albedo{0.0f};                        // linear
    float roughness = 0.3f;
    float rhoS = 0.0f;
    float scatter = 1.0f;   // the share s that scatters (import/MaterialScattering.h)
};

// What scatters beneath one model material: its diffusion profile (scene or
// built-in name; "none" = opaque) and the material's width_scale.
struct SurfaceScattering {
    std::string profile;
    float widthScale = 1.0f;
};

class CharacterSurface {
public:
    // Takes the model in object units and places it with the character's transform.
    // `firstTracedTriangle`: where its triangles start among those rays are traced
    // against (0 when it is traced alone).
    static Result<CharacterSurface> create(const Character& character, Model model, uint32_t firstTracedTriangle = 0);

    const std::string& name() const { return mName; }
    size_t triangleCount() const { return mIndices.size() / 3; }
    glm::vec3 corner(size_t triangle, int which) const { return mPositionsM[mIndices[3 * triangle + size_t(which)]]; }
    // The point at barycentric weights (b1, b2) of the triangle's second and third
    // corners. `backFacing` flips the normal before the normal map, as gl_FrontFacing does.
    // With a footprint, maps are read trilinearly at its level of detail; without, at level 0.
    SurfacePoint pointAt(size_t triangle, float b1, float b2, bool backFacing = false,
                         const MapFootprint* footprint = nullptr) const;
    glm::vec3 positionAt(size_t triangle, float b1, float b2) const;
    // The maps' UV (flip_v applied) at (b1, b2); any point of the triangle's plane
    // extends the weights linearly (for footprints reaching past the triangle).
    glm::vec2 mapUvAt(size_t triangle, float b1, float b2) const;
    glm::vec2 mapUvAtPlanePoint(size_t triangle, const glm::vec3& pointM) const;
    // The mesh's own TEXCOORD_0 (before flip_v) at (b1, b2): the layout of the
    // engine's texture-space irradiance.
    glm::vec2 rawUvAt(size_t triangle, float b1, float b2) const;
    double areaM2() const;
    // The model material of a triangle, and how each material scatters.
    uint32_t materialOf(size_t triangle) const { return mTriangleMaterials[triangle]; }
    size_t materialCount() const { return mMaterials.size(); }
    const SurfaceScattering& scattering(size_t material) const { return mMaterials[material].scattering; }
    // Everything above reads, into `hash` (the reference images' disk cache key):
    // a member added below must be added there too.
    void hashContent(ContentHash& hash) const;

private:
    // Hanika 2021's point: `pointM` (weights of the three corners) lifted to the
    // corners' tangent planes where it lies below them.
    glm::vec3 smoothSurfacePoint(const glm::vec3& pointM, const glm::vec3& weights, const glm::uvec3& corners,
                                 bool backFacing) const;

    std::string mName;
    uint32_t mFirstTracedTriangle = 0;
    std::vector<glm::vec3> mPositionsM;
    std::vector<glm::vec3> mNormals;   // normal matrix applied, not normalised (interpolated first, as on the GPU)
    std::vector<glm::vec4> mTangents;  // xyz world tangent, w bitangent sign
    std::vector<glm::vec2> mUvs;       // flipV already applied
    std::vector<glm::vec2> mRawUvs;    // as the mesh gives them
    std::vector<glm::vec3> mColours;   // COLOR_0; empty: white
    std::vector<uint32_t> mIndices;
    struct SurfaceMaterial {
        MipPyramid albedoMap;   // linear; empty: none
        MipPyramid normalMap;   // empty: none
        MipPyramid scatterMap;  // R multiplies scatter; empty: none
        glm::vec3 albedoTint{1.0f};
        float roughness = 0.3f;
        float rhoS = 0.0f;
        float scatter = 1.0f;
        SurfaceScattering scattering;
    };
    std::vector<SurfaceMaterial> mMaterials;   // Model::materials' order
    std::vector<uint32_t> mTriangleMaterials;  // per triangle
};

}  // namespace dermis::reference
