// The files stress cases load: glTFs with degenerate triangles and zero
// normals, without normals, without UVs and with duplicate vertices, and
// images holding NaN and Inf texels.
#include "core/Image.h"
#include "core/TextFile.h"
#include "stress/StressCases.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace dermis::stress {
namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* kTable = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b0 = bytes[i];
        const uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
        out += kTable[(triple >> 18) & 63];
        out += kTable[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? kTable[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kTable[triple & 63] : '=';
    }
    return out;
}

template <class T>
void append(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
    const size_t offset = bytes.size();
    bytes.resize(offset + values.size() * sizeof(T));
    std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
}

struct GltfMesh {
    std::vector<float> positions;  // xyz
    std::vector<float> normals;    // xyz, or empty: no NORMAL attribute
    std::vector<float> uvs;        // uv, or empty: no TEXCOORD_0
    std::vector<uint16_t> indices;
};

Status writeGltf(const std::string& path, const GltfMesh& mesh) {
    std::vector<unsigned char> bytes;
    std::string views, accessors, attributes;
    const size_t count = mesh.positions.size() / 3;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (size_t v = 0; v < count; ++v) {
        const glm::vec3 p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    int index = 0;
    auto add = [&](const auto& values, const char* type, int componentType, const std::string& extra) {
        const size_t offset = bytes.size();
        append(bytes, values);
        if (index > 0) {
            views += ", ";
            accessors += ", ";
        }
        views += "{\"buffer\": 0, \"byteOffset\": " + std::to_string(offset) +
                 ", \"byteLength\": " + std::to_string(bytes.size() - offset) + "}";
        const size_t n = std::string(type) == "SCALAR" ? values.size() : count;
        accessors += "{\"bufferView\": " + std::to_string(index) + ", \"componentType\": " +
                     std::to_string(componentType) + ", \"count\": " + std::to_string(n) + ", \"type\": \"" +
                     type + "\"" + extra + "}";
        return index++;
    };
    auto bound = [](glm::vec3 v) {
        return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
    };
    attributes += "\"POSITION\": " +
                  std::to_string(add(mesh.positions, "VEC3", 5126, ", \"min\": " + bound(lo) + ", \"max\": " + bound(hi)));
    if (!mesh.normals.empty()) attributes += ", \"NORMAL\": " + std::to_string(add(mesh.normals, "VEC3", 5126, ""));
    if (!mesh.uvs.empty()) attributes += ", \"TEXCOORD_0\": " + std::to_string(add(mesh.uvs, "VEC2", 5126, ""));
    const int indices = add(mesh.indices, "SCALAR", 5123, "");
    // Atomically: two stress processes share the asset directory.
    std::ostringstream out;
    out << "{\"asset\": {\"version\": \"2.0\"},\n \"buffers\": [{\"byteLength\": " << bytes.size()
        << ", \"uri\": \"data:application/octet-stream;base64," << base64(bytes) << "\"}],\n \"bufferViews\": ["
        << views << "],\n \"accessors\": [" << accessors << "],\n \"meshes\": [{\"primitives\": [{\"attributes\": {"
        << attributes << "}, \"indices\": " << indices
        << "}]}],\n \"nodes\": [{\"mesh\": 0}], \"scenes\": [{\"nodes\": [0]}], \"scene\": 0}\n";
    return writeTextFileAtomically(path, out.str());
}

// A 10 cm quad split into two good triangles, plus a zero-area triangle (three
// equal corners), a collinear sliver, and every normal zero.
GltfMesh degenerateMesh() {
    GltfMesh m;
    m.positions = {-0.05f, 0, -0.05f, 0.05f, 0, -0.05f, 0.05f, 0, 0.05f, -0.05f, 0, 0.05f,
                   0, 0, 0, 0, 0, 0, 0, 0, 0, -0.05f, 0, 0, 0, 0, 0, 0.05f, 0, 0};
    m.normals.assign(m.positions.size(), 0.0f);
    m.uvs = {0, 0, 1, 0, 1, 1, 0, 1, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1, 0.5f};
    m.indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 7, 8, 9};
    return m;
}

// A 10 cm bump (a 5x5 grid raised 2 cm in the middle) with normals and UVs;
// the variants below drop one or the other, or list every corner of every
// triangle as a vertex of its own (same positions, indexed separately).
GltfMesh bumpMesh() {
    constexpr int kSide = 5;
    GltfMesh m;
    for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
            const float u = float(i) / (kSide - 1), v = float(j) / (kSide - 1);
            const float x = 0.1f * (u - 0.5f), z = 0.1f * (v - 0.5f);
            const float r2 = (x * x + z * z) / 0.0025f;
            m.positions.insert(m.positions.end(), {x, 0.02f * std::max(0.0f, 1.0f - r2), z});
            m.normals.insert(m.normals.end(), {0.0f, 1.0f, 0.0f});  // rough, not the bump's: only needs to be valid
            m.uvs.insert(m.uvs.end(), {u, v});
        }
    }
    for (int j = 0; j + 1 < kSide; ++j) {
        for (int i = 0; i + 1 < kSide; ++i) {
            const uint16_t a = uint16_t(j * kSide + i), b = uint16_t(a + 1), c = uint16_t(a + kSide), d = uint16_t(c + 1);
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    }
    return m;
}

GltfMesh unshared(const GltfMesh& shared) {
    GltfMesh m;
    for (uint16_t index : shared.indices) {
        m.positions.insert(m.positions.end(), &shared.positions[3 * index], &shared.positions[3 * index] + 3);
        m.normals.insert(m.normals.end(), &shared.normals[3 * index], &shared.normals[3 * index] + 3);
        m.uvs.insert(m.uvs.end(), &shared.uvs[2 * index], &shared.uvs[2 * index] + 2);
        m.indices.push_back(uint16_t(m.indices.size()));
    }
    return m;
}

Image nonFiniteImage(ColourSpace colourSpace, glm::vec4 fill) {
    Image image;
    image.width = 16;
    image.height = 16;
    image.colourSpace = colourSpace;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            glm::vec4 texel = fill;
            if ((x + y) % 3 == 0) texel = glm::vec4(nan, inf, -inf, 1.0f);
            image.texels.push_back(texel);
        }
    }
    return image;
}

}  // namespace

Status writeStressAssets(const std::string& directory) {
    GltfMesh noNormals = bumpMesh(), noUvs = bumpMesh();
    noNormals.normals.clear();
    noUvs.uvs.clear();
    const std::pair<const char*, GltfMesh> meshes[] = {
        {"degenerate", degenerateMesh()}, {"no_normals", noNormals}, {"no_uvs", noUvs}, {"duplicates", unshared(bumpMesh())}};
    for (const auto& [name, mesh] : meshes) {
        if (Status s = writeGltf(directory + "/" + name + ".gltf", mesh); !s.ok()) return s;
    }
    if (Status s = saveImage(directory + "/nan_albedo.exr", nonFiniteImage(ColourSpace::Linear, glm::vec4(0.6f, 0.4f, 0.3f, 1.0f)));
        !s.ok()) {
        return s;
    }
    return saveImage(directory + "/nan_normal.exr", nonFiniteImage(ColourSpace::Linear, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f)));
}

}  // namespace dermis::stress
