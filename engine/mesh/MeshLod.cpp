#include "mesh/MeshLod.h"

#include "mesh/SurfaceDistance.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace dermis {

std::vector<LodLevel> makeLodLevels(const MeshData& mesh, const std::vector<Submesh>& ranges) {
    std::vector<LodLevel> levels;
    if (mesh.triangleCount() < kMinLodTriangles || mesh.vertices.empty()) return levels;
    const float* positions = &mesh.vertices[0].position.x;
    const float scale = meshopt_simplifyScale(positions, mesh.vertices.size(), sizeof(Vertex));
    size_t previousTriangles = mesh.triangleCount();
    float share = 1.0f;
    for (int level = 0; level < kMaxLodLevels; ++level) {
        share *= kLodTriangleRatio;
        // Each level from the full mesh, so that its error is against the full mesh.
        LodLevel lod;
        for (const Submesh& range : ranges) {
            const uint32_t* source = mesh.indices.data() + range.firstIndex;
            std::vector<uint32_t> out(range.indexCount);
            const size_t target = size_t(float(range.indexCount / 3) * share) * 3;
            // A target error of 1 (the mesh's whole extent): the triangle count decides; the error is measured below.
            out.resize(meshopt_simplify(out.data(), source, range.indexCount, positions, mesh.vertices.size(), sizeof(Vertex),
                                        target, 1.0f, meshopt_SimplifyLockBorder, nullptr));
            lod.ranges.push_back({uint32_t(lod.indices.size()), uint32_t(out.size()), range.material});
            lod.indices.insert(lod.indices.end(), out.begin(), out.end());
        }
        if (lod.triangleCount() * 10 > previousTriangles * 9) break;
        const float limit = kMaxLodRelativeError * scale;
        lod.errorObject = sampledHausdorffDistance(mesh, mesh.indices, lod.indices, kLodErrorSamplesPerEdge, limit);
        if (lod.errorObject >= limit) break;
        previousTriangles = lod.triangleCount();
        levels.push_back(std::move(lod));
    }
    return levels;
}

}  // namespace dermis
