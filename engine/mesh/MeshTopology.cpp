#include "mesh/MeshTopology.h"

#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

namespace dermis {

bool isClosedOutward(const MeshData& mesh) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) return false;
    std::map<std::array<float, 3>, uint32_t> welded;
    std::vector<uint32_t> weldedOf(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const glm::vec3& p = mesh.vertices[v].position;
        weldedOf[v] = welded.emplace(std::array<float, 3>{p.x, p.y, p.z}, uint32_t(welded.size())).first->second;
    }
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
