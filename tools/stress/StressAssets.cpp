// The files stress cases load: a glTF with degenerate triangles and zero
// normals, and images holding NaN and Inf texels.
#include "core/Image.h"
#include "stress/StressCases.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
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

// A 10 cm quad split into two good triangles, plus a zero-area triangle (three
// equal corners), a collinear sliver, and every normal zero.
Status writeDegenerateGltf(const std::string& path) {
    const std::vector<float> positions = {-0.05f, 0, -0.05f, 0.05f, 0, -0.05f, 0.05f, 0, 0.05f, -0.05f, 0, 0.05f,
                                          0, 0, 0, 0, 0, 0, 0, 0, 0, -0.05f, 0, 0, 0, 0, 0, 0.05f, 0, 0};
    const std::vector<float> normals(positions.size(), 0.0f);
    const std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1, 0.5f};
    const std::vector<uint16_t> indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 7, 8, 9};
    std::vector<unsigned char> bytes;
    append(bytes, positions);
    append(bytes, normals);
    append(bytes, uvs);
    append(bytes, indices);
    const size_t p = positions.size() * 4, n = normals.size() * 4, t = uvs.size() * 4, i = indices.size() * 2;
    std::ofstream out(path);
    out << R"({"asset": {"version": "2.0"},
      "buffers": [{"byteLength": )" << bytes.size() << R"(, "uri": "data:application/octet-stream;base64,)"
        << base64(bytes) << R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" << p << R"(},
                      {"buffer": 0, "byteOffset": )" << p << R"(, "byteLength": )" << n << R"(},
                      {"buffer": 0, "byteOffset": )" << p + n << R"(, "byteLength": )" << t << R"(},
                      {"buffer": 0, "byteOffset": )" << p + n + t << R"(, "byteLength": )" << i << R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 10, "type": "VEC3",
                     "min": [-0.05, 0, -0.05], "max": [0.05, 0, 0.05]},
                    {"bufferView": 1, "componentType": 5126, "count": 10, "type": "VEC3"},
                    {"bufferView": 2, "componentType": 5126, "count": 10, "type": "VEC2"},
                    {"bufferView": 3, "componentType": 5123, "count": 12, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    if (!out) return makeError(path, "cannot write the stress glTF");
    return success();
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
    if (Status s = writeDegenerateGltf(directory + "/degenerate.gltf"); !s.ok()) return s;
    if (Status s = saveImage(directory + "/nan_albedo.exr", nonFiniteImage(ColourSpace::Linear, glm::vec4(0.6f, 0.4f, 0.3f, 1.0f)));
        !s.ok()) {
        return s;
    }
    return saveImage(directory + "/nan_normal.exr", nonFiniteImage(ColourSpace::Linear, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f)));
}

}  // namespace dermis::stress
