#include "procedural/Procedural.h"
#include "procedural/ProceduralHeadShape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

using namespace dermis;

namespace {

// Generating the head takes a moment; every test shares one copy of each model.
const Model& model(const std::string& name) {
    static std::map<std::string, Model> cache;
    auto found = cache.find(name);
    if (found == cache.end()) {
        Result<Model> made = makeProceduralModel(name);
        EXPECT_TRUE(made.ok()) << name;
        found = cache.emplace(name, std::move(made).value()).first;
    }
    return found->second;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::vec3 corner(const MeshData& mesh, size_t triangle, int c) {
    return mesh.vertices[mesh.indices[3 * triangle + static_cast<size_t>(c)]].position;
}

glm::vec2 uvCorner(const MeshData& mesh, size_t triangle, int c) {
    return mesh.vertices[mesh.indices[3 * triangle + static_cast<size_t>(c)]].uv;
}

// Signed area in the (u, v) plane; negative means counter-clockwise as the
// image is seen (v runs down it), i.e. an unmirrored glTF mapping.
double uvSignedArea(const MeshData& mesh, size_t triangle) {
    const glm::dvec2 a(uvCorner(mesh, triangle, 0)), b(uvCorner(mesh, triangle, 1)), c(uvCorner(mesh, triangle, 2));
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Charts: triangles connected through shared vertex indices.
std::vector<int> chartOfTriangle(const MeshData& mesh, int* chartCount) {
    std::vector<uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        parent[find(mesh.indices[i + 1])] = find(mesh.indices[i]);
        parent[find(mesh.indices[i + 2])] = find(mesh.indices[i]);
    }
    std::map<uint32_t, int> chartOfRoot;
    std::vector<int> chart(mesh.triangleCount());
    for (size_t t = 0; t < chart.size(); ++t) {
        auto inserted = chartOfRoot.emplace(find(mesh.indices[3 * t]), static_cast<int>(chartOfRoot.size()));
        chart[t] = inserted.first->second;
    }
    *chartCount = static_cast<int>(chartOfRoot.size());
    return chart;
}

struct Crossing {
    float s = 0.0f;         // where, along the line
    bool entering = false;  // into the solid: the triangle faces against the line
};

// Where the line {origin + s * axis} crosses the mesh, ordered along it.
std::vector<Crossing> crossings(const MeshData& mesh, const glm::vec3& origin, const glm::vec3& axis) {
    std::vector<Crossing> hits;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
        const glm::vec3 e1 = b - a, e2 = c - a;
        const glm::vec3 p = glm::cross(axis, e2);
        const float det = glm::dot(e1, p);
        if (std::fabs(det) < 1e-14f) continue;
        const glm::vec3 q = origin - a;
        const float u = glm::dot(q, p) / det;
        const glm::vec3 r = glm::cross(q, e1);
        const float v = glm::dot(axis, r) / det;
        if (u < 0.0f || v < 0.0f || u + v > 1.0f) continue;
        hits.push_back({glm::dot(e2, r) / det, glm::dot(glm::cross(e1, e2), axis) < 0.0f});
    }
    std::sort(hits.begin(), hits.end(), [](const Crossing& x, const Crossing& y) { return x.s < y.s; });
    // A line through a shared edge hits both triangles: keep one.
    hits.erase(std::unique(hits.begin(), hits.end(),
                           [](const Crossing& x, const Crossing& y) {
                               return std::fabs(x.s - y.s) < 1e-6f && x.entering == y.entering;
                           }),
               hits.end());
    return hits;
}

class ProceduralMesh : public ::testing::TestWithParam<std::string> {
protected:
    const MeshData& mesh() const { return model(GetParam()).mesh; }
};

TEST_P(ProceduralMesh, HasTriangles) {
    EXPECT_GT(mesh().triangleCount(), 100u);
    EXPECT_EQ(mesh().indices.size() % 3, 0u);
}

TEST_P(ProceduralMesh, IndicesAreInRangeAndTrianglesHaveArea) {
    const MeshData& m = mesh();
    for (uint32_t index : m.indices) ASSERT_LT(index, m.vertices.size());
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const float area = 0.5f * glm::length(glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0)));
        ASSERT_GT(area, 0.0f) << "triangle " << t;
    }
}

