#include "core/ImageResample.h"
#include "import/GltfLoader.h"

#include "FuzzSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace dermis;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t chunk = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) chunk |= uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
        out += kAlphabet[(chunk >> 18) & 63];
        out += kAlphabet[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
    }
    return out;
}

std::vector<unsigned char> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// Builds a small glTF document: one binary buffer, views and accessors added
// from typed arrays, and whatever meshes/nodes/scenes the test writes into doc.
struct GltfBuilder {
    std::vector<unsigned char> bin;
    json doc = {{"asset", {{"version", "2.0"}}}};

    template <class T>
    int accessor(const std::vector<T>& values, int componentType, const char* type, size_t count) {
        while (bin.size() % 4) bin.push_back(0);
        size_t offset = bin.size();
        bin.resize(offset + values.size() * sizeof(T));
        std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
        doc["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
        doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                                    {"componentType", componentType},
                                    {"count", count},
                                    {"type", type}});
        return static_cast<int>(doc["accessors"].size() - 1);
    }
    int vec3(const std::vector<float>& v) { return accessor(v, kFloat, "VEC3", v.size() / 3); }
    int vec2(const std::vector<float>& v) { return accessor(v, kFloat, "VEC2", v.size() / 2); }

    int imageView(const std::vector<unsigned char>& bytes) {
        while (bin.size() % 4) bin.push_back(0);
        size_t offset = bin.size();
        bin.insert(bin.end(), bytes.begin(), bytes.end());
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }

    void writeGltf(const fs::path& path, const std::string& binName = "") {
        json out = doc;
        while (bin.size() % 4) bin.push_back(0);
        if (binName.empty()) {
            out["buffers"] = {
                {{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        } else {
            out["buffers"] = {{{"byteLength", bin.size()}, {"uri", binName}}};
            writeBytes(path.parent_path() / binName, bin.data(), bin.size());
        }
        std::ofstream(path) << out.dump(1);
    }

    // The document as a GLB stores it: one buffer, the BIN chunk.
    json glbDocument() {
        json out = doc;
        while (bin.size() % 4) bin.push_back(0);
        out["buffers"] = {{{"byteLength", bin.size()}}};
        return out;
    }
    std::vector<unsigned char> glbBytes() { return packGlb(glbDocument(), bin); }
    void writeGlb(const fs::path& path) {
        std::vector<unsigned char> glb = glbBytes();
        writeBytes(path, glb.data(), glb.size());
    }

    static std::vector<unsigned char> packGlb(const json& document, const std::vector<unsigned char>& bin) {
        std::string text = document.dump();
        while (text.size() % 4) text += ' ';
        std::vector<unsigned char> glb;
        auto u32 = [&glb](uint32_t v) {
            for (int i = 0; i < 4; ++i) glb.push_back(static_cast<unsigned char>(v >> (8 * i)));
        };
        u32(0x46546C67);
        u32(2);
        u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
        u32(static_cast<uint32_t>(text.size()));
        u32(0x4E4F534A);
        glb.insert(glb.end(), text.begin(), text.end());
        u32(static_cast<uint32_t>(bin.size()));
        u32(0x004E4942);
        glb.insert(glb.end(), bin.begin(), bin.end());
        return glb;
    }
};

// A unit quad in the XY plane facing +Z: u along +X, v = 0 at the top (+Y).
const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kQuadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
const std::vector<float> kQuadUvs = {0, 1, 1, 1, 1, 0, 0, 0};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

// Adds the quad as mesh 0 (positions and UVs always, normals if asked) with
// indices of the given component type; returns the builder for more edits.
GltfBuilder quadBuilder(int indexType, bool withNormals = true) {
    GltfBuilder b;
    json attributes = {{"POSITION", b.vec3(kQuadPositions)}, {"TEXCOORD_0", b.vec2(kQuadUvs)}};
    if (withNormals) attributes["NORMAL"] = b.vec3(kQuadNormals);
    json primitive = {{"attributes", attributes}};
    if (indexType == kUnsignedByte)
        primitive["indices"] =
            b.accessor(std::vector<uint8_t>(kQuadIndices.begin(), kQuadIndices.end()), kUnsignedByte, "SCALAR", 6);
    else if (indexType == kUnsignedShort)
        primitive["indices"] =
            b.accessor(std::vector<uint16_t>(kQuadIndices.begin(), kQuadIndices.end()), kUnsignedShort, "SCALAR", 6);
    else if (indexType == kUnsignedInt)
        primitive["indices"] = b.accessor(kQuadIndices, kUnsignedInt, "SCALAR", 6);
    b.doc["meshes"] = {{{"name", "quad"}, {"primitives", {primitive}}}};
    b.doc["nodes"] = {{{"mesh", 0}}};
    b.doc["scenes"] = {{{"nodes", {0}}}};
    b.doc["scene"] = 0;
    return b;
}

class GltfTest : public ::testing::Test {
protected:
    void SetUp() override {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::temp_directory_path() / ("dermis_gltf_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(mDir, ignored);
    }
    fs::path path(const std::string& name) const { return mDir / name; }

    // Expects a load error whose message names the file.
    void expectError(const fs::path& file, const std::string& fragment = "") {
        Result<Model> model = loadGltf(file.string());
        ASSERT_FALSE(model) << file;
        std::string message = model.error().message();
        EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        if (!fragment.empty()) EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }

    // For input that may or may not be valid: a model with triangles, or an
    // error that names the file on one line. Returns whether it loaded.
    bool expectWellFormedOutcome(const fs::path& file) {
        Result<Model> model = loadGltf(file.string());
        if (model) {
            EXPECT_GT(model->mesh.triangleCount(), 0u);
            for (uint32_t index : model->mesh.indices) EXPECT_LT(index, model->mesh.vertices.size());
            return true;
        }
        std::string message = model.error().message();
        EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return false;
    }

    fs::path mDir;
};

void expectFramesValid(const MeshData& mesh) {
    for (const Vertex& v : mesh.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
        EXPECT_LT(std::fabs(glm::dot(v.normal, glm::vec3(v.tangent))), 1e-4f);
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
    }
}

// The normal of each triangle's winding, which must agree with its vertices'.
void expectWindingMatchesNormals(const MeshData& mesh) {
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[i]];
        const Vertex& b = mesh.vertices[mesh.indices[i + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[i + 2]];
        glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal), 0.0f) << "triangle " << i / 3;
    }
}

}  // namespace

