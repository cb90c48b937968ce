// The UV-layout analysis texture-space SSS draws with: stretch (position
// derivatives) against the UV sphere's closed form, finiteness on degenerate
// triangles, and distances to chart borders.
#include "procedural/Procedural.h"
#include "procedural/ProceduralHead.h"
#include "procedural/ProceduralShapes.h"
#include "mesh/UvLayout.h"
#include "plan/SceneGeometry.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dermis;

namespace {

MeshData proceduralMesh(const std::string& name) {
    auto model = makeProceduralModel(name);
    EXPECT_TRUE(model.ok());
    return model.ok() ? model->mesh : MeshData{};
}

}  // namespace

TEST(UvLayout, SphereStretchMatchesTheClosedFormAwayFromThePoles) {
    // u = longitude / 2 pi, v = polar angle / pi on a sphere of radius r:
    // |dP/du| = 2 pi r sin(theta), |dP/dv| = pi r.
    const MeshData sphere = proceduralMesh("sphere");
    const UvLayout layout = analyseUvLayout(sphere, 1.0f);
    ASSERT_EQ(layout.dPdu.size(), sphere.vertices.size());
    const double r = kSphereRadiusM;
    double worstInside = 0.0;  // away from the seam: averaged over triangles on every side
    double worstSeam = 0.0;    // on the seam: one-sided, first-order error dtheta/3 cot(theta)
    double worstV = 0.0;
    int checked = 0;
    for (size_t i = 0; i < sphere.vertices.size(); ++i) {
        const glm::vec2 uv = sphere.vertices[i].uv;
        const double theta = glm::pi<double>() * uv.y;
        if (theta < glm::radians(35.0) || theta > glm::radians(145.0)) continue;
        const double errorU = std::abs(glm::length(layout.dPdu[i]) / (2.0 * glm::pi<double>() * r * std::sin(theta)) - 1.0);
        const bool seam = uv.x == 0.0f || uv.x == 1.0f;
        (seam ? worstSeam : worstInside) = std::max(seam ? worstSeam : worstInside, errorU);
        worstV = std::max(worstV, std::abs(glm::length(layout.dPdv[i]) / (glm::pi<double>() * r) - 1.0));
        ++checked;
    }
    std::printf("sphere vertices 35..145 deg: worst |dP/du| error %.3f%% (seam %.3f%%), |dP/dv| %.3f%%\n",
                100 * worstInside, 100 * worstSeam, 100 * worstV);
    EXPECT_GT(checked, 1000);
    EXPECT_LT(worstInside, 0.01);
    EXPECT_LT(worstSeam, 0.05);
    EXPECT_LT(worstV, 0.01);
    // Vertices are spread evenly in theta, so the median of sin(theta) is sin(45 deg).
    const double median = glm::pi<double>() * r * std::sqrt(2.0 * std::sin(glm::quarter_pi<double>()));
    EXPECT_NEAR(layout.medianStretch, median, 0.03 * median);
    // Denser than typical, but not ruled by the poles: at least as long as the
    // first ring's chord (the pole vertices take that of their one triangle).
    const double firstRing = glm::pi<double>() * r * std::sqrt(2.0 * std::sin(glm::pi<double>() / 32.0));
    EXPECT_LT(layout.denseStretch, layout.medianStretch);
    EXPECT_GT(layout.denseStretch, 0.99 * firstRing);
}