TEST_P(ProceduralMesh, FramesAreFiniteUnitAndOrthogonal) {
    for (const Vertex& v : mesh().vertices) {
        ASSERT_TRUE(finite(v.position));
        ASSERT_TRUE(finite(v.normal));
        ASSERT_TRUE(finite(glm::vec3(v.tangent)));
        ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
        ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
        ASSERT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-4f);
        ASSERT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
    }
}

// Each triangle's winding agrees with the normals at its corners, so front
// faces point out of the solid.
TEST_P(ProceduralMesh, TrianglesWindOutward) {
    const MeshData& m = mesh();
    size_t disagreeing = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 face = glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0));
        glm::vec3 normalSum(0.0f);
        for (int c = 0; c < 3; ++c) normalSum += m.vertices[m.indices[3 * t + static_cast<size_t>(c)]].normal;
        if (glm::dot(face, normalSum) <= 0.0f) ++disagreeing;
    }
    EXPECT_EQ(disagreeing, 0u);
}

TEST_P(ProceduralMesh, UvsLieInTheUnitSquare) {
    for (const Vertex& v : mesh().vertices) {
        ASSERT_GE(v.uv.x, 0.0f);
        ASSERT_LE(v.uv.x, 1.0f);
        ASSERT_GE(v.uv.y, 0.0f);
        ASSERT_LE(v.uv.y, 1.0f);
    }
}

// Every triangle's UV image keeps the orientation it has seen from outside the
// surface, on every chart: no mirrored or folded-over triangle.
TEST_P(ProceduralMesh, UvTrianglesAreUnmirrored) {
    const MeshData& m = mesh();
    for (size_t t = 0; t < m.triangleCount(); ++t) ASSERT_LT(uvSignedArea(m, t), 0.0) << "triangle " << t;
}

// Rasterises every UV triangle at 1024^2 and counts, per texel centre, the
// triangles strictly containing it: centres on a shared edge count for none.
TEST_P(ProceduralMesh, UvTrianglesDoNotOverlap) {
    constexpr int kSize = 1024;
    const MeshData& m = mesh();
    std::vector<uint8_t> coverage(static_cast<size_t>(kSize) * kSize, 0);
    size_t overlapping = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        glm::dvec2 p[3];
        for (int c = 0; c < 3; ++c) p[c] = glm::dvec2(uvCorner(m, t, c)) * double(kSize);
        const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
        if (area == 0.0) continue;
        const int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
        const int x1 = std::min(kSize - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
        const int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
        const int y1 = std::min(kSize - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 q(x + 0.5, y + 0.5);
                bool inside = true;
                for (int e = 0; e < 3 && inside; ++e) {
                    const glm::dvec2 a = p[e], b = p[(e + 1) % 3];
                    const double edge = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / area;
                    inside = edge > 1e-9 * std::sqrt(std::fabs(area));
                }
                if (!inside) continue;
                uint8_t& count = coverage[static_cast<size_t>(y) * kSize + static_cast<size_t>(x)];
                if (++count == 2) ++overlapping;
            }
        }
    }
    EXPECT_EQ(overlapping, 0u);
    EXPECT_GT(std::count(coverage.begin(), coverage.end(), uint8_t(1)), kSize * kSize / 4);
}

// Distinct charts keep at least 4 texels (at 1024) between their bounds, so
// filtering and mip-mapping at a chart's edge never reaches another chart.
TEST_P(ProceduralMesh, ChartsAreSeparatedByGutters) {
    const MeshData& m = mesh();
    int charts = 0;
    const std::vector<int> chart = chartOfTriangle(m, &charts);
    std::vector<glm::vec2> lo(static_cast<size_t>(charts), glm::vec2(2.0f)), hi(static_cast<size_t>(charts), glm::vec2(-1.0f));
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        for (int c = 0; c < 3; ++c) {
            lo[static_cast<size_t>(chart[t])] = glm::min(lo[static_cast<size_t>(chart[t])], uvCorner(m, t, c));
            hi[static_cast<size_t>(chart[t])] = glm::max(hi[static_cast<size_t>(chart[t])], uvCorner(m, t, c));
        }
    }
    const float gutter = 4.0f / 1024.0f;
    for (size_t a = 0; a < lo.size(); ++a) {
        for (size_t b = a + 1; b < lo.size(); ++b) {
            const glm::vec2 gap = glm::max(lo[b] - hi[a], lo[a] - hi[b]);
            EXPECT_GE(std::max(gap.x, gap.y), gutter) << "charts " << a << " and " << b;
        }
    }
}

