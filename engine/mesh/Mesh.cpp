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

}  // namespace dermis
