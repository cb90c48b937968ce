#include "mesh/Tangents.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <unordered_map>

namespace dermis {
namespace {

// Below this |sin| of the angle between a triangle's two UV edges, its UV
// mapping is treated as degenerate and the triangle adds no tangent.
constexpr float kMinUvSine = 1e-6f;
constexpr float kMinLengthSq = 1e-30f;

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit vector, or `fallback` when `v` is zero or not finite.
glm::vec3 normalizeOr(const glm::vec3& v, const glm::vec3& fallback) {
    float lengthSq = glm::dot(v, v);
    if (!(lengthSq > kMinLengthSq) || !std::isfinite(lengthSq)) return fallback;
    return v / std::sqrt(lengthSq);
}

// Interior angle at `corner` between the edges to `a` and `b`; 0 when an edge
// has no length.
float cornerAngle(const glm::vec3& corner, const glm::vec3& a, const glm::vec3& b) {
    glm::vec3 ea = a - corner;
    glm::vec3 eb = b - corner;
    float sine = glm::length(glm::cross(ea, eb));
    float cosine = glm::dot(ea, eb);
    if (!(sine > 0.0f) && !(std::fabs(cosine) > 0.0f)) return 0.0f;
    float angle = std::atan2(sine, cosine);
    return std::isfinite(angle) ? angle : 0.0f;
}

// Any unit vector orthogonal to unit `n`, chosen stably from the axis n is
// least aligned with.
glm::vec3 anyOrthogonal(const glm::vec3& n) {
    glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return normalizeOr(axis - n * glm::dot(n, axis), glm::vec3(0.0f, 1.0f, 0.0f));
}

bool validTriangle(const MeshData& mesh, size_t first) {
    size_t count = mesh.vertices.size();
    return mesh.indices[first] < count && mesh.indices[first + 1] < count && mesh.indices[first + 2] < count;
}

}  // namespace

void generateTangents(MeshData& mesh) {
    std::vector<Vertex>& vertices = mesh.vertices;
    std::vector<glm::vec3> tangentSum(vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitangentSum(vertices.size(), glm::vec3(0.0f));

    for (size_t first = 0; first + 2 < mesh.indices.size(); first += 3) {
        if (!validTriangle(mesh, first)) continue;
        const uint32_t corners[3] = {mesh.indices[first], mesh.indices[first + 1], mesh.indices[first + 2]};
        const Vertex& v0 = vertices[corners[0]];
        const Vertex& v1 = vertices[corners[1]];
        const Vertex& v2 = vertices[corners[2]];

        glm::vec3 e1 = v1.position - v0.position;
        glm::vec3 e2 = v2.position - v0.position;
        // UVs are stored with v = 0 at the image's top row (glTF), while the
        // normal map's +Y points up the image. Differentiating against
        // (1 - v) makes the bitangent point up the image, so an unmirrored
        // mapping gets w = +1, as in tangents that glTF exporters write.
        glm::vec2 d1(v1.uv.x - v0.uv.x, v0.uv.y - v1.uv.y);
        glm::vec2 d2(v2.uv.x - v0.uv.x, v0.uv.y - v2.uv.y);
        float det = d1.x * d2.y - d2.x * d1.y;
        float uvScale = std::sqrt(glm::dot(d1, d1) * glm::dot(d2, d2));
        if (!(std::fabs(det) > kMinUvSine * uvScale) || !std::isfinite(det)) continue;

        // The 1/det scale cancels on normalisation; only its sign matters.
        float sign = det > 0.0f ? 1.0f : -1.0f;
        glm::vec3 faceTangent = sign * (e1 * d2.y - e2 * d1.y);
        glm::vec3 faceBitangent = sign * (e2 * d1.x - e1 * d2.x);
        if (!isFinite(faceTangent) || !isFinite(faceBitangent)) continue;

        for (int c = 0; c < 3; ++c) {
            uint32_t index = corners[c];
            float angle = cornerAngle(vertices[index].position, vertices[corners[(c + 1) % 3]].position,
                                      vertices[corners[(c + 2) % 3]].position);
            if (!(angle > 0.0f)) continue;
            // Projecting onto the vertex's tangent plane before weighting keeps
            // triangles steep to the normal from dominating, as MikkTSpace does.
            glm::vec3 n = normalizeOr(vertices[index].normal, glm::vec3(0.0f));
            glm::vec3 t = normalizeOr(faceTangent - n * glm::dot(n, faceTangent), glm::vec3(0.0f));
            glm::vec3 b = normalizeOr(faceBitangent - n * glm::dot(n, faceBitangent), glm::vec3(0.0f));
            tangentSum[index] += angle * t;
            bitangentSum[index] += angle * b;
        }
    }

    for (size_t i = 0; i < vertices.size(); ++i) {
        Vertex& vertex = vertices[i];
        glm::vec3 n = normalizeOr(vertex.normal, glm::vec3(0.0f, 0.0f, 1.0f));
        glm::vec3 t = tangentSum[i];
        t = normalizeOr(t - n * glm::dot(n, t), glm::vec3(0.0f));
        if (glm::dot(t, t) == 0.0f) t = anyOrthogonal(n);
        float w = glm::dot(glm::cross(n, t), bitangentSum[i]) < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(t, w);
    }
}

void generateNormals(MeshData& mesh) {
    std::vector<Vertex>& vertices = mesh.vertices;

    // Vertices split only for their UVs (seams) share one position; summing
    // per position keeps the shading smooth across such seams.
    struct PositionHash {
        size_t operator()(const glm::vec3& p) const {
            std::hash<float> h;
            return h(p.x) ^ (h(p.y) * 0x9e3779b97f4a7c15ull) ^ (h(p.z) * 0xc2b2ae3d27d4eb4full);
        }
    };
    std::unordered_map<glm::vec3, uint32_t, PositionHash> groupOfPosition;
    std::vector<uint32_t> group(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        auto inserted = groupOfPosition.emplace(vertices[i].position, static_cast<uint32_t>(groupOfPosition.size()));
        group[i] = inserted.first->second;
    }

    std::vector<glm::vec3> normalSum(groupOfPosition.size(), glm::vec3(0.0f));
    for (size_t first = 0; first + 2 < mesh.indices.size(); first += 3) {
        if (!validTriangle(mesh, first)) continue;
        const uint32_t corners[3] = {mesh.indices[first], mesh.indices[first + 1], mesh.indices[first + 2]};
        const glm::vec3& p0 = vertices[corners[0]].position;
        const glm::vec3& p1 = vertices[corners[1]].position;
        const glm::vec3& p2 = vertices[corners[2]].position;
        // The unnormalised cross product is twice the area: area weighting.
        glm::vec3 areaNormal = glm::cross(p1 - p0, p2 - p0);
        if (!isFinite(areaNormal) || !(glm::dot(areaNormal, areaNormal) > 0.0f)) continue;
        for (int c = 0; c < 3; ++c) {
            float angle = cornerAngle(vertices[corners[c]].position, vertices[corners[(c + 1) % 3]].position,
                                      vertices[corners[(c + 2) % 3]].position);
            normalSum[group[corners[c]]] += angle * areaNormal;
        }
    }

    for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i].normal = normalizeOr(normalSum[group[i]], glm::vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace dermis
