#include "mesh/Mesh.h"
#include "mesh/Model.h"

#include <limits>

namespace dermis {

Bounds MeshData::bounds() const {
    if (vertices.empty()) return {};
    Bounds b{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    for (const Vertex& v : vertices) {
        b.min = glm::min(b.min, v.position);
        b.max = glm::max(b.max, v.position);
    }
    return b;
}

std::vector<Submesh> Model::drawRanges() const {
    if (!submeshes.empty()) return submeshes;
    return {Submesh{0, static_cast<uint32_t>(mesh.indices.size()), 0}};
}

SceneModels shareModels(std::vector<Model> models) {
    SceneModels shared;
    for (Model& model : models) shared.push_back(std::make_shared<const Model>(std::move(model)));
    return shared;
}

void setVertexFrames(MeshData& mesh, const SkinnedVertices& frames) {
    for (size_t v = 0; v < mesh.vertices.size() && v < frames.positions.size(); ++v) {
        mesh.vertices[v].position = frames.positions[v];
        mesh.vertices[v].normal = frames.normals[v];
        mesh.vertices[v].tangent = frames.tangents[v];
    }
}

}  // namespace dermis
