#include "mesh/Tangents.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>

using namespace dermis;

namespace {

// A flat grid in the XY plane facing +Z: u grows along +X and, in the glTF
// convention, v grows downward (-Y), so the image's top row is at +Y.
MeshData makeGrid(int cells, bool mirrorU = false) {
    MeshData mesh;
    for (int y = 0; y <= cells; ++y) {
        for (int x = 0; x <= cells; ++x) {
            Vertex v;
            float fx = static_cast<float>(x) / static_cast<float>(cells);
            float fy = static_cast<float>(y) / static_cast<float>(cells);
            v.position = glm::vec3(fx, -fy, 0.0f);
            v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
            v.uv = glm::vec2(mirrorU ? 1.0f - fx : fx, fy);
            v.tangent = glm::vec4(0.0f);
            mesh.vertices.push_back(v);
        }
    }
    auto at = [cells](int x, int y) { return static_cast<uint32_t>(y * (cells + 1) + x); };
    for (int y = 0; y < cells; ++y) {
        for (int x = 0; x < cells; ++x) {
            // Counter-clockwise seen from +Z.
            mesh.indices.insert(mesh.indices.end(), {at(x, y), at(x, y + 1), at(x + 1, y + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(x, y), at(x + 1, y + 1), at(x + 1, y)});
        }
    }
    return mesh;
}

// Longitude phi turns so that u grows to the viewer's right seen from outside;
// v = 0 at the north pole (+Y), the image's top row. The seam column is
// duplicated, as any UV-mapped sphere must be.
glm::vec3 spherePoint(float phi, float theta) {
    // Exact poles: sin(pi) is not 0 in float, and the pole copies must coincide.
    if (theta <= 0.0f) return glm::vec3(0.0f, 1.0f, 0.0f);
    if (theta >= glm::pi<float>()) return glm::vec3(0.0f, -1.0f, 0.0f);
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
}

MeshData makeSphere(int slices, int stacks, bool withNormals) {
    MeshData mesh;
    for (int j = 0; j <= stacks; ++j) {
        for (int i = 0; i <= slices; ++i) {
            float u = static_cast<float>(i) / static_cast<float>(slices);
            float v = static_cast<float>(j) / static_cast<float>(stacks);
            Vertex vertex;
            vertex.position = spherePoint(u * glm::two_pi<float>(), v * glm::pi<float>());
            vertex.normal = withNormals ? vertex.position : glm::vec3(0.0f);
            vertex.uv = glm::vec2(u, v);
            mesh.vertices.push_back(vertex);
        }
    }
    auto at = [slices](int i, int j) { return static_cast<uint32_t>(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return mesh;
}

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

void expectUnitOrthogonal(const Vertex& v) {
    ASSERT_TRUE(finite(v.tangent));
    glm::vec3 t(v.tangent);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-4f);
    EXPECT_LT(std::fabs(glm::dot(t, glm::normalize(v.normal))), 1e-4f);
    EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
}

}  // namespace

TEST(Tangents, GridTangentsFollowU) {
    MeshData mesh = makeGrid(4);
    generateTangents(mesh);
    for (const Vertex& v : mesh.vertices) {
        expectUnitOrthogonal(v);
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
        // Unmirrored mapping: cross(n, t) * w points up the image (+Y).
        EXPECT_EQ(v.tangent.w, 1.0f);
        glm::vec3 bitangent = glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
        EXPECT_NEAR(bitangent.y, 1.0f, 1e-5f);
    }
}

TEST(Tangents, MirroredGridFlipsSign) {
    MeshData mesh = makeGrid(3, true);
    generateTangents(mesh);
    for (const Vertex& v : mesh.vertices) {
        expectUnitOrthogonal(v);
        EXPECT_NEAR(v.tangent.x, -1.0f, 1e-5f);  // still along +u, which now runs along -X
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST(Tangents, SphereTangentsAreUnitOrthogonalAlongU) {
    MeshData mesh = makeSphere(32, 16, true);
    generateTangents(mesh);
    const int slices = 32;
    const int stacks = 16;
    for (int j = 0; j <= stacks; ++j) {
        for (int i = 0; i <= slices; ++i) {
            const Vertex& v = mesh.vertices[static_cast<size_t>(j * (slices + 1) + i)];
            expectUnitOrthogonal(v);
            if (j == 0 || j == stacks) continue;  // dP/du vanishes at the poles
            float phi = v.uv.x * glm::two_pi<float>();
            glm::vec3 alongU(-std::sin(phi), 0.0f, -std::cos(phi));  // d spherePoint / d phi, normalised
            EXPECT_GT(glm::dot(glm::vec3(v.tangent), alongU), 0.99f) << "vertex " << i << "," << j;
            EXPECT_EQ(v.tangent.w, 1.0f);
        }
    }
}

TEST(Tangents, DegenerateTrianglesGiveFiniteTangents) {
    MeshData mesh;
    Vertex a;
    a.position = glm::vec3(1.0f, 2.0f, 3.0f);
    a.normal = glm::vec3(0.0f, 1.0f, 0.0f);
    a.uv = glm::vec2(0.5f);
    // Triangle 0: all three corners equal.
    mesh.vertices = {a, a, a};
    // Triangle 1: a real triangle whose UVs are all the same.
    Vertex b = a, c = a, d = a;
    b.position = glm::vec3(0.0f);
    c.position = glm::vec3(1.0f, 0.0f, 0.0f);
    d.position = glm::vec3(0.0f, 0.0f, -1.0f);
    mesh.vertices.insert(mesh.vertices.end(), {b, c, d});
    // Triangle 2: collinear UVs and a zero normal.
    Vertex e = b, f = c, g = d;
    e.uv = glm::vec2(0.0f);
    f.uv = glm::vec2(0.5f);
    g.uv = glm::vec2(1.0f);
    e.normal = f.normal = g.normal = glm::vec3(0.0f);
    mesh.vertices.insert(mesh.vertices.end(), {e, f, g});
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};

    generateTangents(mesh);
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vertex& v = mesh.vertices[i];
        ASSERT_TRUE(finite(v.tangent)) << "vertex " << i;
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f) << "vertex " << i;
        if (glm::length(v.normal) > 0.0f) EXPECT_LT(std::fabs(glm::dot(glm::vec3(v.tangent), v.normal)), 1e-4f);
    }
}

TEST(Tangents, OutOfRangeIndicesAreIgnored) {
    MeshData mesh = makeGrid(1);
    mesh.indices.insert(mesh.indices.end(), {0, 1, 99});
    generateTangents(mesh);
    generateNormals(mesh);
    for (const Vertex& v : mesh.vertices) expectUnitOrthogonal(v);
}

TEST(Tangents, GeneratedNormalsAreSmoothAndOutward) {
    MeshData mesh = makeSphere(24, 12, false);
    generateNormals(mesh);
    for (const Vertex& v : mesh.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        // Seam and pole vertices are duplicated; welding by position keeps them radial.
        EXPECT_GT(glm::dot(v.normal, glm::normalize(v.position)), 0.99f);
    }
    generateTangents(mesh);
    for (const Vertex& v : mesh.vertices) expectUnitOrthogonal(v);
}

TEST(Tangents, GeneratedNormalsOfFlatGridFaceTheViewer) {
    MeshData mesh = makeGrid(2);
    for (Vertex& v : mesh.vertices) v.normal = glm::vec3(0.0f);
    generateNormals(mesh);
    for (const Vertex& v : mesh.vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
}

TEST(Tangents, IsolatedAndDegenerateVerticesGetFallbackNormal) {
    MeshData mesh;
    Vertex v;
    v.normal = glm::vec3(0.0f);
    mesh.vertices = {v, v, v, v};
    mesh.vertices[3].position = glm::vec3(5.0f);  // referenced by no triangle
    mesh.indices = {0, 1, 2};                      // zero area
    generateNormals(mesh);
    for (const Vertex& out : mesh.vertices) EXPECT_EQ(out.normal, glm::vec3(0.0f, 0.0f, 1.0f));
}
