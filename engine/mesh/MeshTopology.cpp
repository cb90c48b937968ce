#include "mesh/MeshTopology.h"

#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

namespace dermis {

WeldedPoints weldByPosition(const std::vector<glm::vec3>& points) {
    std::map<std::array<float, 3>, uint32_t> welded;
    WeldedPoints out;
    out.ids.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec3& p = points[i];
        out.ids[i] = welded.emplace(std::array<float, 3>{p.x, p.y, p.z}, uint32_t(welded.size())).first->second;
    }
    out.count = welded.size();
    return out;
}

bool isClosedOutward(const MeshData& mesh) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) return false;
    std::vector<glm::vec3> positions;
    positions.reserve(mesh.vertices.size());
    for (const Vertex& v : mesh.vertices) positions.push_back(v.position);
    const std::vector<uint32_t> weldedOf = weldByPosition(positions).ids;
    std::unordered_map<uint64_t, int> directedEdges;
    double sixVolume = 0.0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        uint32_t ids[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = mesh.indices[t + size_t(k)];
            if (index >= mesh.vertices.size()) return false;
            ids[k] = weldedOf[index];
        }
        if (ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0]) continue;  // no area, never drawn
        for (int k = 0; k < 3; ++k) ++directedEdges[(uint64_t(ids[k]) << 32) | ids[(k + 1) % 3]];
        const glm::dvec3 a = mesh.vertices[mesh.indices[t]].position;
        const glm::dvec3 b = mesh.vertices[mesh.indices[t + 1]].position;
        const glm::dvec3 c = mesh.vertices[mesh.indices[t + 2]].position;
        sixVolume += glm::dot(a, glm::cross(b, c));
    }
    if (directedEdges.empty()) return false;
    for (const auto& [edge, count] : directedEdges) {
        if (count != 1) return false;
        const uint64_t reverse = (edge << 32) | (edge >> 32);
        const auto found = directedEdges.find(reverse);
        if (found == directedEdges.end() || found->second != 1) return false;
    }
    return sixVolume > 0.0;
}

}  // namespace dermis