// With coincident positions welded, every edge borders exactly two triangles
// that run along it in opposite directions (closed and consistently wound),
// except, on the plane, the edges of its border.
TEST_P(ProceduralMesh, SurfaceIsClosedOrOpenOnlyAtTheBorder) {
    const MeshData& m = mesh();
    std::map<std::tuple<long, long, long>, uint32_t> weldIndex;
    std::vector<uint32_t> welded(m.vertices.size());
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const glm::vec3 p = m.vertices[i].position * 1e7f;  // 0.1 micrometre cells
        const auto key = std::make_tuple(std::lround(p.x), std::lround(p.y), std::lround(p.z));
        welded[i] = weldIndex.emplace(key, static_cast<uint32_t>(weldIndex.size())).first->second;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> directedEdges;
    std::map<std::pair<uint32_t, uint32_t>, glm::vec3> edgeMidpoint;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = m.indices[3 * t + static_cast<size_t>(c)];
            const uint32_t b = m.indices[3 * t + static_cast<size_t>((c + 1) % 3)];
            ++directedEdges[{welded[a], welded[b]}];
            edgeMidpoint[{welded[a], welded[b]}] = 0.5f * (m.vertices[a].position + m.vertices[b].position);
        }
    }
    size_t unpaired = 0;
    size_t offBorder = 0;
    for (const auto& [edge, count] : directedEdges) {
        const auto reverse = directedEdges.find({edge.second, edge.first});
        if (count == 1 && reverse != directedEdges.end() && reverse->second == 1) continue;
        ++unpaired;
        const glm::vec3 p = edgeMidpoint[edge];
        if (count != 1 || std::max(std::fabs(p.x), std::fabs(p.z)) < 0.5f - 1e-6f) ++offBorder;
    }
    if (GetParam() == "plane") {
        EXPECT_EQ(unpaired, 4u * 32u);  // 32 cells a side
        EXPECT_EQ(offBorder, 0u);
    } else {
        EXPECT_EQ(unpaired, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Procedural, ProceduralMesh, ::testing::Values("head", "plane", "sphere", "wedge"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

TEST(ProceduralModels, NamesAreTheHeadsAndTheThreeShapes) {
    EXPECT_EQ(proceduralModelNames(), (std::vector<std::string>{"head", "nodding_head", "plane", "sphere", "wedge"}));
}

TEST(ProceduralModels, UnknownNameIsAnError) {
    Result<Model> made = makeProceduralModel("teapot");
    ASSERT_FALSE(made.ok());
    EXPECT_EQ(made.error().where, "");
    EXPECT_EQ(made.error().what, "unknown procedural mesh \"teapot\" (known: head, nodding_head, plane, sphere, wedge)");
}

TEST(ProceduralModels, TestShapesHaveNoMaps) {
    for (const char* name : {"plane", "sphere", "wedge"}) {
        EXPECT_TRUE(model(name).materials[0].albedoMap.empty()) << name;
        EXPECT_TRUE(model(name).materials[0].normalMap.empty()) << name;
    }
}

TEST(ProceduralPlane, IsAMetreSquareFacingUp) {
    const MeshData& m = model("plane").mesh;
    const Bounds b = m.bounds();
    EXPECT_FLOAT_EQ(b.min.x, -0.5f);
    EXPECT_FLOAT_EQ(b.max.x, 0.5f);
    EXPECT_FLOAT_EQ(b.min.z, -0.5f);
    EXPECT_FLOAT_EQ(b.max.z, 0.5f);
    EXPECT_EQ(b.min.y, 0.0f);
    EXPECT_EQ(b.max.y, 0.0f);
    for (const Vertex& v : m.vertices) {
        EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
        EXPECT_NEAR(v.uv.x, v.position.x + 0.5f, 1e-6f);
        EXPECT_NEAR(v.uv.y, v.position.z + 0.5f, 1e-6f);
    }
}

TEST(ProceduralSphere, VerticesLieOnTheRadiusWithRadialNormals) {
    const MeshData& m = model("sphere").mesh;
    for (const Vertex& v : m.vertices) {
        ASSERT_NEAR(glm::length(v.position), 0.1f, 1e-6f);
        ASSERT_NEAR(glm::dot(v.normal, glm::normalize(v.position)), 1.0f, 1e-5f);
    }
    // u along longitude: the front (+Z) is u = 0.5, the pole v = 0 is +Y.
    for (const Vertex& v : m.vertices) {
        if (v.position.z > 0.09999f) {
            EXPECT_NEAR(v.uv.x, 0.5f, 1e-5f);
            EXPECT_NEAR(v.uv.y, 0.5f, 1e-5f);
        }
        if (v.position.y > 0.0999f) {
            EXPECT_EQ(v.uv.y, 0.0f);
        }
    }
}

TEST(ProceduralWedge, ThicknessGrowsFromOneToTwentyMillimetres) {
    const MeshData& m = model("wedge").mesh;
    const Bounds b = m.bounds();
    EXPECT_NEAR(b.min.x, 0.0f, 1e-7f);
    EXPECT_NEAR(b.max.x, 0.2f, 1e-7f);
    EXPECT_NEAR(b.size().z, 0.1f, 1e-7f);
    // Measured by lines along Y: in through the bottom, out through the top.
    // The ends are faces of their own, so the lines there run a hair inside.
    for (float x : {1e-6f, 0.0517f, 0.1233f, 0.2f - 1e-6f}) {
        for (float z : {-0.0371f, 0.0013f, 0.0213f}) {
            const std::vector<Crossing> hits = crossings(m, {x, -0.1f, z}, {0.0f, 1.0f, 0.0f});
            ASSERT_EQ(hits.size(), 2u) << "x = " << x << ", z = " << z;
            EXPECT_TRUE(hits[0].entering);
            EXPECT_FALSE(hits[1].entering);
            const float thicknessMm = 1000.0f * (hits[1].s - hits[0].s);
            EXPECT_NEAR(thicknessMm, 1.0f + 19.0f * x / 0.2f, 1e-3f) << "x = " << x;
        }
    }
}

TEST(ProceduralWedge, FacesAreFlatShaded) {
    const MeshData& m = model("wedge").mesh;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 face = glm::normalize(glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0)));
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(glm::dot(face, m.vertices[m.indices[3 * t + static_cast<size_t>(c)]].normal), 1.0f, 1e-5f);
    }
}