TEST_F(GltfTest, QuadWithEachIndexWidth) {
    for (int indexType : {kUnsignedByte, kUnsignedShort, kUnsignedInt}) {
        fs::path file = path("quad" + std::to_string(indexType) + ".gltf");
        quadBuilder(indexType).writeGltf(file);
        Result<Model> model = loadGltf(file.string());
        ASSERT_TRUE(model) << model.error().message();
        EXPECT_EQ(model->mesh.vertices.size(), 4u);
        EXPECT_EQ(model->mesh.indices, kQuadIndices);
        EXPECT_EQ(model->mesh.name, "quad");
        EXPECT_EQ(model->mesh.vertices[2].uv, glm::vec2(1.0f, 0.0f));
        EXPECT_TRUE(model->materials[0].albedoMap.empty());
        expectFramesValid(model->mesh);
        // Generated tangents follow +u (+X) with an unmirrored sign.
        for (const Vertex& v : model->mesh.vertices) EXPECT_EQ(v.tangent, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    }
}

TEST_F(GltfTest, NonIndexedPrimitive) {
    GltfBuilder b;
    std::vector<float> positions;
    for (uint32_t index : kQuadIndices)
        positions.insert(positions.end(), kQuadPositions.begin() + 3 * index, kQuadPositions.begin() + 3 * index + 3);
    b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", b.vec3(positions)}}}}}}}};
    b.doc["nodes"] = {{{"mesh", 0}}};
    b.writeGltf(path("flat.gltf"));  // no scenes: every root node is loaded
    Result<Model> model = loadGltf(path("flat.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->mesh.vertices.size(), 6u);
    EXPECT_EQ(model->mesh.triangleCount(), 2u);
    EXPECT_EQ(model->mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    for (const Vertex& v : model->mesh.vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);  // generated
    expectFramesValid(model->mesh);
}

TEST_F(GltfTest, NodeHierarchyTransformsPositions) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    // Parent: translate (10,0,0), scale 2; child: translate (0,1,0) with the mesh.
    b.doc["nodes"] = {{{"children", {1}}, {"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}},
                      {{"mesh", 0}, {"translation", {0, 1, 0}}},
                      {{"mesh", 0}, {"translation", {100, 0, 0}}}};  // not in the scene
    b.doc["scenes"] = {{{"nodes", {2}}}, {{"nodes", {0}}}};
    b.doc["scene"] = 1;
    b.writeGltf(path("tree.gltf"));
    Result<Model> model = loadGltf(path("tree.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->mesh.triangleCount(), 2u);
    Bounds bounds = model->mesh.bounds();
    EXPECT_NEAR(bounds.min.x, 10.0f, 1e-5f);
    EXPECT_NEAR(bounds.max.x, 12.0f, 1e-5f);
    EXPECT_NEAR(bounds.min.y, 2.0f, 1e-5f);
    EXPECT_NEAR(bounds.max.y, 4.0f, 1e-5f);
    EXPECT_NEAR(bounds.max.z, 0.0f, 1e-5f);
}

TEST_F(GltfTest, RotationAndMatrixTransformNormalsAndTangents) {
    GltfBuilder b = quadBuilder(kUnsignedInt);
    const float s = std::sqrt(0.5f);
    // Node 0: 90 degrees about +Y, so +Z normals become +X and +X tangents -Z.
    // Node 1: the same as a column-major matrix, plus translation (0,0,5).
    b.doc["nodes"] = {{{"mesh", 0}, {"rotation", {0, s, 0, s}}},
                      {{"mesh", 0}, {"matrix", {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 5, 1}}}};
    b.doc["scenes"] = {{{"nodes", {0, 1}}}};
    b.writeGltf(path("rotated.gltf"));
    Result<Model> model = loadGltf(path("rotated.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->mesh.vertices.size(), 8u);
    EXPECT_EQ(model->mesh.triangleCount(), 4u);
    for (const Vertex& v : model->mesh.vertices) {
        EXPECT_NEAR(v.normal.x, 1.0f, 1e-5f);
        EXPECT_NEAR(v.tangent.z, -1.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
    EXPECT_NEAR(model->mesh.vertices[4].position.z, 5.0f, 1e-5f);
    EXPECT_NEAR(model->mesh.vertices[5].position.z, 4.0f, 1e-5f);
    expectWindingMatchesNormals(model->mesh);
}

TEST_F(GltfTest, MirroringScaleKeepsWindingAndFrames) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["nodes"] = {{{"mesh", 0}, {"scale", {-1, 1, 1}}}};
    b.writeGltf(path("mirror.gltf"));
    Result<Model> model = loadGltf(path("mirror.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    expectWindingMatchesNormals(model->mesh);
    expectFramesValid(model->mesh);
    for (const Vertex& v : model->mesh.vertices) {
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
        EXPECT_NEAR(v.tangent.x, -1.0f, 1e-6f);  // +u now runs along -X: a mirrored frame
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST_F(GltfTest, GeneratesMissingNormalsAndTangents) {
    GltfBuilder b = quadBuilder(kUnsignedByte, false);
    b.doc["nodes"] = {{{"mesh", 0}, {"scale", {3, 1, 1}}}};
    b.writeGltf(path("bare.gltf"));
    Result<Model> model = loadGltf(path("bare.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    expectFramesValid(model->mesh);
    for (const Vertex& v : model->mesh.vertices) {
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    }
}

// glTF 2.0 §3.7.2.1: without NORMAL, flat normals. A unit cube of 8 shared
// vertices and 12 triangles, stretched along x by its node, with a colour per
// corner: every triangle gets three vertices of its own, whose normal is
// the axis its face looks along (closed form), and each copy keeps its
// corner's position and colour. Smooth normals (what the loader gave before)
// point along the cube's diagonals: 0.577 from every axis.
TEST_F(GltfTest, PrimitiveWithoutNormalsIsDrawnFlat) {
    GltfBuilder b;
    std::vector<float> corners, colours;
    for (int i = 0; i < 8; ++i) {
        const float x = float(i & 1), y = float((i >> 1) & 1), z = float((i >> 2) & 1);
        corners.insert(corners.end(), {x, y, z});
        colours.insert(colours.end(), {x, y, z, 1.0f});
    }
    // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    const std::vector<uint16_t> cube = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                        2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    b.doc["meshes"] = {{{"primitives",
                         {{{"attributes", {{"POSITION", b.vec3(corners)}, {"COLOR_0", b.accessor(colours, kFloat, "VEC4", 8)}}},
                           {"indices", b.accessor(cube, kUnsignedShort, "SCALAR", cube.size())}}}}}};
    b.doc["nodes"] = {{{"mesh", 0}, {"scale", {2, 1, 1}}}};
    b.writeGltf(path("cube.gltf"));
    Result<Model> model = loadGltf(path("cube.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->mesh.vertices.size(), 36u);
    ASSERT_EQ(model->colours.size(), 36u);
    const glm::vec3 faceNormals[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (size_t i = 0; i < model->mesh.indices.size(); ++i) {
        const uint32_t index = model->mesh.indices[i];
        const Vertex& v = model->mesh.vertices[index];
        const glm::vec3 corner(corners[3 * cube[i]], corners[3 * cube[i] + 1], corners[3 * cube[i] + 2]);
        EXPECT_LT(glm::distance(v.normal, faceNormals[i / 6]), 1e-6f) << "corner " << i;
        EXPECT_LT(glm::distance(v.position, corner * glm::vec3(2, 1, 1)), 1e-6f) << "corner " << i;
        EXPECT_EQ(model->colours[index], glm::vec4(corner, 1.0f)) << "corner " << i;
    }
    expectFramesValid(model->mesh);
}

TEST_F(GltfTest, FileTangentsAreKeptAndOrthogonalised) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    // Slightly off the surface, and with w = -1: kept, made orthogonal, sign kept.
    std::vector<float> tangents = {1, 0, 0.1f, -1, 1, 0, 0.1f, -1, 1, 0, 0.1f, -1, 1, 0, 0.1f, -1};
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = b.accessor(tangents, kFloat, "VEC4", 4);
    b.writeGltf(path("tangents.gltf"));
    Result<Model> model = loadGltf(path("tangents.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    expectFramesValid(model->mesh);
    for (const Vertex& v : model->mesh.vertices) {
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST_F(GltfTest, GlbAndExternalBinLoadTheSameMesh) {
    quadBuilder(kUnsignedShort).writeGlb(path("quad.glb"));
    quadBuilder(kUnsignedShort).writeGltf(path("quad.gltf"), "quad data.bin");
    Result<Model> glb = loadGltf(path("quad.glb").string());
    Result<Model> gltf = loadGltf(path("quad.gltf").string());
    ASSERT_TRUE(glb) << glb.error().message();
    ASSERT_TRUE(gltf) << gltf.error().message();
    EXPECT_EQ(glb->mesh.indices, kQuadIndices);
    EXPECT_EQ(gltf->mesh.indices, kQuadIndices);
    ASSERT_EQ(glb->mesh.vertices.size(), 4u);
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(glb->mesh.vertices[i].position, gltf->mesh.vertices[i].position);
}

TEST_F(GltfTest, StripsFansAndNonTriangles) {
    GltfBuilder b;
    int positions = b.vec3(kQuadPositions);
    int normals = b.vec3(kQuadNormals);  // without them every triangle would get vertices of its own
    int strip = b.accessor(std::vector<uint16_t>{0, 1, 3, 2}, kUnsignedShort, "SCALAR", 4);
    const json attributes = {{"POSITION", positions}, {"NORMAL", normals}};
    b.doc["meshes"] = {{{"primitives",
                         {{{"attributes", attributes}, {"indices", strip}, {"mode", 5}},
                          {{"attributes", attributes}, {"mode", 6}},
                          {{"attributes", attributes}, {"mode", 1}}}}}};  // lines: skipped
    b.doc["nodes"] = {{{"mesh", 0}}};
    b.writeGltf(path("strips.gltf"));
    Result<Model> model = loadGltf(path("strips.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->mesh.vertices.size(), 8u);
    EXPECT_EQ(model->mesh.indices, (std::vector<uint32_t>{0, 1, 3, 1, 2, 3, 5, 6, 4, 6, 7, 4}));
    expectWindingMatchesNormals(model->mesh);
}

TEST_F(GltfTest, MaterialMapsFromDataUriBufferViewAndFile) {
    const Image pixel = makeImage(3, 2, ColourSpace::Linear, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    ASSERT_TRUE(saveImage(path("albedo.png").string(), pixel));
    ASSERT_TRUE(saveImage(path("normal map.png").string(), pixel));
    std::vector<unsigned char> png = readBytes(path("albedo.png"));

    GltfBuilder b = quadBuilder(kUnsignedShort);
    int view = b.imageView(png);
    b.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png)}},
                       {{"uri", "normal%20map.png"}},
                       {{"bufferView", view}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}};
    b.doc["materials"] = {
        {{"name", "plain"}},
        {{"name", "skin"},
         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 2}}}}},
         {"normalTexture", {{"index", 1}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    json second = b.doc["meshes"][0]["primitives"][0];
    second["material"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(second);
    b.writeGltf(path("textured.gltf"));

    Result<Model> model = loadGltf(path("textured.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->mesh.triangleCount(), 4u);
    // Each primitive keeps its material; the maps are the second one's.
    ASSERT_EQ(model->materials.size(), 2u);
    EXPECT_EQ(model->materials[0].name, "plain");
    EXPECT_TRUE(model->materials[0].albedoMap.empty());
    const ModelMaterial& skin = model->materials[1];
    EXPECT_EQ(skin.name, "skin");
    ASSERT_EQ(model->submeshes.size(), 2u);
    EXPECT_EQ(model->submeshes[0].material, 0);
    EXPECT_EQ(model->submeshes[1].material, 1);
    EXPECT_EQ(model->submeshes[1].firstIndex, 6u);
    EXPECT_EQ(model->submeshes[1].indexCount, 6u);
    for (const Image* map : {&skin.albedoMap, &skin.normalMap, &skin.metallicRoughnessMap}) {
        EXPECT_EQ(map->width, 3);
        EXPECT_EQ(map->height, 2);
        ASSERT_FALSE(map->empty());
        EXPECT_NEAR(map->texels[0].y, 0.4f, 1.0f / 255.0f);
    }
    EXPECT_EQ(skin.albedoMap.colourSpace, ColourSpace::Srgb);
    EXPECT_EQ(skin.normalMap.colourSpace, ColourSpace::Linear);
    EXPECT_EQ(skin.metallicRoughnessMap.colourSpace, ColourSpace::Linear);

    fs::remove(path("normal map.png"));
    expectError(path("textured.gltf"), "normal map.png");
}

TEST_F(GltfTest, SurfaceExtensionsAndAlphaModeAreRead) {
    // Each extension's grey value sits in its own channel (diffuse transmission
    // in A, volume thickness in G): the loader moves it to R, where the scatter
    // and thickness maps are read. The PNG's channels differ so a wrong one shows.
    ASSERT_TRUE(saveImage(path("grey.png").string(), makeImage(2, 2, ColourSpace::Linear, glm::vec4(0.1f, 0.5f, 0.9f, 0.6f))));
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["images"] = {{{"uri", "grey.png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["extensionsUsed"] = {"KHR_materials_diffuse_transmission", "KHR_materials_volume", "KHR_materials_transmission"};
    b.doc["materials"] = {
        {{"name", "skin"},
         {"extensions",
          {{"KHR_materials_diffuse_transmission",
            {{"diffuseTransmissionFactor", 0.4}, {"diffuseTransmissionTexture", {{"index", 0}}}}},
           {"KHR_materials_volume", {{"thicknessFactor", 0.02}, {"thicknessTexture", {{"index", 0}}}}}}}},
        {{"name", "lens"}, {"alphaMode", "BLEND"}, {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}},
        {{"name", "plain"}}};
    json primitive = b.doc["meshes"][0]["primitives"][0];
    b.doc["meshes"][0]["primitives"] = json::array();
    for (int m = 0; m < 3; ++m) {
        primitive["material"] = m;
        b.doc["meshes"][0]["primitives"].push_back(primitive);
    }
    b.writeGltf(path("surface.gltf"));
    Result<Model> model = loadGltf(path("surface.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->materials.size(), 3u);
    const ModelMaterial& skin = model->materials[0];
    EXPECT_FLOAT_EQ(skin.diffuseTransmission, 0.4f);
    ASSERT_FALSE(skin.diffuseTransmissionMap.empty());
    EXPECT_NEAR(skin.diffuseTransmissionMap.texels[0].r, 0.6f, 1.0f / 255.0f);  // A
    EXPECT_FLOAT_EQ(skin.thicknessFactor, 0.02f);
    ASSERT_FALSE(skin.thicknessMap.empty());
    EXPECT_NEAR(skin.thicknessMap.texels[0].r, 0.5f, 1.0f / 255.0f);  // G
    EXPECT_EQ(skin.alphaMode, "OPAQUE");
    const ModelMaterial& lens = model->materials[1];
    EXPECT_EQ(lens.alphaMode, "BLEND");
    EXPECT_FLOAT_EQ(lens.transmission, 1.0f);
    EXPECT_LT(lens.diffuseTransmission, 0.0f);  // the file gives none
    const ModelMaterial& plain = model->materials[2];
    EXPECT_LT(plain.diffuseTransmission, 0.0f);
    EXPECT_EQ(plain.thicknessFactor, 0.0f);
    EXPECT_TRUE(plain.thicknessMap.empty());
}

TEST_F(GltfTest, CorruptEmbeddedImageIsAnError) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    int view = b.imageView({0x89, 'P', 'N', 'G', 1, 2, 3, 4});
    b.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}, {"name", "broken"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.writeGlb(path("badimage.glb"));
    expectError(path("badimage.glb"), "broken");
}

TEST_F(GltfTest, MissingFilesAndMalformedJson) {
    expectError(path("absent.gltf"), "not found");

    quadBuilder(kUnsignedShort).writeGltf(path("split.gltf"), "split.bin");
    fs::remove(path("split.bin"));
    expectError(path("split.gltf"), "buffer 0 'split.bin' not found");

    std::ofstream(path("broken.gltf")) << R"({"asset": {"version": "2.0"}, "meshes": [ {)";
    expectError(path("broken.gltf"), "JSON");

    std::ofstream(path("empty.gltf")) << "";
    expectError(path("empty.gltf"));

    // A .glb of other bytes: the missing magic is named, not a JSON parse error
    // (without the check the message read "malformed JSON: ... invalid literal").
    std::ofstream(path("noise.glb")) << "PK\x03\x04 not a glTF at all";
    expectError(path("noise.glb"), "magic 'glTF'");
    // A .glb holding glTF JSON is still read as JSON (some tools write that).
    quadBuilder(kUnsignedShort).writeGltf(path("json.glb"));
    auto json = loadGltf(path("json.glb").string());
    EXPECT_TRUE(json.ok()) << (json.ok() ? "" : json.error().message());
}

TEST_F(GltfTest, TruncatedGlb) {
    std::vector<unsigned char> glb = quadBuilder(kUnsignedShort).glbBytes();
    for (size_t size : {glb.size() - 4, glb.size() / 2, size_t(30), size_t(12), size_t(3)}) {
        fs::path file = path("cut" + std::to_string(size) + ".glb");
        writeBytes(file, glb.data(), size);
        expectError(file);
    }
    // The header's length agrees with a file whose BIN chunk claims too much.
    std::vector<unsigned char> lying = glb;
    size_t jsonLength = lying[12] | lying[13] << 8;
    lying[20 + jsonLength] += 8;
    writeBytes(path("lying.glb"), lying.data(), lying.size());
    expectError(path("lying.glb"), "BIN");
}

TEST_F(GltfTest, AccessorAndIndexValidation) {
    {  // count larger than the buffer view holds
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["accessors"][0]["count"] = 5;
        b.writeGltf(path("overrun.gltf"));
        expectError(path("overrun.gltf"), "accessor 0");
    }
    {  // an enormous count must fail fast, not allocate
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["accessors"][0]["count"] = 4000000000u;
        b.writeGlb(path("huge.glb"));
        expectError(path("huge.glb"), "accessor 0");
    }
    {  // attribute accessor index out of range
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42;
        b.writeGltf(path("noaccessor.gltf"));
        expectError(path("noaccessor.gltf"), "accessor 42");
    }
    {  // index value beyond the vertex count
        GltfBuilder b;
        int positions = b.vec3(kQuadPositions);
        int indices = b.accessor(std::vector<uint32_t>{0, 1, 4}, kUnsignedInt, "SCALAR", 3);
        b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}};
        b.doc["nodes"] = {{{"mesh", 0}}};
        b.writeGltf(path("badindex.gltf"));
        expectError(path("badindex.gltf"), "index 4");
    }
    {  // buffer view beyond its buffer
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["bufferViews"][1]["byteOffset"] = 100000;
        b.writeGltf(path("badview.gltf"));
        expectError(path("badview.gltf"), "bufferView");
    }
    {  // wrong accessor type
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["accessors"][0]["type"] = "VEC2";
        b.writeGltf(path("badtype.gltf"));
        expectError(path("badtype.gltf"), "expected VEC3");
    }
}

TEST_F(GltfTest, StructuralErrors) {
    {  // only lines: no triangles at all
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["meshes"][0]["primitives"][0]["mode"] = 1;
        b.writeGltf(path("lines.gltf"));
        expectError(path("lines.gltf"), "no triangles");
    }
    {  // a node cycle must not hang
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
        b.writeGltf(path("cycle.gltf"));
        expectError(path("cycle.gltf"), "node 0");
    }
    {  // child index out of range
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["nodes"] = {{{"mesh", 0}, {"children", {7}}}};
        b.writeGltf(path("child.gltf"));
        expectError(path("child.gltf"), "node 7");
    }
    {  // non-finite transform
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["nodes"] = {{{"mesh", 0}, {"scale", {1e39, 1, 1}}}};
        b.writeGltf(path("inf.gltf"));
        expectError(path("inf.gltf"), "node 0");
    }
}

namespace {

// The quad with a base colour map in a buffer view: the GLB the fuzz tests
// break, so that damage can land in the JSON, the geometry or the image.
GltfBuilder texturedQuadBuilder(const fs::path& scratchPng) {
    Image image;
    image.width = 4;
    image.height = 4;
    for (int i = 0; i < 16; ++i) image.texels.emplace_back(0.1f * float(i % 5), 0.5f, 0.06f * float(i), 1.0f);
    EXPECT_TRUE(saveImage(scratchPng.string(), image));
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["images"] = {{{"bufferView", b.imageView(readBytes(scratchPng))}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    return b;
}

}  // namespace

TEST_F(GltfTest, GlbAndGltfTruncatedAtManyOffsetsAreErrors) {
    GltfBuilder b = texturedQuadBuilder(path("map.png"));
    std::vector<unsigned char> glb = b.glbBytes();
    writeBytes(path("whole.glb"), glb.data(), glb.size());
    Result<Model> whole = loadGltf(path("whole.glb").string());
    ASSERT_TRUE(whole) << whole.error().message();
    EXPECT_EQ(whole->materials[0].albedoMap.width, 4);
    for (size_t length : fuzz::truncationLengths(glb.size())) {
        SCOPED_TRACE("first " + std::to_string(length) + " bytes of the GLB");
        fs::path file = path("cut" + std::to_string(length) + ".glb");
        writeBytes(file, glb.data(), length);
        expectError(file);
    }
    b.writeGltf(path("whole.gltf"));
    std::vector<unsigned char> text = readBytes(path("whole.gltf"));
    for (size_t length : fuzz::truncationLengths(text.size(), 16, 64)) {
        SCOPED_TRACE("first " + std::to_string(length) + " bytes of the glTF");
        fs::path file = path("cut" + std::to_string(length) + ".gltf");
        writeBytes(file, text.data(), length);
        expectError(file);
    }
}

// Every value of the GLB's JSON, in turn, replaced by a wrong type or an
// extreme number (a string where a count goes, 2^31 and 2^64-1 counts, ...).
TEST_F(GltfTest, EveryValueWithEveryWrongTypeIsAWellFormedOutcome) {
    GltfBuilder b = texturedQuadBuilder(path("map.png"));
    const json document = b.glbDocument();
    const std::vector<json> replacements = {"6",        -1,          0.5,         nullptr,
                                            json::array(), json::object(), 2147483648u, 4294967295u,
                                            18446744073709551615u, 1e300};
    const json flat = document.flatten();
    size_t loaded = 0, total = 0;
    for (const auto& [pointer, original] : flat.items()) {
        for (const json& replacement : replacements) {
            json edited = document;
            edited[json::json_pointer(pointer)] = replacement;
            SCOPED_TRACE(pointer + " = " + replacement.dump());
            std::vector<unsigned char> glb = GltfBuilder::packGlb(edited, b.bin);
            fs::path file = path("typed" + std::to_string(total++) + ".glb");
            writeBytes(file, glb.data(), glb.size());
            loaded += expectWellFormedOutcome(file) ? 1 : 0;
            fs::remove(file);
        }
    }
    EXPECT_GT(loaded, 0u);  // a mesh name can be anything, an unused value ignored
    EXPECT_LT(loaded, total);
}

TEST_F(GltfTest, HugeCountsAndLengthsFailFast) {
    struct Case {
        const char* name;
        const char* pointer;
        json value;
        const char* fragment;  // in the error; nullptr: loading may also succeed
    };
    const std::vector<Case> cases = {
        {"count 2^31", "/accessors/0/count", 2147483648u, "accessor 0"},
        {"count 2^64-1", "/accessors/0/count", 18446744073709551615u, ""},
        {"byteOffset 2^32-1", "/accessors/0/byteOffset", 4294967295u, "accessor 0"},
        {"view longer than buffer", "/bufferViews/0/byteLength", 1u << 30, ""},
        {"view past buffer end", "/bufferViews/0/byteOffset", 4294967292u, ""},
        {"stride 2^31", "/bufferViews/0/byteStride", 2147483648u, ""},
        {"buffer 2 GiB", "/buffers/0/byteLength", 2147483648u, ""},
        {"image view 2^31", "/bufferViews/4/byteLength", 2147483648u, ""},
        {"index count 2^31", "/accessors/3/count", 2147483648u, "accessor 3"},
        {"POSITION is MAT4", "/accessors/0/type", "MAT4", "accessor 0"},
        {"POSITION is SCALAR", "/accessors/0/type", "SCALAR", "expected VEC3"},
        {"unknown type", "/accessors/0/type", "VEC7", ""},
        {"unknown component type", "/accessors/0/componentType", 1234, ""},
        {"NORMAL count below POSITION's", "/accessors/2/count", 3, "NORMAL has 3 elements"},
        {"indices VEC3", "/accessors/3/type", "VEC3", ""},
        {"indices float", "/accessors/3/componentType", kFloat, ""},
        {"count as a string", "/accessors/0/count", "4", ""},
        {"mesh index as a string", "/nodes/0/mesh", "0", nullptr},
        {"scale as a string", "/nodes/0/scale", "big", nullptr},
    };
    GltfBuilder b = texturedQuadBuilder(path("map.png"));
    const json document = b.glbDocument();
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        json edited = document;
        edited[json::json_pointer(c.pointer)] = c.value;
        std::vector<unsigned char> glb = GltfBuilder::packGlb(edited, b.bin);
        fs::path file = path(std::string(c.name) + ".glb");
        writeBytes(file, glb.data(), glb.size());
        if (c.fragment)
            expectError(file, c.fragment);
        else
            expectWellFormedOutcome(file);
    }
}

TEST_F(GltfTest, DeeplyNestedJsonIsAnError) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    json document = b.glbDocument();
    std::string text = document.dump();
    text.pop_back();  // the closing brace
    text += ", \"extras\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
    std::ofstream(path("deep.gltf")) << text;
    expectError(path("deep.gltf"), "nested");
}

// 300 seeded mutants of the textured GLB and 100 of the same file as
// glTF text with a data URI.
TEST_F(GltfTest, RandomMutationsNeverCrash) {
    GltfBuilder b = texturedQuadBuilder(path("map.png"));
    const std::vector<unsigned char> glb = b.glbBytes();
    fuzz::Mutator mutator(31337u);
    size_t loaded = 0;
    constexpr int kGlbMutants = 300;
    for (int mutant = 0; mutant < kGlbMutants; ++mutant) {
        SCOPED_TRACE("GLB mutant " + std::to_string(mutant));
        std::vector<unsigned char> bytes = mutator.mutate(glb);
        fs::path file = path("mutant" + std::to_string(mutant) + ".glb");
        writeBytes(file, bytes.data(), bytes.size());
        loaded += expectWellFormedOutcome(file) ? 1 : 0;
    }
    EXPECT_GT(loaded, 0u);
    EXPECT_LT(loaded, size_t(kGlbMutants));

    b.writeGltf(path("whole.gltf"));
    const std::vector<unsigned char> text = readBytes(path("whole.gltf"));
    fuzz::Mutator textMutator(4242u, "{}[]\",:0123456789.-+eE truefalsnul\\/");
    for (int mutant = 0; mutant < 100; ++mutant) {
        SCOPED_TRACE("glTF mutant " + std::to_string(mutant));
        std::vector<unsigned char> bytes = textMutator.mutate(text);
        fs::path file = path("mutant" + std::to_string(mutant) + ".gltf");
        writeBytes(file, bytes.data(), bytes.size());
        expectWellFormedOutcome(file);
    }
}

// ctest: content
TEST(GltfSharedContent, LeePerrySmithHead) {
    const fs::path dir = fs::path(DERMIS_SHARED_CONTENT_DIR) / "LeePerrySmith";
    if (!fs::exists(dir / "LeePerrySmith.glb") || !fs::exists(dir / "LeePerrySmith_textured_flipV.glb"))
        GTEST_SKIP() << "shared content not found in " << dir << " (the LeePerrySmith head scan); skipping";

    Result<Model> plain = loadGltf((dir / "LeePerrySmith.glb").string());
    ASSERT_TRUE(plain) << plain.error().message();
    // The README's 9,279 unique vertices is also what the file stores: the
    // loader keeps glTF vertices as they are.
    EXPECT_EQ(plain->mesh.vertices.size(), 9279u);
    EXPECT_EQ(plain->mesh.triangleCount(), 17684u);
    glm::vec3 size = plain->mesh.bounds().size();
    EXPECT_NEAR(size.x, 8.6f, 0.1f);
    EXPECT_NEAR(size.y, 7.9f, 0.1f);
    EXPECT_NEAR(size.z, 5.2f, 0.1f);
    EXPECT_TRUE(plain->materials[0].albedoMap.empty());
    EXPECT_TRUE(plain->materials[0].normalMap.empty());
    expectFramesValid(plain->mesh);

    Result<Model> textured = loadGltf((dir / "LeePerrySmith_textured_flipV.glb").string());
    ASSERT_TRUE(textured) << textured.error().message();
    EXPECT_EQ(textured->mesh.vertices.size(), 9279u);
    EXPECT_EQ(textured->mesh.triangleCount(), 17684u);
    EXPECT_EQ(textured->materials[0].albedoMap.width, 1024);
    EXPECT_EQ(textured->materials[0].albedoMap.height, 1024);
    EXPECT_EQ(textured->materials[0].albedoMap.colourSpace, ColourSpace::Srgb);
    EXPECT_EQ(textured->materials[0].normalMap.width, 1024);
    EXPECT_EQ(textured->materials[0].normalMap.height, 1024);
    EXPECT_EQ(textured->materials[0].normalMap.colourSpace, ColourSpace::Linear);
    EXPECT_TRUE(textured->materials[0].metallicRoughnessMap.empty());
    expectFramesValid(textured->mesh);

    // With the V flip, the scan's UV mapping is unmirrored almost everywhere.
    size_t positive = 0;
    for (const Vertex& v : textured->mesh.vertices) positive += v.tangent.w > 0.0f ? 1 : 0;
    EXPECT_GT(positive, textured->mesh.vertices.size() * 9 / 10);
}

// Skins, clips and morph targets are not applied yet: the loader says so,
// naming the clips, instead of dropping them silently (the issue found a
// soldier's 2 skins and 4 clips dropped without a word).
// A quad skinned to two joints (nodes 1 and 2, node 2 at x = 1 under node
// 1): vertices 0 and 3 (x = 0) follow joint 0, vertices 1 and 2 (x = 1) joint 1.
GltfBuilder skinnedQuad(const std::vector<uint16_t>& joints, const std::vector<float>& weights) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    json& attributes = b.doc["meshes"][0]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = b.accessor(joints, kUnsignedShort, "VEC4", joints.size() / 4);
    attributes["WEIGHTS_0"] = b.accessor(weights, kFloat, "VEC4", weights.size() / 4);
    b.doc["nodes"][0]["skin"] = 0;
    b.doc["nodes"].push_back({{"name", "root"}, {"children", {2}}});
    b.doc["nodes"].push_back({{"name", "tip"}, {"translation", {1.0, 0.0, 0.0}}});
    const std::vector<float> inverseBind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};
    b.doc["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", b.accessor(inverseBind, kFloat, "MAT4", 2)}}};
    b.doc["scenes"][0]["nodes"] = {0, 1};
    return b;
}

const std::vector<uint16_t> kQuadJoints = {0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
const std::vector<float> kQuadWeights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

// A clip "lift": joint 1 ("tip", node 2) moves by +1 in y from 0 s to 1 s.
void addLiftClip(GltfBuilder& b, int node) {
    const int times = b.accessor(std::vector<float>{0.0f, 1.0f}, kFloat, "SCALAR", 2);
    const int offsets = b.vec3({1, 0, 0, 1, 1, 0});
    b.doc["animations"] = {{{"name", "lift"},
                            {"samplers", {{{"input", times}, {"output", offsets}, {"interpolation", "LINEAR"}}}},
                            {"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", "translation"}}}}}}}};
}

TEST_F(GltfTest, SkinClipsAndMorphTargetsAreImported) {
    GltfBuilder b = skinnedQuad(kQuadJoints, kQuadWeights);
    addLiftClip(b, 2);
    b.writeGltf(path("lift.gltf"));
    Result<Model> model = loadGltf(path("lift.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    const Rig& rig = model->rig;
    ASSERT_EQ(rig.skins.size(), 1u);
    ASSERT_EQ(rig.palette.size(), 2u);
    ASSERT_EQ(rig.clips.size(), 1u);
    EXPECT_EQ(rig.clips[0].name, "lift");
    EXPECT_FLOAT_EQ(rig.clips[0].durationS(), 1.0f);
    // Rest pose: joint matrices are the identity, so the mesh is the quad as given.
    for (size_t v = 0; v < 4; ++v)
        EXPECT_NEAR(glm::distance(model->mesh.vertices[v].position,
                                  glm::vec3(kQuadPositions[3 * v], kQuadPositions[3 * v + 1], kQuadPositions[3 * v + 2])),
                    0.0f, 1e-6f);
    // Half way: the x = 1 edge is lifted by 0.5, the x = 0 edge stays.
    const SkinnedVertices half = deformRig(rig, poseRig(rig, 0, 0.5f));
    EXPECT_NEAR(glm::distance(half.positions[1], glm::vec3(1.0f, 0.5f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(half.positions[2], glm::vec3(1.0f, 1.5f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(half.positions[0], glm::vec3(0.0f)), 0.0f, 1e-6f);
}

// The skinned quad without normals: each corner copy keeps its vertex's joint,
// so the lift clip still raises exactly the x = 1 edge.
TEST_F(GltfTest, FlatPrimitiveCopiesKeepTheirSkinWeights) {
    GltfBuilder b = skinnedQuad(kQuadJoints, kQuadWeights);
    b.doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    addLiftClip(b, 2);
    b.writeGltf(path("flat_lift.gltf"));
    Result<Model> model = loadGltf(path("flat_lift.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->mesh.vertices.size(), 6u);
    ASSERT_EQ(model->rig.influences.size(), 6u);
    const SkinnedVertices lifted = deformRig(model->rig, poseRig(model->rig, 0, 1.0f));
    for (size_t v = 0; v < 6; ++v) {
        const glm::vec3 rest = model->mesh.vertices[v].position;
        EXPECT_NEAR(lifted.positions[v].y - rest.y, rest.x, 1e-6f) << v;  // x = 1 rises by 1, x = 0 stays
        EXPECT_NEAR(model->mesh.vertices[v].normal.z, 1.0f, 1e-6f) << v;
    }
}

TEST_F(GltfTest, UnskinnedMeshUnderAnAnimatedNodeMovesRigidly) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["nodes"] = {{{"name", "parent"}, {"children", {1}}, {"translation", {1.0, 0.0, 0.0}}},
                      {{"mesh", 0}, {"translation", {0.0, 0.0, 2.0}}}};
    b.doc["scenes"][0]["nodes"] = {0};
    addLiftClip(b, 0);
    b.writeGltf(path("rigid.gltf"));
    Result<Model> model = loadGltf(path("rigid.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    // At rest both node translations apply, as for a static file.
    EXPECT_NEAR(glm::distance(model->mesh.vertices[0].position, glm::vec3(1.0f, 0.0f, 2.0f)), 0.0f, 1e-6f);
    const SkinnedVertices lifted = deformRig(model->rig, poseRig(model->rig, 0, 1.0f));
    EXPECT_NEAR(glm::distance(lifted.positions[2], glm::vec3(2.0f, 2.0f, 2.0f)), 0.0f, 1e-6f);
}

TEST_F(GltfTest, MorphTargetWeightMovesVerticesAsSpecified) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    const int delta = b.vec3({0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4});
    b.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", delta}}};
    b.doc["meshes"][0]["weights"] = {0.25};
    b.writeGltf(path("morph.gltf"));
    Result<Model> model = loadGltf(path("morph.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->rig.morphSlots.size(), 1u);
    // glTF 2.0 §3.7.2.2: position = base + w x delta, with the mesh's default weight 0.25 at rest.
    for (size_t v = 0; v < 4; ++v) EXPECT_NEAR(model->mesh.vertices[v].position.z, 0.25f * float(v + 1), 1e-6f);
    RigPose pose = poseRig(model->rig, -1, 0.0f);
    pose.morphWeights[0] = -1.5f;
    const SkinnedVertices moved = deformRig(model->rig, pose);
    for (size_t v = 0; v < 4; ++v) EXPECT_NEAR(moved.positions[v].z, -1.5f * float(v + 1), 1e-6f);
}

TEST_F(GltfTest, BadSkinsAndClipsAreRefusedNamingThePlace) {
    // A joint index past the skin's two joints.
    std::vector<uint16_t> joints = kQuadJoints;
    joints[8] = 7;
    skinnedQuad(joints, kQuadWeights).writeGltf(path("joint.gltf"));
    expectError(path("joint.gltf"), "JOINTS_0 of vertex 2 names joint 7; skin 0 has 2 joints");

    std::vector<float> weights = kQuadWeights;
    weights[4] = -0.5f;
    skinnedQuad(kQuadJoints, weights).writeGltf(path("negative.gltf"));
    expectError(path("negative.gltf"), "WEIGHTS_0 of vertex 1 is negative");

    weights = kQuadWeights;
    weights[4] = 0.0f;
    skinnedQuad(kQuadJoints, weights).writeGltf(path("zero.gltf"));
    expectError(path("zero.gltf"), "the weights of vertex 1 sum to 0");

    GltfBuilder missing = skinnedQuad(kQuadJoints, kQuadWeights);
    addLiftClip(missing, 9);
    missing.writeGltf(path("missing.gltf"));
    expectError(path("missing.gltf"), "animation 0 'lift' channel 0 targets node 9, which does not exist (3 nodes)");

    GltfBuilder bare = quadBuilder(kUnsignedShort);
    bare.doc["nodes"][0]["skin"] = 0;
    bare.doc["nodes"].push_back({{"name", "root"}});
    bare.doc["skins"] = {{{"joints", {1}}}};
    bare.writeGltf(path("bare.gltf"));
    expectError(path("bare.gltf"), "has skin 0 but the primitive has no JOINTS_0/WEIGHTS_0");

    GltfBuilder extension = quadBuilder(kUnsignedShort);
    // Refraction through glass is not drawn: a file that requires it is refused.
    extension.doc["extensionsUsed"] = {"KHR_materials_transmission"};
    extension.doc["extensionsRequired"] = {"KHR_materials_transmission"};
    extension.writeGltf(path("glass.gltf"));
    expectError(path("glass.gltf"), "requires KHR_materials_transmission, which Dermis does not support");
}

TEST_F(GltfTest, WeightsOffOneAreNormalisedWithOneWarning) {
    std::vector<float> weights = kQuadWeights;
    weights[4] = 0.5f;  // vertex 1: 0.5, a tenth of a weight is far past rounding
    weights[8] = 0.6f;  // vertex 2
    skinnedQuad(kQuadJoints, weights).writeGltf(path("half.gltf"));
    ::testing::internal::CaptureStderr();
    Result<Model> model = loadGltf(path("half.gltf").string());
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_NE(err.find("half.gltf: the skin weights of 2 vertices do not sum to one (worst 0.5"), std::string::npos) << err;
    EXPECT_FLOAT_EQ(model->rig.influences[1].weights[0], 1.0f);

    // A second influence set: the four largest of the eight are kept.
    GltfBuilder eight = skinnedQuad(kQuadJoints, kQuadWeights);
    std::vector<float> first(16, 0.0f), second(16, 0.0f);
    std::vector<uint16_t> firstJoints(16, 0), secondJoints(16, 0);
    for (size_t v = 0; v < 4; ++v) {
        for (size_t i = 0; i < 4; ++i) {
            first[4 * v + i] = 0.15f;  // joint 0 four times: 0.6
            second[4 * v + i] = i == 0 ? 0.25f : 0.05f;  // joint 1: 0.25, then 0.05 three times
            secondJoints[4 * v + i] = 1;
        }
    }
    json& attributes = eight.doc["meshes"][0]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = eight.accessor(firstJoints, kUnsignedShort, "VEC4", 4);
    attributes["WEIGHTS_0"] = eight.accessor(first, kFloat, "VEC4", 4);
    attributes["JOINTS_1"] = eight.accessor(secondJoints, kUnsignedShort, "VEC4", 4);
    attributes["WEIGHTS_1"] = eight.accessor(second, kFloat, "VEC4", 4);
    eight.writeGltf(path("eight.gltf"));
    ::testing::internal::CaptureStderr();
    Result<Model> kept = loadGltf(path("eight.gltf").string());
    const std::string keptErr = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(kept) << kept.error().message();
    EXPECT_NE(keptErr.find("4 vertices have more than 4 influences (JOINTS_1); the 4 largest are kept, renormalised "
                           "(largest weight dropped 0.15"),
              std::string::npos)
        << keptErr;
    // Kept: 0.25 (joint 1) and three 0.15s (joint 0), summing to 0.7.
    EXPECT_NEAR(kept->rig.influences[0].weights[0], 0.25f / 0.7f, 1e-6f);
    EXPECT_EQ(kept->rig.influences[0].joints[0], 1);
}

TEST_F(GltfTest, UnsupportedOptionalExtensionsAreNamedInOneWarning) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_clearcoat", "KHR_materials_sheen"};
    b.writeGltf(path("used.gltf"));
    ::testing::internal::CaptureStderr();
    ASSERT_TRUE(loadGltf(path("used.gltf").string()));
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("used.gltf: uses KHR_materials_clearcoat, KHR_materials_sheen, which this loader ignores"),
              std::string::npos)
        << err;
}

// glTF 2.0 §3.12: a file whose extensionsRequired names an extension the loader
// does not support must be refused; the two it supports load.
TEST_F(GltfTest, UnsupportedRequiredExtensionsAreRefusedInOneLine) {
    for (const char* extension : {"KHR_materials_clearcoat", "EXT_made_up"}) {
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["extensionsUsed"] = {extension};
        b.doc["extensionsRequired"] = {extension};
        b.writeGltf(path("required.gltf"));
        Result<Model> model = loadGltf(path("required.gltf").string());
        ASSERT_FALSE(model) << extension;
        EXPECT_EQ(model.error().message().find('\n'), std::string::npos);
        EXPECT_NE(model.error().message().find(std::string("required.gltf: requires ") + extension +
                                               ", which Dermis does not support"),
                  std::string::npos)
            << model.error().message();
    }
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["extensionsUsed"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    b.doc["extensionsRequired"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    b.writeGltf(path("supported.gltf"));
    Result<Model> model = loadGltf(path("supported.gltf").string());
    EXPECT_TRUE(model) << model.error().message();
}

namespace {
void writeTestPng(const fs::path& file) {
    Image pixel;
    pixel.width = 2;
    pixel.height = 2;
    pixel.texels.assign(4, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    ASSERT_TRUE(saveImage(file.string(), pixel));
}

// The quad with a base colour texture whose KHR_texture_transform is `transform`.
GltfBuilder texturedQuad(const json& transform) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["images"] = {{{"uri", "albedo.png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    return b;
}
}  // namespace

TEST_F(GltfTest, TextureTransformFollowsTheExtensionsWorkedExample) {
    writeTestPng(path("albedo.png"));
    // The extension's example: offset [0, 1], rotation pi/2, scale 0.5 reads the image's
    // lower-left quadrant turned a quarter: (u, v) -> (v / 2, 1 - u / 2).
    texturedQuad({{"offset", {0.0, 1.0}}, {"rotation", 1.57079632679}, {"scale", {0.5, 0.5}}})
        .writeGltf(path("turned.gltf"));
    Result<Model> model = loadGltf(path("turned.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    for (size_t v = 0; v < 4; ++v) {
        const glm::vec2 file(kQuadUvs[2 * v], kQuadUvs[2 * v + 1]);
        const glm::vec2 expected(file.y / 2.0f, 1.0f - file.x / 2.0f);
        EXPECT_NEAR(glm::distance(model->mesh.vertices[v].uv, expected), 0.0f, 1e-6f) << v;
    }
}

// glTF 2.0 §5.26: a texture's sampler says how its map wraps; the loader
// keeps it for the GPU and the reference (it used to make every map repeat).
// A sampler index out of range, or a wrap value that is none of the three, is refused.
TEST_F(GltfTest, SamplersWrapModesReachTheMaterial) {
    writeTestPng(path("albedo.png"));
    GltfBuilder b = texturedQuad(json::object());
    b.doc["extensionsUsed"] = json::array();
    b.doc["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};
    b.doc["textures"][0]["sampler"] = 0;
    b.writeGltf(path("wrapped.gltf"));
    Result<Model> model = loadGltf(path("wrapped.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->materials[0].albedoWrap.s, TextureWrap::ClampToEdge);
    EXPECT_EQ(model->materials[0].albedoWrap.t, TextureWrap::MirroredRepeat);

    GltfBuilder plain = texturedQuad(json::object());
    plain.doc["extensionsUsed"] = json::array();
    plain.writeGltf(path("plain.gltf"));
    Result<Model> repeating = loadGltf(path("plain.gltf").string());
    ASSERT_TRUE(repeating) << repeating.error().message();
    EXPECT_EQ(repeating->materials[0].albedoWrap, TextureWraps{});  // no sampler: repeat

    b.doc["textures"][0]["sampler"] = 5;
    b.writeGltf(path("far.gltf"));
    expectError(path("far.gltf"), "sampler 5 is out of range");
    b.doc["textures"][0]["sampler"] = 0;
    b.doc["samplers"][0]["wrapS"] = 9729;  // GL_LINEAR: a filter, not a wrap
    b.writeGltf(path("odd.gltf"));
    expectError(path("odd.gltf"), "sampler 0: wrapS 9729 is not 33071, 33648 or 10497");
}

// glTF 2.0 §3.2: a file of another version, or one asking for a later minor
// version, is refused in one line (a 1.0 file used to read "no triangles").
TEST_F(GltfTest, OtherVersionsAreRefusedByName) {
    for (const auto& [asset, message] : {std::pair{json{{"version", "1.0"}}, "glTF 1.0 is not supported"},
                                         std::pair{json{{"version", "2.0"}, {"minVersion", "2.1"}}, "asset.minVersion 2.1"}}) {
        GltfBuilder b = quadBuilder(kUnsignedShort);
        b.doc["asset"] = asset;
        b.writeGltf(path("version.gltf"));
        expectError(path("version.gltf"), std::string("version.gltf: ") + message);
    }
}

// Values glTF 2.0 forbids, which used to load as something else: a default
// scene out of range (scene 0 was drawn), unsigned-integer colours not
// normalized (read up to 255, the albedo saturated), a base colour factor
// outside [0, 1]. Each is refused in one line naming the value.
TEST_F(GltfTest, ValuesTheSpecificationForbidsAreRefusedByName) {
    GltfBuilder scene = quadBuilder(kUnsignedShort);
    scene.doc["scene"] = 5;
    scene.writeGltf(path("scene.gltf"));
    expectError(path("scene.gltf"), "scene 5 is out of range (the file has 1 scenes)");

    GltfBuilder colours = quadBuilder(kUnsignedShort);
    const std::vector<uint8_t> bytes(16, 200);
    colours.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = colours.accessor(bytes, kUnsignedByte, "VEC4", 4);
    colours.writeGltf(path("colours.gltf"));
    expectError(path("colours.gltf"), "holds unsigned integers but is not normalized");

    GltfBuilder factor = quadBuilder(kUnsignedShort);
    factor.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {5.0, 0.5, 0.5, 1.0}}}}}};
    factor.doc["meshes"][0]["primitives"][0]["material"] = 0;
    factor.writeGltf(path("factor.gltf"));
    expectError(path("factor.gltf"), "material 0: baseColorFactor[0] 5 is outside [0, 1]");
}

TEST_F(GltfTest, QuantizedUvsAreScaledBackByTheirTextureTransform) {
    writeTestPng(path("albedo.png"));
    // As gltfpack writes them: UVs as normalised uint16 of (uv - offset) / scale, with the
    // transform restoring them (KHR_mesh_quantization with KHR_texture_transform).
    const glm::vec2 offset(-0.25f, -1.0f), scale(1.5f, 2.0f);  // spans [-0.25, 1.25] and [-1, 1]
    std::vector<uint16_t> quantized;
    for (size_t i = 0; i < kQuadUvs.size(); ++i)
        quantized.push_back(uint16_t(std::lround((kQuadUvs[i] - offset[int(i % 2)]) / scale[int(i % 2)] * 65535.0)));
    GltfBuilder b = texturedQuad({{"offset", {offset.x, offset.y}}, {"scale", {scale.x, scale.y}}});
    const int uvs = b.accessor(quantized, kUnsignedShort, "VEC2", 4);
    b.doc["accessors"][uvs]["normalized"] = true;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uvs;
    b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    b.writeGltf(path("quantized.gltf"));
    Result<Model> model = loadGltf(path("quantized.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    // 16-bit quantization of a span of 1 / scale: within half a step of 1/65535.
    for (size_t v = 0; v < 4; ++v) {
        const glm::vec2 expected(kQuadUvs[2 * v], kQuadUvs[2 * v + 1]);
        EXPECT_NEAR(model->mesh.vertices[v].uv.x, expected.x, 0.5f * scale.x / 65535.0f + 1e-7f) << v;
        EXPECT_NEAR(model->mesh.vertices[v].uv.y, expected.y, 0.5f * scale.y / 65535.0f + 1e-7f) << v;
    }
}

TEST_F(GltfTest, MalformedTextureTransformIsRefusedNamingTheMap) {
    writeTestPng(path("albedo.png"));
    texturedQuad({{"scale", {1.0}}}).writeGltf(path("bad_transform.gltf"));
    Result<Model> model = loadGltf(path("bad_transform.gltf").string());
    ASSERT_FALSE(model);
    EXPECT_NE(model.error().message().find(
                  "material 0 baseColorTexture: KHR_texture_transform scale must be an array of two numbers"),
              std::string::npos)
        << model.error().message();
}

// glTF 2.0 §3.6.2.3: a sparse accessor is its base (a bufferView, or zeros) with
// listed elements replaced; Blender writes morph targets this way.
TEST_F(GltfTest, SparseMorphTargetWithoutBaseMovesOnlyItsListedVertices) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    const int indexView = b.imageView({1, 0, 3, 0});  // uint16 vertices 1 and 3
    std::vector<unsigned char> deltas(2 * 3 * sizeof(float));
    const float values[6] = {0, 0, 2, 0, 0, 4};
    std::memcpy(deltas.data(), values, sizeof values);
    const int valueView = b.imageView(deltas);
    b.doc["accessors"].push_back({{"componentType", kFloat},
                                  {"count", 4},
                                  {"type", "VEC3"},
                                  {"sparse",
                                   {{"count", 2},
                                    {"indices", {{"bufferView", indexView}, {"componentType", kUnsignedShort}}},
                                    {"values", {{"bufferView", valueView}}}}}});
    b.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", b.doc["accessors"].size() - 1}}};
    b.doc["meshes"][0]["weights"] = {0.5};
    b.writeGltf(path("sparse.gltf"));
    Result<Model> model = loadGltf(path("sparse.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    // Vertices 0 and 2 keep z = 0 (zeros); 1 and 3 move by 0.5 x their delta.
    const float expected[4] = {0.0f, 1.0f, 0.0f, 2.0f};
    for (size_t v = 0; v < 4; ++v) EXPECT_NEAR(model->mesh.vertices[v].position.z, expected[v], 1e-6f) << v;
}

TEST_F(GltfTest, SparseAccessorReplacesElementsOfItsBase) {
    GltfBuilder b = quadBuilder(kUnsignedShort);
    // The UVs again, with vertex 2's replaced by (0.5, 0.25) through a uint8 index.
    const int indexView = b.imageView({2});
    std::vector<unsigned char> uv(2 * sizeof(float));
    const float replacement[2] = {0.5f, 0.25f};
    std::memcpy(uv.data(), replacement, sizeof replacement);
    const int valueView = b.imageView(uv);
    json& uvs = b.doc["accessors"][b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"].get<int>()];
    uvs["sparse"] = {{"count", 1},
                     {"indices", {{"bufferView", indexView}, {"componentType", kUnsignedByte}}},
                     {"values", {{"bufferView", valueView}}}};
    b.writeGltf(path("sparse_uv.gltf"));
    Result<Model> model = loadGltf(path("sparse_uv.gltf").string());
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_EQ(model->mesh.vertices[2].uv, glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(model->mesh.vertices[0].uv, glm::vec2(kQuadUvs[0], kQuadUvs[1]));
    EXPECT_EQ(model->mesh.vertices[3].uv, glm::vec2(kQuadUvs[6], kQuadUvs[7]));
}

TEST_F(GltfTest, BadSparseAccessorsAreRefusedNamingTheAccessor) {
    struct Case {
        const char* name;
        std::vector<unsigned char> indices;
        int count;
        const char* message;
    };
    const Case cases[] = {
        {"index out of range", {9}, 1, "sparse: index 9 at 0 is out of range for 4 elements"},
        {"values past their view", {0, 1}, 2, "sparse values (24 bytes at 0) runs past the end of bufferView"},
        {"count above the accessor's", {0, 1, 2, 3, 0}, 5, "sparse count 5 is not in [1, 4]"},
    };
    for (const Case& c : cases) {
        GltfBuilder b = quadBuilder(kUnsignedShort);
        const int indexView = b.imageView(c.indices);
        const int valueView = b.imageView(std::vector<unsigned char>(12, 0));  // one VEC3 of floats
        b.doc["accessors"].push_back({{"componentType", kFloat},
                                      {"count", 4},
                                      {"type", "VEC3"},
                                      {"sparse",
                                       {{"count", c.count},
                                        {"indices", {{"bufferView", indexView}, {"componentType", kUnsignedByte}}},
                                        {"values", {{"bufferView", valueView}}}}}});
        b.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", b.doc["accessors"].size() - 1}}};
        b.writeGltf(path("bad_sparse.gltf"));
        Result<Model> model = loadGltf(path("bad_sparse.gltf").string());
        ASSERT_FALSE(model) << c.name;
        EXPECT_NE(model.error().message().find(c.message), std::string::npos) << c.name << ": " << model.error().message();
        EXPECT_NE(model.error().message().find("bad_sparse.gltf"), std::string::npos) << c.name;
    }
}

// KHR_texture_basisu: KTX2 textures have no Debian decoder. A texture with only a KTX2 source
// is skipped with one warning naming the map and how to convert; one with a PNG fallback in
// `source` uses it; the file loads either way.
TEST_F(GltfTest, Ktx2TexturesAreSkippedWithOneWarningAndFallbacksUsed) {
    writeTestPng(path("albedo.png"));
    GltfBuilder b = quadBuilder(kUnsignedShort);
    b.doc["images"] = {{{"uri", "skin.ktx2"}, {"mimeType", "image/ktx2"}}, {{"uri", "albedo.png"}}};
    b.doc["textures"] = {{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}},
                         {{"source", 1}, {"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}};
    b.doc["materials"] = {{{"name", "Skin"},
                           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {0.8, 0.5, 0.4, 1.0}}}}},
                          {{"name", "Cloth"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}}};
    json second = b.doc["meshes"][0]["primitives"][0];
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    second["material"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(second);
    b.doc["extensionsUsed"] = {"KHR_texture_basisu"};
    b.doc["extensionsRequired"] = {"KHR_texture_basisu"};
    b.writeGltf(path("ktx2.gltf"));
    ::testing::internal::CaptureStderr();
    Result<Model> model = loadGltf(path("ktx2.gltf").string());
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->materials.size(), 2u);
    EXPECT_TRUE(model->materials[0].albedoMap.empty());
    EXPECT_EQ(model->materials[0].baseColourFactor, glm::vec4(0.8f, 0.5f, 0.4f, 1.0f));
    EXPECT_FALSE(model->materials[1].albedoMap.empty());  // the PNG fallback
    EXPECT_NE(err.find("ktx2.gltf: material 0 'Skin' baseColorTexture: texture 0 is KTX2 (KHR_texture_basisu), which "
                       "Dermis cannot decode; drawn with the material's factors. Re-export with PNG or JPEG textures"),
              std::string::npos)
        << err;
    EXPECT_EQ(err.find("texture 1 is KTX2"), std::string::npos) << err;
}

// The scene's scale limit holds through every glTF door (core/Limits.h,
// checkTransformScale): a node's composed scale, a joint's, an inverse bind
// matrix and an animated scale. 1e30 once rendered half a plane.
TEST_F(GltfTest, ScalesOutsideTheCharacterLimitAreRefusedWhateverTheirSource) {
    GltfBuilder node = quadBuilder(kUnsignedShort);
    node.doc["nodes"][0]["scale"] = {1e30, 1.0, 1.0};
    node.writeGltf(path("node.gltf"));
    expectError(path("node.gltf"), "node 0: its composed scale 1e+30 (axis x) is outside [1e-06, 1e+06]");

    // Each factor alone is allowed; their product is not.
    GltfBuilder composed = quadBuilder(kUnsignedShort);
    composed.doc["nodes"][0]["scale"] = {1.0, 1e4, 1.0};
    composed.doc["nodes"].push_back({{"name", "parent"}, {"scale", {1.0, 1e4, 1.0}}, {"children", {0}}});
    composed.doc["scenes"][0]["nodes"] = {1};
    composed.writeGltf(path("composed.gltf"));
    expectError(path("composed.gltf"), "node 0: its composed scale 1e+08 (axis y)");

    GltfBuilder inverseBind = skinnedQuad(kQuadJoints, kQuadWeights);
    const std::vector<float> huge = {1e30f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                     1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};
    inverseBind.doc["skins"][0]["inverseBindMatrices"] = inverseBind.accessor(huge, kFloat, "MAT4", 2);
    inverseBind.writeGltf(path("bind.gltf"));
    expectError(path("bind.gltf"), "skin 0 inverse bind matrix 0: its composed scale 1e+30");

    GltfBuilder animated = skinnedQuad(kQuadJoints, kQuadWeights);
    const int times = animated.accessor(std::vector<float>{0.0f, 1.0f}, kFloat, "SCALAR", 2);
    const int scales = animated.vec3({1, 1, 1, 1, 1e-9f, 1});
    animated.doc["animations"] = {{{"name", "shrink"},
                                   {"samplers", {{{"input", times}, {"output", scales}, {"interpolation", "LINEAR"}}}},
                                   {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "scale"}}}}}}}};
    animated.writeGltf(path("animated.gltf"));
    expectError(path("animated.gltf"), "key 1: its composed scale 1e-09 (axis y)");

    // Exactly 0 is how exporters hide a part: it loads.
    GltfBuilder hidden = quadBuilder(kUnsignedShort);
    hidden.doc["nodes"][0]["scale"] = {0.0, 0.0, 0.0};
    hidden.writeGltf(path("hidden.gltf"));
    EXPECT_TRUE(loadGltf(path("hidden.gltf").string()));
}