TEST(UvLayout, DegenerateTrianglesGiveFiniteValues) {
    MeshData mesh;
    auto vertex = [](glm::vec3 p, glm::vec2 uv) {
        Vertex v;
        v.position = p;
        v.uv = uv;
        return v;
    };
    mesh.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {1, 0}), vertex({0, 1, 0}, {0, 1}),
                     // no area in space (collinear), some in UV
                     vertex({2, 0, 0}, {2, 0}), vertex({3, 0, 0}, {3, 1}), vertex({4, 0, 0}, {2.5f, 2}),
                     // no area in UV, some in space
                     vertex({0, 0, 5}, {5, 5}), vertex({1, 0, 5}, {5, 5}), vertex({0, 1, 5}, {5, 5}),
                     // a sliver in UV
                     vertex({0, 0, 9}, {7, 7}), vertex({1, 0, 9}, {7.0001f, 7}), vertex({0, 1, 9}, {7, 7.0000001f})};
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
    const UvLayout layout = analyseUvLayout(mesh, 1.0f);
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(layout.dPdu[i][c])) << i;
            EXPECT_TRUE(std::isfinite(layout.dPdv[i][c])) << i;
        }
        EXPECT_TRUE(std::isfinite(layout.borderDistance[i])) << i;
    }
    EXPECT_FLOAT_EQ(glm::length(layout.dPdu[0]), 1.0f);
    EXPECT_EQ(glm::length(layout.dPdu[3]), 0.0f);  // only in a degenerate triangle
    EXPECT_EQ(glm::length(layout.dPdu[6]), 0.0f);
    EXPECT_TRUE(std::isfinite(layout.medianStretch));
}

TEST(UvLayout, PlaneBorderDistanceIsTheDistanceToItsNearestEdge) {
    // The plane is one chart, 1 m square, centred at the origin in XZ.
    const MeshData plane = proceduralMesh("plane");
    const UvLayout layout = analyseUvLayout(plane, 1.0f);
    for (size_t i = 0; i < plane.vertices.size(); ++i) {
        const glm::vec3 p = plane.vertices[i].position;
        const float expected = std::min({p.x + 0.5f, 0.5f - p.x, p.z + 0.5f, 0.5f - p.z});
        ASSERT_NEAR(layout.borderDistance[i], expected, 1e-4f) << "vertex " << i;
    }
}

TEST(UvLayout, SphereSeamAndPolesAreChartBorders) {
    const MeshData sphere = proceduralMesh("sphere");
    const UvLayout layout = analyseUvLayout(sphere, 1.0f);
    float equatorFarSide = -1.0f;
    for (size_t i = 0; i < sphere.vertices.size(); ++i) {
        const glm::vec2 uv = sphere.vertices[i].uv;
        const bool pole = uv.y == 0.0f || uv.y == 1.0f;  // some pole copies are used by no triangle
        if (!pole && (uv.x == 0.0f || uv.x == 1.0f)) EXPECT_EQ(layout.borderDistance[i], 0.0f) << "seam vertex " << i;
        if (std::abs(uv.x - 0.5f) < 1e-4f && std::abs(uv.y - 0.5f) < 1e-4f) equatorFarSide = layout.borderDistance[i];
    }
    // Opposite the seam on the equator, the nearest border is the ring next to
    // a pole (the zigzag of pole triangles), a quarter meridian minus one row away.
    const float expected = kSphereRadiusM * (glm::half_pi<float>() - glm::pi<float>() / 32.0f);
    EXPECT_NEAR(equatorFarSide, expected, 0.02f * expected);
}

// The share of the surface on triangles without UV area, against areas
// worked out by hand.
TEST(UvLayout, UvlessSurfaceFractionIsTheAreaShareOfTrianglesWithoutUvArea) {
    EXPECT_EQ(analyseUvLayout(proceduralMesh("sphere"), 1.0f).uvlessSurfaceFraction, 0.0f);

    MeshData bare = proceduralMesh("sphere");
    for (Vertex& v : bare.vertices) v.uv = glm::vec2(0.0f);  // as a glTF without TEXCOORD_0 loads
    EXPECT_EQ(analyseUvLayout(bare, 1.0f).uvlessSurfaceFraction, 1.0f);

    // Two triangles in space, areas 1/2 and 3/2 (units^2): the second is
    // collapsed to a line in UV, so 3/4 of the surface has no UV area. A third
    // triangle degenerate in space (a repeated corner) counts for neither.
    MeshData mesh;
    const auto vertex = [](glm::vec3 p, glm::vec2 uv) {
        Vertex v;
        v.position = p;
        v.uv = uv;
        return v;
    };
    mesh.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {1, 0}), vertex({0, 1, 0}, {0, 1}),
                     vertex({0, 0, 1}, {0.5f, 0.5f}), vertex({3, 0, 1}, {0.5f, 0.5f}), vertex({0, 1, 1}, {0.7f, 0.7f}),
                     vertex({5, 5, 5}, {0.1f, 0.9f})};
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 6, 0};
    EXPECT_NEAR(analyseUvLayout(mesh, 1.0f).uvlessSurfaceFraction, 0.75f, 1e-6f);
}

