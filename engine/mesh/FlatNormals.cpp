#include "mesh/FlatNormals.h"

#include <cmath>

namespace dermis {

UnweldedMesh unweldWithFaceNormals(const MeshData& mesh) {
    UnweldedMesh out;
    out.mesh.name = mesh.name;
    const size_t corners = mesh.indices.size() - mesh.indices.size() % 3;
    out.mesh.vertices.reserve(corners);
    out.mesh.indices.reserve(corners);
    out.sourceVertex.reserve(corners);
    out.degenerate.reserve(corners);
    for (size_t i = 0; i < corners; i += 3) {
        const glm::vec3& a = mesh.vertices[mesh.indices[i]].position;
        const glm::vec3& b = mesh.vertices[mesh.indices[i + 1]].position;
        const glm::vec3& c = mesh.vertices[mesh.indices[i + 2]].position;
        const glm::vec3 face = glm::cross(b - a, c - a);
        const float lengthSq = glm::dot(face, face);
        const bool degenerate = !(lengthSq > 0.0f) || !std::isfinite(lengthSq);
        for (size_t k = 0; k < 3; ++k) {
            Vertex vertex = mesh.vertices[mesh.indices[i + k]];
            if (!degenerate) vertex.normal = face / std::sqrt(lengthSq);
            out.mesh.indices.push_back(static_cast<uint32_t>(out.mesh.vertices.size()));
            out.mesh.vertices.push_back(vertex);
            out.sourceVertex.push_back(mesh.indices[i + k]);
            out.degenerate.push_back(degenerate);
        }
    }
    return out;
}

}  // namespace dermis
