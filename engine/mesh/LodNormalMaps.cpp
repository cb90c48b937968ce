#include "mesh/LodNormalMaps.h"

#include "mesh/UvBake.h"

#include <cmath>

namespace dermis {
namespace {

// The triangles of `ranges` that use `material`, over the mesh's vertices
// (their v flipped when the character samples at 1 - v).
MeshData trianglesOf(const MeshData& mesh, const std::vector<uint32_t>& indices, const std::vector<Submesh>& ranges,
                     int material, bool flipV) {
    MeshData out;
    out.vertices = mesh.vertices;
    if (flipV)
        for (Vertex& vertex : out.vertices) vertex.uv.y = 1.0f - vertex.uv.y;
    for (const Submesh& range : ranges) {
        if (range.material != material) continue;
        out.indices.insert(out.indices.end(), indices.begin() + range.firstIndex,
                           indices.begin() + range.firstIndex + range.indexCount);
    }
    return out;
}

glm::vec3 decodeNormal(const glm::vec4& texel) { return glm::vec3(texel) * 2.0f - 1.0f; }

}  // namespace

Image bakeLodNormalMap(const MeshData& mesh, const std::vector<Submesh>& fullRanges, const LodLevel& level, int material,
                       const Image& normalMap, bool flipV) {
    if (normalMap.empty()) return {};
    const MeshData full = trianglesOf(mesh, mesh.indices, fullRanges, material, flipV);
    const MeshData coarse = trianglesOf(mesh, level.indices, level.ranges, material, flipV);
    if (full.indices.empty() || coarse.indices.empty()) return {};
    const int w = normalMap.width;
    const int h = normalMap.height;
    const SurfaceMap fullSurface = rasteriseSurface(full, {}, w, h);
    const SurfaceMap coarseSurface = rasteriseSurface(coarse, {}, w, h);

    // Texels no level triangle covers are marked with a value no unit normal
    // encodes, then given the material's own after the gutter is grown.
    const glm::vec4 unset(-1.0f);
    Image baked = normalMap;
    forEachRow(h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const SurfaceTexel& at = coarseSurface.texels[i];
            if (!at.covered) {
                baked.texels[i] = unset;
                continue;
            }
            const glm::vec3 tangentNormal = decodeNormal(normalMap.texels[i]);
            const SurfaceTexel& fine = fullSurface.texels[i];
            // The full mesh's shading normal as gbuffer.frag makes it: its frame
            // (T, B, N) times the map's normal; where the full mesh does not reach
            // this texel (a level's chart may stray past it by a little), the
            // level's own.
            glm::vec3 shading = fine.covered ? fine.tangent * tangentNormal.x + fine.bitangent * tangentNormal.y +
                                                   fine.normal * tangentNormal.z
                                             : at.tangent * tangentNormal.x + at.bitangent * tangentNormal.y +
                                                   at.normal * tangentNormal.z;
            const float length = glm::length(shading);
            shading = length > 0.0f ? shading / length : at.normal;
            const glm::vec3 inLevel(glm::dot(at.tangent, shading), glm::dot(at.bitangent, shading), glm::dot(at.normal, shading));
            baked.texels[i] = glm::vec4(inLevel * 0.5f + 0.5f, normalMap.texels[i].w);
        }
    });
    fillGutters(baked, coarseSurface, kLodNormalGutterRings, unset, true);
    for (size_t i = 0; i < baked.texels.size(); ++i)
        if (baked.texels[i] == unset) baked.texels[i] = normalMap.texels[i];
    return baked;
}

void bakeLodNormalMaps(Model& model, bool flipV) {
    const std::vector<Submesh> ranges = model.drawRanges();
    for (LodLevel& level : model.lods) {
        level.normalMaps.clear();
        for (size_t m = 0; m < model.materials.size(); ++m)
            level.normalMaps.push_back(
                bakeLodNormalMap(model.mesh, ranges, level, int(m), model.materials[m].normalMap, flipV));
    }
}

}  // namespace dermis
