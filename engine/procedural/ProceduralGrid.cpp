#include "procedural/ProceduralGrid.h"

namespace dermis {

void appendGrid(MeshData& mesh, int columns, int rows, const std::function<Vertex(int column, int row)>& vertexAt) {
    const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
    for (int row = 0; row <= rows; ++row)
        for (int column = 0; column <= columns; ++column) mesh.vertices.push_back(vertexAt(column, row));

    const auto index = [&](int column, int row) {
        return first + static_cast<uint32_t>(row * (columns + 1) + column);
    };
    const auto addTriangle = [&](uint32_t a, uint32_t b, uint32_t c) {
        const glm::vec3& pa = mesh.vertices[a].position;
        const glm::vec3& pb = mesh.vertices[b].position;
        const glm::vec3& pc = mesh.vertices[c].position;
        if (pa == pb || pb == pc || pc == pa) return;
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    };
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const uint32_t i00 = index(column, row);
            const uint32_t i10 = index(column + 1, row);
            const uint32_t i01 = index(column, row + 1);
            const uint32_t i11 = index(column + 1, row + 1);
            addTriangle(i00, i01, i11);
            addTriangle(i00, i11, i10);
        }
    }
}

}  // namespace dermis