namespace {

MeshData uvTriangles(const std::vector<glm::vec2>& uvs) {
    MeshData mesh;
    for (size_t i = 0; i < uvs.size(); ++i) {
        Vertex v;
        v.position = glm::vec3(float(i % 3 == 1), float(i % 3 == 2), float(i / 3));  // any non-degenerate triangle
        v.uv = uvs[i];
        mesh.vertices.push_back(v);
        mesh.indices.push_back(uint32_t(i));
    }
    return mesh;
}

}  // namespace

// The share of covered texels covered twice, against layouts worked out by
// hand: shared edges count once (a half-open test), a mirrored chart twice.
TEST(UvLayout, OverlapFractionCountsTexelsCoveredTwice) {
    // The unit square as two triangles sharing the diagonal: no overlap.
    const MeshData square = uvTriangles({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
    EXPECT_EQ(analyseUvLayout(square, 1.0f).uvOverlapFraction, 0.0f);
    // The left half twice (a mirrored chart) beside a right half once: half
    // of the covered texels are covered twice.
    const MeshData mirrored = uvTriangles({{0, 0}, {0.5f, 0}, {0.5f, 1}, {0, 0}, {0.5f, 1}, {0, 1},  //
                                           {0, 0}, {0.5f, 1}, {0.5f, 0}, {0, 0}, {0, 1}, {0.5f, 1},  // wound the other way
                                           {0.5f, 0}, {1, 0}, {1, 1}, {0.5f, 0}, {1, 1}, {0.5f, 1}});
    EXPECT_NEAR(analyseUvLayout(mirrored, 1.0f).uvOverlapFraction, 0.5f, 1e-6f);
    // Outside the unit square nothing is covered (the irradiance texture clips it).
    EXPECT_EQ(analyseUvLayout(uvTriangles({{1.5f, 1.5f}, {2, 1.5f}, {2, 2}, {1.5f, 1.5f}, {2, 1.5f}, {2, 2}}), 1.0f)
                  .uvOverlapFraction,
              0.0f);
    // The UV sphere's quads tile the square.
    const float sphere = analyseUvLayout(proceduralMesh("sphere"), 1.0f).uvOverlapFraction;
    const float head = analyseUvLayout(proceduralMesh("head"), 1.0f).uvOverlapFraction;
    std::printf("[ measured ] UV overlap: sphere %.4f%%, procedural head %.4f%%\n", 100.0 * sphere, 100.0 * head);
    EXPECT_EQ(sphere, 0.0f);
}

namespace {

// Two square sheets, 1 x 4 object units, each a chart of its own, that meet
// along the y axis (the hinge, a seam: its vertices are split, one copy per
// chart). Sheet A lies along +x with normal +z; sheet B is A's mirror image
// continuing along -x, then folded about the hinge by `foldRad` (0: flat,
// pi: folded back onto A, as the two faces of an ear meet at its rim). Every
// vertex carries its sheet's exact normal. `lengthB` scales sheet B along
// its length (1: as long as A).
constexpr int kSheetColumns = 4;  // along x, 0.25 apart
constexpr int kSheetRows = 8;     // along y, 0.5 apart

MeshData hingedSheets(float foldRad, float lengthB = 1.0f) {
    MeshData mesh;
    for (int sheet = 0; sheet < 2; ++sheet) {
        const auto first = static_cast<uint32_t>(mesh.vertices.size());
        for (int row = 0; row <= kSheetRows; ++row) {
            for (int column = 0; column <= kSheetColumns; ++column) {
                const float s = 0.25f * float(column) * (sheet == 0 ? 1.0f : lengthB);  // distance from the hinge
                const float y = -2.0f + 0.5f * float(row);
                Vertex v;
                if (sheet == 0) {
                    v.position = {s, y, 0.0f};
                    v.normal = {0.0f, 0.0f, 1.0f};
                } else {
                    v.position = {-s * std::cos(foldRad), y, s * std::sin(foldRad)};
                    v.normal = {std::sin(foldRad), 0.0f, std::cos(foldRad)};
                }
                // Chart A in u [0, 0.25], chart B in u [0.5, 0.75]: apart.
                v.uv = {0.5f * float(sheet) + 0.0625f * float(column), 0.125f * float(row)};
                mesh.vertices.push_back(v);
            }
        }
        const auto at = [&](int column, int row) { return first + static_cast<uint32_t>(row * (kSheetColumns + 1) + column); };
        for (int row = 0; row < kSheetRows; ++row) {
            for (int column = 0; column < kSheetColumns; ++column) {
                mesh.indices.insert(mesh.indices.end(), {at(column, row), at(column + 1, row), at(column + 1, row + 1),
                                                         at(column, row), at(column + 1, row + 1), at(column, row + 1)});
            }
        }
    }
    return mesh;
}

size_t sheetVertex(int sheet, int column, int row) {
    return static_cast<size_t>(sheet * (kSheetColumns + 1) * (kSheetRows + 1) + row * (kSheetColumns + 1) + column);
}

}  // namespace

TEST(UvLayout, ASeamContinuesOnTheOtherChartAndTurnsAsTheSurfaceFolds) {
    // The probe 0.5 object units into either sheet: the turn is -N_A.N_B of
    // the two sheets' normals, -cos(fold) in closed form, exact here (every
    // vertex has its sheet's normal). Against constants: 1e-5.
    const float metresPerUnit = kSeamProbeM / 0.5f;
    for (float foldDeg : {0.0f, 90.0f, 170.0f}) {
        const float fold = glm::radians(foldDeg);
        const MeshData mesh = hingedSheets(fold);
        const UvLayout layout = analyseUvLayout(mesh, metresPerUnit);
        // A's vertex a quarter from the hinge, mid-height: its nearest border
        // point is the hinge vertex beside it, whose other copy is B's.
        const glm::vec4 c = layout.seamContinuation[sheetVertex(0, 1, kSheetRows / 2)];
        const glm::vec2 partnerUv = mesh.vertices[sheetVertex(1, 0, kSheetRows / 2)].uv;
        EXPECT_EQ(c.z, 1.0f) << foldDeg;
        EXPECT_EQ(glm::vec2(c.x, c.y), partnerUv) << foldDeg;
        EXPECT_NEAR(c.w, -std::cos(fold), 1e-5f) << foldDeg;
        // And from B's side, the same turn back.
        const glm::vec4 back = layout.seamContinuation[sheetVertex(1, 1, kSheetRows / 2)];
        EXPECT_EQ(glm::vec2(back.x, back.y), mesh.vertices[sheetVertex(0, 0, kSheetRows / 2)].uv) << foldDeg;
        EXPECT_NEAR(back.w, -std::cos(fold), 1e-5f) << foldDeg;
        // The far edge of a sheet is the mesh's own: nothing goes on there.
        EXPECT_EQ(layout.seamContinuation[sheetVertex(0, kSheetColumns, kSheetRows / 2)].z, 0.0f) << foldDeg;
    }
    // Sheet B shortened to 0.2, under half the probe: a strip round a box's
    // thin end, whose light is not what lies beyond the border. A's vertices
    // take no continuation (B's still do: A reaches 1).
    const MeshData strip = hingedSheets(glm::half_pi<float>(), 0.2f);
    const UvLayout layout = analyseUvLayout(strip, metresPerUnit);
    EXPECT_EQ(layout.seamContinuation[sheetVertex(0, 1, kSheetRows / 2)].z, 0.0f);
    EXPECT_EQ(layout.seamContinuation[sheetVertex(1, 1, kSheetRows / 2)].z, 1.0f);
}

TEST(UvLayout, ThePlaneHasNoSeamAndTheSphereSeamGoesOnFlat) {
    const MeshData plane = proceduralMesh("plane");
    for (const glm::vec4& c : analyseUvLayout(plane, 1.0f).seamContinuation) ASSERT_EQ(c.z, 0.0f);

    // The UV sphere's seam (u = 0 and u = 1) joins the chart to itself: a
    // seam vertex away from the poles continues at the same v on the other
    // edge, and the surface there goes on without turning round.
    const MeshData sphere = proceduralMesh("sphere");
    const UvLayout layout = analyseUvLayout(sphere, 1.0f);
    int seamVertices = 0;
    for (size_t i = 0; i < sphere.vertices.size(); ++i) {
        const glm::vec2 uv = sphere.vertices[i].uv;
        if (uv.y < 0.25f || uv.y > 0.75f || (uv.x != 0.0f && uv.x != 1.0f)) continue;
        ++seamVertices;
        const glm::vec4 c = layout.seamContinuation[i];
        EXPECT_EQ(c.z, 1.0f) << "seam vertex " << i;
        EXPECT_EQ(c.x, 1.0f - uv.x) << "seam vertex " << i;
        EXPECT_EQ(c.y, uv.y) << "seam vertex " << i;
        EXPECT_LT(c.w, -0.9f) << "seam vertex " << i;
    }
    EXPECT_GT(seamVertices, 0);
}

TEST(UvLayout, TheProceduralEarsRimTurnsRoundAndTheSkullSeamDoesNot) {
    // The procedural head, in metres: each ear's two faces are charts that
    // meet at its rim, the skull's one chart meets itself at the back (the
    // rows next to its poles are borders too, of the pole copies' slivers,
    // but with no other copy of their vertices there: no seam).
    // The gather takes the rim formula of include/ThinEdges.glsl in full
    // from a turn of THIN_EDGE_OPPOSED_FULL (0.4) and none under
    // THIN_EDGE_OPPOSED_NONE (0.1): every ear rim vertex must reach the
    // first, every skull seam vertex stay under the second.
    const HeadMesh head = makeHeadMesh();
    const UvLayout layout = analyseUvLayout(head.mesh, 1.0f);
    std::vector<bool> ear(head.mesh.vertices.size(), false);
    for (size_t t = head.skullTriangleCount * 3; t < head.mesh.indices.size(); ++t) ear[head.mesh.indices[t]] = true;
    float earLeast = 2.0f, skullMost = -2.0f;
    int earRim = 0, skullSeam = 0;
    for (size_t v = 0; v < head.mesh.vertices.size(); ++v) {
        if (layout.borderDistance[v] != 0.0f) continue;
        const glm::vec4 c = layout.seamContinuation[v];
        if (ear[v]) {
            EXPECT_EQ(c.z, 1.0f) << "ear border vertex " << v;
            earLeast = std::min(earLeast, c.w);
            ++earRim;
        } else if (c.z == 1.0f) {
            skullMost = std::max(skullMost, c.w);
            ++skullSeam;
        }
    }
    std::printf("[ measured ] seam turn: %d ear rim vertices from %.3f, %d skull seam vertices up to %.3f\n", earRim,
                earLeast, skullSeam, skullMost);
    EXPECT_GT(earRim, 0);
    EXPECT_GT(skullSeam, 0);
    EXPECT_GE(earLeast, 0.4f);
    EXPECT_LT(skullMost, 0.1f);
}

// The planner asks for a character's layout every frame, at the scale it
// reads from the character's transform; a rotated transform gives that scale
// with rounding that changes from frame to frame, and each fresh analysis
// costs a Dijkstra over the mesh and the buried-vertex rays. A scale off by
// rounding keeps the analysed layout; one that moves the 3 mm seam probe
// (twice the size) gets a new one. Broken on purpose (exact comparison): the
// first expectation fails.
TEST(UvLayout, SceneGeometryKeepsTheLayoutUnlessTheScaleReallyChanges) {
    std::vector<Model> models(1);
    models[0].mesh = proceduralMesh("sphere");
    SceneGeometry geometry(models);
    const UvLayout* first = &geometry.uvLayout(0, 1.0f);
    EXPECT_EQ(&geometry.uvLayout(0, std::nextafter(1.0f, 2.0f)), first);
    EXPECT_EQ(&geometry.uvLayout(0, 1.0f), first);
    EXPECT_NE(&geometry.uvLayout(0, 2.0f), first);
}