TEST(ProceduralHead, IsHeadSizedWithANeck) {
    const MeshData& m = model("head").mesh;
    const Bounds b = m.bounds();
    EXPECT_NEAR(b.size().x, 0.20f, 0.02f);   // ear to ear
    EXPECT_NEAR(b.size().z, 0.23f, 0.03f);   // back of the head to the tip of the nose
    EXPECT_GT(b.max.y, 0.10f);               // crown
    EXPECT_LT(b.min.y, -0.15f);              // neck stub
    EXPECT_GT(b.max.z, 0.11f);               // the nose is the foremost point
    EXPECT_GE(m.triangleCount(), 20000u);
    EXPECT_LE(m.triangleCount(), 60000u);
}

TEST(ProceduralHead, IsMirrorSymmetric) {
    const MeshData& m = model("head").mesh;
    const Bounds b = m.bounds();
    EXPECT_NEAR(b.min.x, -b.max.x, 1e-5f);
}

// Lines along X from outside, where they meet an ear standing free of the
// skull (in, out, then a gap before the skull), cross it within a few
// millimetres: the ears are thin enough to let light through.
TEST(ProceduralHead, EarsAreThin) {
    const MeshData& m = model("head").mesh;
    for (float side : {1.0f, -1.0f}) {
        // Only triangles well out on this side can be crossed near its ear.
        MeshData half;
        half.vertices = m.vertices;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            float minX = 1.0f;
            for (int c = 0; c < 3; ++c) minX = std::min(minX, side * corner(m, t, c).x);
            if (minX > 0.05f)
                for (int c = 0; c < 3; ++c) half.indices.push_back(m.indices[3 * t + static_cast<size_t>(c)]);
        }
        int freeLines = 0;
        float thickestMm = 0.0f;
        float thinnestMm = 1000.0f;
        for (float y = -0.04f; y <= 0.04f; y += 0.0041f) {
            for (float z = -0.06f; z <= 0.02f; z += 0.0041f) {
                const std::vector<Crossing> hits = crossings(half, {0.3f * side, y, z}, {-side, 0.0f, 0.0f});
                // In and out of the ear, then into the skull after a gap.
                if (hits.size() < 3 || !hits[0].entering || hits[1].entering || !hits[2].entering) continue;
                if (hits[2].s - hits[1].s < 0.002f) continue;
                ++freeLines;
                const float thicknessMm = 1000.0f * (hits[1].s - hits[0].s);
                thickestMm = std::max(thickestMm, thicknessMm);
                thinnestMm = std::min(thinnestMm, thicknessMm);
            }
        }
        EXPECT_GT(freeLines, 20) << "side " << side;
        EXPECT_LT(thickestMm, 5.0f) << "side " << side;
        EXPECT_GT(thinnestMm, 0.0f) << "side " << side;
    }
}

