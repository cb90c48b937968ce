#include "procedural/ProceduralHead.h"

#include "mesh/UvBake.h"
#include "procedural/ProceduralEar.h"
#include "procedural/ProceduralGrid.h"
#include "procedural/ProceduralHeadShape.h"
#include "mesh/Tangents.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

using glm::vec2;
using glm::vec3;

constexpr int kSkullColumns = 192;  // around
constexpr int kSkullRows = 128;     // top to neck
// Columns crowd toward the face: their density there is 1 / (1 - crowding)
// times the mean, and 1 / (1 + crowding) at the back.
constexpr float kFaceCrowding = 0.45f;

// The atlas: the skull across the top, the four ear faces in a strip below.
constexpr float kGutter = 8.0f / 1024.0f;
constexpr float kSkullBottomV = 0.785f;
constexpr float kEarUvPerM = 3.2f;

constexpr float kRayStartM = 0.32f;  // beyond every part of the head

// Distance along the ray from the origin to the outermost surface crossing.
float traceRadius(const vec3& direction) {
    float outside = kRayStartM;
    float r = kRayStartM;
    for (int step = 0; step < 1000 && r > 0.0f; ++step) {
        const float d = headSignedDistance(r * direction);
        if (d < 0.0f) break;
        outside = r;
        // The field is only near a distance, so step by half of it.
        r -= std::max(0.5f * d, 1e-4f);
    }
    float inside = std::max(r, 0.0f);
    for (int i = 0; i < 32; ++i) {
        const float mid = 0.5f * (inside + outside);
        (headSignedDistance(mid * direction) < 0.0f ? inside : outside) = mid;
    }
    return 0.5f * (inside + outside);
}

// The ray direction for a skull grid vertex: longitude from the back (-Z)
// through -X to the face (+Z), so that u grows to the right seen from outside.
vec3 skullDirection(int column, int row) {
    // The seam column repeats column 0's direction exactly.
    const float turn = static_cast<float>(column % kSkullColumns) / kSkullColumns;
    const float longitude = glm::two_pi<float>() * turn + kFaceCrowding * std::sin(glm::two_pi<float>() * turn);
    const float polar = glm::pi<float>() * static_cast<float>(row) / kSkullRows;
    // Exact poles, so that a pole's copies coincide and their slivers drop out.
    const bool pole = row == 0 || row == kSkullRows;
    const float ring = pole ? 0.0f : std::sin(polar);
    const float height = row == 0 ? 1.0f : row == kSkullRows ? -1.0f : std::cos(polar);
    return vec3(-ring * std::sin(longitude), height, -ring * std::cos(longitude));
}

void appendSkull(MeshData& mesh) {
    // Trace every vertex first, in parallel: it is most of the mesh's cost.
    constexpr int kStride = kSkullColumns + 1;
    std::vector<Vertex> traced(static_cast<size_t>(kStride) * (kSkullRows + 1));
    forEachRow(kSkullRows + 1, [&](int row) {
        for (int column = 0; column <= kSkullColumns; ++column) {
            const vec3 direction = skullDirection(column, row);
            Vertex& v = traced[static_cast<size_t>(row) * kStride + static_cast<size_t>(column)];
            v.position = traceRadius(direction) * direction;
            v.normal = headSurfaceNormal(v.position);
        }
    });

    const vec2 uvMin(kGutter, kGutter);
    const vec2 uvSize(1.0f - 2.0f * kGutter, kSkullBottomV - kGutter);
    appendGrid(mesh, kSkullColumns, kSkullRows, [&](int column, int row) {
        Vertex v = traced[static_cast<size_t>(row) * kStride + static_cast<size_t>(column)];
        const bool pole = row == 0 || row == kSkullRows;
        // A pole copy sits mid-column, under the one triangle it belongs to.
        const float s = (static_cast<float>(column) + (pole ? 0.5f : 0.0f)) / kSkullColumns;
        v.uv = uvMin + uvSize * vec2(std::min(s, 1.0f), static_cast<float>(row) / kSkullRows);
        return v;
    });
}

}  // namespace

HeadMesh makeHeadMesh() {
    HeadMesh head;
    head.mesh.name = "head";
    appendSkull(head.mesh);
    head.skullTriangleCount = head.mesh.triangleCount();

    const vec2 chartSize = kEarUvPerM * earChartSizeM();
    const float earV = kSkullBottomV + kGutter;
    vec2 corner(kGutter, earV);
    vec2 charts[4];
    for (vec2& chart : charts) {
        chart = corner;
        corner.x += chartSize.x + kGutter;
    }
    appendEar(head.mesh, 1.0f, charts[0], charts[1], kEarUvPerM);
    appendEar(head.mesh, -1.0f, charts[2], charts[3], kEarUvPerM);

    generateTangents(head.mesh);
    return head;
}

}  // namespace dermis
