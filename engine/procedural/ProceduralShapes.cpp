#include "procedural/ProceduralShapes.h"

#include "procedural/ProceduralGrid.h"
#include "mesh/Tangents.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

constexpr int kPlaneCells = 32;
constexpr int kSphereSlices = 64;
constexpr int kSphereStacks = 32;

// Wedge atlas: every face at one scale, separated by an 8-texel gutter at 1024.
constexpr float kWedgeUvPerM = 4.0f;
constexpr float kWedgeGutter = 8.0f / 1024.0f;
constexpr int kWedgeLengthCells = 40;
constexpr int kWedgeDepthCells = 20;
constexpr int kWedgeThicknessCells = 2;

float toFloat(int i) { return static_cast<float>(i); }

float wedgeThicknessM(float xM) {
    return 0.001f * (kWedgeThinMm + (kWedgeThickMm - kWedgeThinMm) * xM / kWedgeLengthM);
}

Vertex makeVertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
    Vertex v;
    v.position = position;
    v.normal = normal;
    v.uv = uv;
    return v;
}

}  // namespace

MeshData makePlaneMesh() {
    MeshData mesh;
    mesh.name = "plane";
    const float step = 1.0f / toFloat(kPlaneCells);
    appendGrid(mesh, kPlaneCells, kPlaneCells, [&](int column, int row) {
        const glm::vec2 uv(toFloat(column) * step, toFloat(row) * step);
        return makeVertex(glm::vec3(uv.x - 0.5f, 0.0f, uv.y - 0.5f), glm::vec3(0.0f, 1.0f, 0.0f), uv);
    });
    generateTangents(mesh);
    return mesh;
}

MeshData makeSphereMesh() {
    MeshData mesh;
    mesh.name = "sphere";
    appendGrid(mesh, kSphereSlices, kSphereStacks, [&](int column, int row) {
        const float u = toFloat(column) / toFloat(kSphereSlices);
        const float v = toFloat(row) / toFloat(kSphereStacks);
        // 0 at -Z, pi/2 at -X, pi at +Z; the seam column repeats column 0 exactly.
        const float longitude = glm::two_pi<float>() * toFloat(column % kSphereSlices) / toFloat(kSphereSlices);
        const float polar = glm::pi<float>() * v;
        // Exact poles, so that a pole's copies coincide and their slivers drop out.
        const bool pole = row == 0 || row == kSphereStacks;
        const float ring = pole ? 0.0f : std::sin(polar);
        const float height = row == 0 ? 1.0f : row == kSphereStacks ? -1.0f : std::cos(polar);
        const glm::vec3 direction(-ring * std::sin(longitude), height, -ring * std::cos(longitude));
        // A pole copy sits mid-column, under the one triangle it belongs to.
        const float poleU = std::min(1.0f, (toFloat(column) + 0.5f) / toFloat(kSphereSlices));
        return makeVertex(kSphereRadiusM * direction, direction, glm::vec2(pole ? poleU : u, v));
    });
    generateTangents(mesh);
    return mesh;
}

MeshData makeWedgeMesh() {
    MeshData mesh;
    mesh.name = "wedge";
    const float length = kWedgeLengthM;
    const float halfDepth = 0.5f * kWedgeDepthM;
    const float slope = 0.5f * (wedgeThicknessM(length) - wedgeThicknessM(0.0f)) / length;  // of each face
    const float s = kWedgeUvPerM;
    const float g = kWedgeGutter;
    const float maxThickness = wedgeThicknessM(length);
    const auto fraction = [](int i, int n) { return toFloat(i) / toFloat(n); };

    // Top, +Y side: u along +X, v along +Z.
    const glm::vec3 topNormal = glm::normalize(glm::vec3(-slope, 1.0f, 0.0f));
    appendGrid(mesh, kWedgeLengthCells, kWedgeDepthCells, [&](int column, int row) {
        const float x = length * fraction(column, kWedgeLengthCells);
        const float z = halfDepth * (2.0f * fraction(row, kWedgeDepthCells) - 1.0f);
        return makeVertex({x, 0.5f * wedgeThicknessM(x), z}, topNormal, {g + s * x, g + s * (z + halfDepth)});
    });
    // Bottom, -Y side: u along +X, v along -Z.
    const float bottomV = 2.0f * g + s * kWedgeDepthM;
    const glm::vec3 bottomNormal = glm::normalize(glm::vec3(-slope, -1.0f, 0.0f));
    appendGrid(mesh, kWedgeLengthCells, kWedgeDepthCells, [&](int column, int row) {
        const float x = length * fraction(column, kWedgeLengthCells);
        // Written as the top's z of the mirrored row, so shared edges match exactly.
        const float z = halfDepth * (2.0f * fraction(kWedgeDepthCells - row, kWedgeDepthCells) - 1.0f);
        return makeVertex({x, -0.5f * wedgeThicknessM(x), z}, bottomNormal,
                          {g + s * x, bottomV + s * (halfDepth - z)});
    });
    // Sides, +Z then -Z: u along the length seen from outside, v down.
    for (int side = 0; side < 2; ++side) {
        const float sign = side == 0 ? 1.0f : -1.0f;
        const float centreV = 3.0f * g + 2.0f * s * kWedgeDepthM + toFloat(side) * (g + s * maxThickness) +
                              0.5f * s * maxThickness;
        appendGrid(mesh, kWedgeLengthCells, kWedgeThicknessCells, [&](int column, int row) {
            const float along = length * fraction(column, kWedgeLengthCells);
            const float x = length * fraction(side == 0 ? column : kWedgeLengthCells - column, kWedgeLengthCells);
            const float y = 0.5f * wedgeThicknessM(x) * (1.0f - 2.0f * fraction(row, kWedgeThicknessCells));
            return makeVertex({x, y, sign * halfDepth}, {0.0f, 0.0f, sign}, {g + s * along, centreV - s * y});
        });
    }
    // Ends, x = 0.2 m then x = 0: turned a quarter so they fit beside the top
    // and bottom; u along the thickness, v along z.
    const float capU = 2.0f * g + s * length;
    for (int end = 0; end < 2; ++end) {
        const float x = end == 0 ? length : 0.0f;
        const float thickness = wedgeThicknessM(x);
        const float sign = end == 0 ? 1.0f : -1.0f;
        const float u0 = end == 0 ? capU : capU + g + s * maxThickness;
        appendGrid(mesh, kWedgeThicknessCells, kWedgeDepthCells, [&](int column, int row) {
            // x = 0.2: u runs down (-Y); x = 0: u runs up (+Y); both keep the
            // texture unmirrored from outside.
            const float across = thickness * fraction(column, kWedgeThicknessCells);
            const float y = sign * (0.5f * thickness - across);
            const float z = halfDepth * (2.0f * fraction(row, kWedgeDepthCells) - 1.0f);
            return makeVertex({x, y, z}, {sign, 0.0f, 0.0f}, {u0 + s * across, g + s * (z + halfDepth)});
        });
    }
    generateTangents(mesh);
    return mesh;
}

}  // namespace dermis