TEST(ProceduralHead, AlbedoMapIsVariedSrgbSkin) {
    const Image& albedo = model("head").materials[0].albedoMap;
    ASSERT_EQ(albedo.width, 1024);
    ASSERT_EQ(albedo.height, 1024);
    EXPECT_EQ(albedo.colourSpace, ColourSpace::Srgb);
    ASSERT_EQ(albedo.texels.size(), size_t(1024) * 1024);
    double sum = 0.0, sumSq = 0.0;
    for (const glm::vec4& t : albedo.texels) {
        for (int c = 0; c < 4; ++c) ASSERT_TRUE(t[c] >= 0.0f && t[c] <= 1.0f);
        EXPECT_EQ(t.w, 1.0f);
        // Skin: red above green above blue.
        ASSERT_GT(t.x, t.y);
        ASSERT_GT(t.y, t.z);
        sum += t.y;
        sumSq += double(t.y) * t.y;
    }
    const double mean = sum / double(albedo.texels.size());
    const double deviation = std::sqrt(sumSq / double(albedo.texels.size()) - mean * mean);
    EXPECT_GT(deviation, 0.01);
}

// The colour of the surface point nearest to `pointM`, read at its vertex's UV.
glm::vec3 albedoNear(const glm::vec3& pointM) {
    const Model& head = model("head");
    const Vertex* nearest = &head.mesh.vertices.front();
    for (const Vertex& v : head.mesh.vertices)
        if (glm::distance(v.position, pointM) < glm::distance(nearest->position, pointM)) nearest = &v;
    const Image& albedo = head.materials[0].albedoMap;
    glm::vec3 sum(0.0f);
    // A 5x5 average, to see the region's colour rather than its mottling.
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const int x = std::clamp(int(nearest->uv.x * float(albedo.width)) + dx, 0, albedo.width - 1);
            const int y = std::clamp(int(nearest->uv.y * float(albedo.height)) + dy, 0, albedo.height - 1);
            sum += glm::vec3(albedo.at(x, y));
        }
    }
    return sum / 25.0f;
}

float redness(const glm::vec3& c) { return c.x / std::max(c.y, 1e-3f); }

TEST(ProceduralHead, AlbedoFeaturesLandWhereTheMeshPutsThem) {
    const glm::vec3 forehead = albedoNear({0.0f, 0.07f, 0.1f});
    EXPECT_GT(redness(albedoNear(head::kCheekM)), redness(forehead) + 0.03f);
    EXPECT_GT(redness(albedoNear(head::kMouthM + glm::vec3(0.0f, 0.007f, 0.0f))), redness(forehead) + 0.1f);
    EXPECT_LT(albedoNear(head::kBrowM + glm::vec3(0.0f, 0.0f, 0.01f)).y, forehead.y - 0.05f);
}

TEST(ProceduralHead, NormalMapHoldsUnitNormalsFacingOut) {
    const Image& normals = model("head").materials[0].normalMap;
    ASSERT_EQ(normals.width, 2048);
    ASSERT_EQ(normals.height, 2048);
    EXPECT_EQ(normals.colourSpace, ColourSpace::Linear);
    ASSERT_EQ(normals.texels.size(), size_t(2048) * 2048);
    size_t tiltedOver1Deg = 0;
    size_t tiltedOver5Deg = 0;
    for (const glm::vec4& t : normals.texels) {
        const glm::vec3 n = glm::vec3(t) * 2.0f - 1.0f;
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
        ASSERT_GT(n.z, 0.0f);
        if (n.z < std::cos(glm::radians(1.0f))) ++tiltedOver1Deg;
        if (n.z < std::cos(glm::radians(5.0f))) ++tiltedOver5Deg;
    }
    // Fine creases tilt most of the skin a little, pores a few texels a lot.
    EXPECT_GT(tiltedOver1Deg, normals.texels.size() / 2);
    EXPECT_GT(tiltedOver5Deg, normals.texels.size() / 40);
}

}  // namespace
