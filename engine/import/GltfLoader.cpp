#include "import/GltfLoader.h"

#include "core/Log.h"
#include "mesh/Tangents.h"

// The one translation unit that compiles tinygltf. Images are not decoded by
// tinygltf: its loader callback only keeps the encoded bytes of data URIs, and
// the maps a material needs are decoded afterwards through OpenImageIO, from
// buffer views this file has bounds-checked or from files beside the glTF.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

namespace dermis {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxFileBytes = size_t(1) << 31;
// Caps on the merged mesh: node instancing could otherwise multiply a valid
// mesh into an unbounded allocation.
constexpr size_t kMaxVertices = size_t(1) << 24;
constexpr size_t kMaxIndices = size_t(3) << 25;
constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr size_t kGlbHeaderBytes = 12;
constexpr size_t kGlbChunkHeaderBytes = 8;
constexpr size_t kMaxMessageLength = 300;
// tinygltf copies "extras" and "extensions" into its Value tree recursively,
// one stack frame per level, so deep nesting would overflow the stack.
constexpr size_t kMaxJsonNesting = 256;

std::string oneLine(const std::string& text) {
    std::string line;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!line.empty() && line.back() != ';' && line.back() != ' ') line += "; ";
        } else {
            // Parser messages can quote raw bytes of a corrupt file.
            line += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
        }
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
    // Parser messages quote the input, which may be a megabyte data URI.
    if (line.size() > kMaxMessageLength) line = line.substr(0, kMaxMessageLength) + "...";
    return line;
}

// The deepest nesting of arrays and objects in JSON text (brackets inside
// strings do not count); malformed text is left for the parser to report.
size_t jsonNestingDepth(const char* text, size_t size) {
    size_t depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

std::string quoted(const std::string& name) { return name.empty() ? std::string() : " '" + name + "'"; }

Result<std::vector<unsigned char>> readWholeFile(const std::string& path) {
    std::error_code error;
    if (!fs::exists(path, error)) return makeError(path, "file not found");
    if (!fs::is_regular_file(path, error)) return makeError(path, "not a regular file");
    uintmax_t size = fs::file_size(path, error);
    if (error) return makeError(path, "cannot read size: " + error.message());
    if (size > kMaxFileBytes) return makeError(path, "file is larger than 2 GiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError(path, "cannot open file");
    std::vector<unsigned char> bytes(static_cast<size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (static_cast<uintmax_t>(in.gcount()) != size) return makeError(path, "could not read the whole file");
    return bytes;
}

// tinygltf file-system callbacks. It looks for a buffer beside the glTF and
// then in the working directory; accepting only absolute candidates (the
// glTF's folder is passed absolute) drops the second, surprising search.
bool fileExistsCallback(const std::string& path, void*) {
    std::error_code error;
    return fs::path(path).is_absolute() && fs::is_regular_file(path, error);
}

std::string expandFilePathCallback(const std::string& path, void*) { return path; }

bool readWholeFileCallback(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    Result<std::vector<unsigned char>> bytes = readWholeFile(path);
    if (!bytes) {
        if (err) *err += bytes.error().what;
        return false;
    }
    *out = std::move(bytes.value());
    return true;
}

bool writeWholeFileCallback(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

// Keeps data-URI bytes (a copy tinygltf owns); buffer-view images are left
// for decodeImage(), which checks the view against its buffer first.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

uint32_t readU32(const std::vector<unsigned char>& bytes, size_t offset) {
    return uint32_t(bytes[offset]) | uint32_t(bytes[offset + 1]) << 8 | uint32_t(bytes[offset + 2]) << 16 |
           uint32_t(bytes[offset + 3]) << 24;
}

struct GlbLayout {
    size_t length = 0;  // bytes the header claims, never more than the file holds
    size_t jsonOffset = 0;
    size_t jsonLength = 0;
};

// tinygltf checks the GLB chunks too, but lets a BIN chunk run 8 bytes past
// the end; checking here first also gives clearer messages.
Result<GlbLayout> checkGlb(const std::vector<unsigned char>& bytes, const std::string& path) {
    const size_t size = bytes.size();
    if (size < kGlbHeaderBytes + kGlbChunkHeaderBytes)
        return makeError(path, "truncated GLB: " + std::to_string(size) + " bytes is shorter than its headers");
    uint32_t version = readU32(bytes, 4);
    if (version != 2) return makeError(path, "GLB version " + std::to_string(version) + " is not supported");
    GlbLayout layout;
    layout.length = readU32(bytes, 8);
    if (layout.length > size)
        return makeError(path, "truncated GLB: header says " + std::to_string(layout.length) + " bytes, file has " +
                                   std::to_string(size));
    layout.jsonLength = readU32(bytes, 12);
    layout.jsonOffset = kGlbHeaderBytes + kGlbChunkHeaderBytes;
    if (readU32(bytes, 16) != kGlbJsonChunk) return makeError(path, "GLB's first chunk is not JSON");
    size_t jsonEnd = layout.jsonOffset + layout.jsonLength;
    if (jsonEnd > layout.length) return makeError(path, "truncated GLB: the JSON chunk runs past the end");
    if (jsonEnd < layout.length) {
        if (jsonEnd + kGlbChunkHeaderBytes > layout.length)
            return makeError(path, "truncated GLB: no room for the BIN chunk header");
        size_t binLength = readU32(bytes, jsonEnd);
        if (jsonEnd + kGlbChunkHeaderBytes + binLength > layout.length)
            return makeError(path, "truncated GLB: the BIN chunk runs past the end");
    }
    return layout;
}

std::string percentDecode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// Turns tinygltf's multi-line error into one line, naming the buffer when a
// buffer file is missing ("buffer 0 'x.bin' not found").
std::string describeLoadError(const std::string& err, const std::string& json) {
    const std::string notFound = "File not found : ";
    size_t at = err.find(notFound);
    if (at != std::string::npos) {
        size_t start = at + notFound.size();
        std::string file = err.substr(start, err.find('\n', start) - start);
        nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
        if (document.is_object() && document.contains("buffers") && document["buffers"].is_array()) {
            const nlohmann::json& buffers = document["buffers"];
            for (size_t i = 0; i < buffers.size(); ++i) {
                const nlohmann::json& buffer = buffers[i];
                if (buffer.is_object() && buffer.contains("uri") && buffer["uri"].is_string() &&
                    percentDecode(buffer["uri"].get<std::string>()) == file)
                    return "buffer " + std::to_string(i) + " '" + file + "' not found";
            }
        }
        return "buffer file '" + file + "' not found";
    }
    std::string line = oneLine(err);
    if (line.find("parse_error") != std::string::npos) return "malformed JSON: " + line;
    return line.empty() ? "tinygltf could not load the file" : line;
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "a matrix or unknown type";
    }
}

float decodeComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float value;
            std::memcpy(&value, p, sizeof value);
            return value;
        }
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: {
            double value;
            std::memcpy(&value, p, sizeof value);
            return static_cast<float>(value);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? float(p[0]) / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            float value = float(static_cast<int8_t>(p[0]));
            return normalized ? std::max(value / 127.0f, -1.0f) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t value;
            std::memcpy(&value, p, sizeof value);
            return normalized ? float(value) / 65535.0f : float(value);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t value;
            std::memcpy(&value, p, sizeof value);
            return normalized ? std::max(float(value) / 32767.0f, -1.0f) : float(value);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t value;
            std::memcpy(&value, p, sizeof value);
            return normalized ? float(double(value) / 4294967295.0) : float(value);
        }
        default:
            return 0.0f;
    }
}

glm::vec3 normalizeOr(const glm::vec3& v, const glm::vec3& fallback) {
    float lengthSq = glm::dot(v, v);
    if (!(lengthSq > 1e-30f) || !std::isfinite(lengthSq)) return fallback;
    return v / std::sqrt(lengthSq);
}

struct AccessorView {
    const unsigned char* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
    size_t componentSize = 0;
    int components = 0;
};

// A primitive's triangle list before it joins the merged mesh.
struct Piece {
    MeshData mesh;
    std::vector<bool> badNormal;  // missing, zero or not finite after transform
    std::vector<bool> badTangent;
};

class GltfConverter {
public:
    GltfConverter(const tinygltf::Model& gltf, std::string path)
        : mGltf(gltf), mPath(std::move(path)), mBaseDir(fs::absolute(mPath).parent_path()) {}

    Result<Model> convert() {
        if (Status status = checkExtensions(); !status) return status.error();
        if (Status status = addScene(); !status) return status.error();
        if (mModel.mesh.triangleCount() == 0) return fail("no triangles in the scene");
        warnOfUnappliedAnimation();
        if (Status status = loadMaps(); !status) return status.error();
        if (mModel.mesh.name.empty()) mModel.mesh.name = fs::path(mPath).stem().string();
        return std::move(mModel);
    }

private:
    Error fail(const std::string& what) const { return makeError(mPath, what); }

    // Skins, clips and morph targets are not applied yet (engine/anim holds
    // the sampling and skinning); until they are, say so instead of dropping
    // them silently.
    void warnOfUnappliedAnimation() const {
        size_t targets = 0;
        for (const tinygltf::Mesh& mesh : mGltf.meshes)
            for (const tinygltf::Primitive& primitive : mesh.primitives) targets = std::max(targets, primitive.targets.size());
        std::vector<std::string> parts;
        if (!mGltf.skins.empty()) parts.push_back(std::to_string(mGltf.skins.size()) + " skin(s)");
        if (!mGltf.animations.empty()) {
            std::string clips;
            for (const tinygltf::Animation& animation : mGltf.animations)
                clips += (clips.empty() ? "" : ", ") + (animation.name.empty() ? std::string("unnamed") : animation.name);
            parts.push_back(std::to_string(mGltf.animations.size()) + " animation(s) (" + clips + ")");
        }
        if (targets > 0) parts.push_back(std::to_string(targets) + " morph target(s)");
        if (parts.empty()) return;
        std::string list;
        for (size_t i = 0; i < parts.size(); ++i) list += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
        log::warn(mPath + ": " + list + " not applied yet: the mesh renders in its bind pose");
    }

    Status checkExtensions() {
        for (const std::string& extension : mGltf.extensionsRequired) {
            if (extension == "KHR_mesh_quantization") continue;
            if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression")
                return fail("requires " + extension + ", which is not supported");
            log::warn(mPath + ": requires " + extension + ", which is ignored");
        }
        return success();
    }

    std::vector<int> rootNodes() const {
        int scene = mGltf.defaultScene;
        if (scene < 0 || scene >= static_cast<int>(mGltf.scenes.size())) scene = mGltf.scenes.empty() ? -1 : 0;
        if (scene >= 0) return mGltf.scenes[static_cast<size_t>(scene)].nodes;
        std::vector<bool> isChild(mGltf.nodes.size(), false);
        for (const tinygltf::Node& node : mGltf.nodes)
            for (int child : node.children)
                if (child >= 0 && static_cast<size_t>(child) < isChild.size())
                    isChild[static_cast<size_t>(child)] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < isChild.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
        return roots;
    }

    Result<glm::mat4> localTransform(int index, const tinygltf::Node& node) const {
        const std::string where = "node " + std::to_string(index);
        glm::mat4 local(1.0f);
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16)
                return fail(where + ": matrix has " + std::to_string(node.matrix.size()) + " values, not 16");
            for (int i = 0; i < 16; ++i) local[i / 4][i % 4] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);
        } else {
            if (!node.translation.empty() && node.translation.size() != 3)
                return fail(where + ": translation needs 3 values");
            if (!node.rotation.empty() && node.rotation.size() != 4) return fail(where + ": rotation needs 4 values");
            if (!node.scale.empty() && node.scale.size() != 3) return fail(where + ": scale needs 3 values");
            glm::vec3 translation(0.0f), scale(1.0f);
            glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
            for (int i = 0; i < 3 && !node.translation.empty(); ++i)
                translation[i] = static_cast<float>(node.translation[static_cast<size_t>(i)]);
            for (int i = 0; i < 3 && !node.scale.empty(); ++i)
                scale[i] = static_cast<float>(node.scale[static_cast<size_t>(i)]);
            if (!node.rotation.empty()) {
                // glTF stores x, y, z, w; glm::quat's constructor takes w first.
                rotation = glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                     static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
                float length = glm::length(rotation);
                if (!(length > 0.0f) || !std::isfinite(length))
                    return fail(where + ": rotation is not a valid quaternion");
                rotation = rotation / length;
            }
            local = glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
                    glm::scale(glm::mat4(1.0f), scale);
        }
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(local[c][r])) return fail(where + ": transform is not finite");
        return local;
    }

    Status addScene() {
        std::vector<bool> visited(mGltf.nodes.size(), false);
        std::vector<std::pair<int, glm::mat4>> stack;
        std::vector<int> roots = rootNodes();
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::mat4(1.0f));
        while (!stack.empty()) {
            auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || static_cast<size_t>(index) >= mGltf.nodes.size())
                return fail("node " + std::to_string(index) + " is out of range (" +
                            std::to_string(mGltf.nodes.size()) + " nodes)");
            if (visited[static_cast<size_t>(index)])
                return fail("node " + std::to_string(index) + " is reached twice (a cycle or a shared child)");
            visited[static_cast<size_t>(index)] = true;
            const tinygltf::Node& node = mGltf.nodes[static_cast<size_t>(index)];
            Result<glm::mat4> local = localTransform(index, node);
            if (!local) return local.error();
            glm::mat4 world = parent * local.value();
            if (node.mesh >= 0) {
                if (static_cast<size_t>(node.mesh) >= mGltf.meshes.size())
                    return fail("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) +
                                " is out of range");
                if (Status status = addMesh(node.mesh, world); !status) return status;
            }
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
                stack.emplace_back(*child, world);
        }
        return success();
    }

    Status addMesh(int meshIndex, const glm::mat4& world) {
        const tinygltf::Mesh& mesh = mGltf.meshes[static_cast<size_t>(meshIndex)];
        if (mModel.mesh.name.empty()) mModel.mesh.name = mesh.name;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where = "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p);
            if (Status status = addPrimitive(where, mesh.primitives[p], world); !status) return status;
        }
        return success();
    }

    Result<AccessorView> viewAccessor(int index, const std::string& where) const {
        const std::string name = where + ": accessor " + std::to_string(index);
        if (index < 0 || static_cast<size_t>(index) >= mGltf.accessors.size())
            return fail(name + " is out of range (" + std::to_string(mGltf.accessors.size()) + " accessors)");
        const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
        if (accessor.sparse.isSparse) return fail(name + " is sparse, which is not supported");
        int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
        int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
        if (componentSize <= 0 || components <= 0) return fail(name + " has an invalid type or component type");
        AccessorView view;
        view.count = accessor.count;
        view.componentSize = static_cast<size_t>(componentSize);
        view.components = components;
        if (accessor.count == 0) return view;
        if (accessor.bufferView < 0 || static_cast<size_t>(accessor.bufferView) >= mGltf.bufferViews.size())
            return fail(name + " has no valid bufferView");
        const tinygltf::BufferView& bufferView = mGltf.bufferViews[static_cast<size_t>(accessor.bufferView)];
        const std::string viewName = "bufferView " + std::to_string(accessor.bufferView);
        if (bufferView.buffer < 0 || static_cast<size_t>(bufferView.buffer) >= mGltf.buffers.size())
            return fail(viewName + ": buffer " + std::to_string(bufferView.buffer) + " is out of range");
        const std::vector<unsigned char>& buffer = mGltf.buffers[static_cast<size_t>(bufferView.buffer)].data;
        if (bufferView.byteOffset > buffer.size() || bufferView.byteLength > buffer.size() - bufferView.byteOffset)
            return fail(viewName + " (" + std::to_string(bufferView.byteLength) + " bytes at " +
                        std::to_string(bufferView.byteOffset) + ") is outside its buffer of " +
                        std::to_string(buffer.size()) + " bytes");
        const size_t elementSize = view.componentSize * static_cast<size_t>(components);
        view.stride = bufferView.byteStride == 0 ? elementSize : bufferView.byteStride;
        if (view.stride < elementSize)
            return fail(viewName + ": byteStride " + std::to_string(view.stride) + " is smaller than the " +
                        std::to_string(elementSize) + "-byte elements of accessor " + std::to_string(index));
        // Checked before anything is allocated: count is bounded by the view.
        if (bufferView.byteLength < elementSize || accessor.byteOffset > bufferView.byteLength - elementSize ||
            accessor.count - 1 > (bufferView.byteLength - elementSize - accessor.byteOffset) / view.stride)
            return fail(name + " (" + std::to_string(accessor.count) + " elements) runs past the end of " + viewName);
        view.data = buffer.data() + bufferView.byteOffset + accessor.byteOffset;
        return view;
    }

    Result<std::vector<float>> readFloats(int index, int type, const std::string& where) const {
        Result<AccessorView> view = viewAccessor(index, where);
        if (!view) return view.error();
        const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
        const std::string name = where + ": accessor " + std::to_string(index);
        if (accessor.type != type)
            return fail(name + " is " + typeName(accessor.type) + ", expected " + typeName(type));
        std::vector<float> values(view->count * static_cast<size_t>(view->components));
        for (size_t i = 0; i < view->count; ++i) {
            for (int c = 0; c < view->components; ++c) {
                float value =
                    decodeComponent(view->data + i * view->stride + static_cast<size_t>(c) * view->componentSize,
                                    accessor.componentType, accessor.normalized);
                if (!std::isfinite(value)) return fail(name + " holds a value that is not finite");
                values[i * static_cast<size_t>(view->components) + static_cast<size_t>(c)] = value;
            }
        }
        return values;
    }

    Result<std::vector<uint32_t>> readIndices(int index, size_t vertexCount, const std::string& where) const {
        Result<AccessorView> view = viewAccessor(index, where);
        if (!view) return view.error();
        const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
        const std::string name = where + ": index accessor " + std::to_string(index);
        if (accessor.type != TINYGLTF_TYPE_SCALAR) return fail(name + " is not SCALAR");
        if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            return fail(name + " must hold unsigned 8-, 16- or 32-bit integers");
        std::vector<uint32_t> indices(view->count);
        for (size_t i = 0; i < view->count; ++i) {
            const unsigned char* p = view->data + i * view->stride;
            uint32_t value = 0;
            if (view->componentSize == 1) {
                value = p[0];
            } else if (view->componentSize == 2) {
                uint16_t short16;
                std::memcpy(&short16, p, sizeof short16);
                value = short16;
            } else {
                std::memcpy(&value, p, sizeof value);
            }
            if (value >= vertexCount)
                return fail(name + ": index " + std::to_string(value) + " at " + std::to_string(i) +
                            " is out of range for " + std::to_string(vertexCount) + " vertices");
            indices[i] = value;
        }
        return indices;
    }

    // Triangle lists from lists, strips and fans (glTF 2.0 §3.7.2.1).
    static Result<std::vector<uint32_t>> toTriangleList(std::vector<uint32_t> indices, int mode,
                                                        const std::string& where, const std::string& path) {
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (indices.size() % 3 != 0)
                return makeError(path,
                                 where + ": " + std::to_string(indices.size()) + " indices is not a multiple of 3");
            return indices;
        }
        std::vector<uint32_t> list;
        if (indices.size() < 3) return list;
        list.reserve((indices.size() - 2) * 3);
        for (size_t i = 0; i + 2 < indices.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                size_t odd = i % 2;
                list.insert(list.end(), {indices[i], indices[i + 1 + odd], indices[i + 2 - odd]});
            } else {
                list.insert(list.end(), {indices[i + 1], indices[i + 2], indices[0]});
            }
        }
        return list;
    }

    Status addPrimitive(const std::string& where, const tinygltf::Primitive& primitive, const glm::mat4& world) {
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            log::warn(mPath + ": " + where + " is not made of triangles (mode " + std::to_string(primitive.mode) +
                      "); skipped");
            return success();
        }
        auto attribute = [&](const char* name) {
            auto it = primitive.attributes.find(name);
            return it == primitive.attributes.end() ? -1 : it->second;
        };
        const int positionAccessor = attribute("POSITION");
        if (positionAccessor < 0) return fail(where + " has no POSITION attribute");

        Result<AccessorView> positionView = viewAccessor(positionAccessor, where);
        if (!positionView) return positionView.error();
        const size_t vertexCount = positionView->count;
        if (vertexCount == 0) return success();
        if (vertexCount > kMaxVertices - mModel.mesh.vertices.size())
            return fail("the scene has more than " + std::to_string(kMaxVertices) + " vertices");

        Result<std::vector<float>> positions = readFloats(positionAccessor, TINYGLTF_TYPE_VEC3, where);
        if (!positions) return positions.error();
        std::optional<std::vector<float>> normals, uvs, tangents;
        struct Optional {
            const char* name;
            int type;
            std::optional<std::vector<float>>* out;
        };
        for (const Optional& optional :
             {Optional{"NORMAL", TINYGLTF_TYPE_VEC3, &normals}, Optional{"TEXCOORD_0", TINYGLTF_TYPE_VEC2, &uvs},
              Optional{"TANGENT", TINYGLTF_TYPE_VEC4, &tangents}}) {
            int accessor = attribute(optional.name);
            if (accessor < 0) continue;
            Result<std::vector<float>> values = readFloats(accessor, optional.type, where + " " + optional.name);
            if (!values) return values.error();
            if (mGltf.accessors[static_cast<size_t>(accessor)].count != vertexCount)
                return fail(where + ": " + optional.name + " has " +
                            std::to_string(mGltf.accessors[static_cast<size_t>(accessor)].count) +
                            " elements, POSITION has " + std::to_string(vertexCount));
            *optional.out = std::move(values.value());
        }

        std::vector<uint32_t> indices;
        if (primitive.indices >= 0) {
            Result<std::vector<uint32_t>> read = readIndices(primitive.indices, vertexCount, where);
            if (!read) return read.error();
            indices = std::move(read.value());
        } else {
            indices.resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) indices[i] = static_cast<uint32_t>(i);
        }
        Result<std::vector<uint32_t>> triangles = toTriangleList(std::move(indices), primitive.mode, where, mPath);
        if (!triangles) return triangles.error();
        if (triangles->size() > kMaxIndices - mModel.mesh.indices.size())
            return fail("the scene has more than " + std::to_string(kMaxIndices / 3) + " triangles");

        Piece piece = buildPiece(*positions, normals, uvs, tangents, world);
        piece.mesh.indices = std::move(triangles.value());
        // A mirroring transform turns counter-clockwise triangles clockwise.
        if (glm::determinant(glm::mat3(world)) < 0.0f)
            for (size_t i = 0; i + 2 < piece.mesh.indices.size(); i += 3)
                std::swap(piece.mesh.indices[i + 1], piece.mesh.indices[i + 2]);
        repairFrames(piece);

        if (primitive.material >= 0) {
            if (static_cast<size_t>(primitive.material) >= mGltf.materials.size())
                return fail(where + ": material " + std::to_string(primitive.material) + " is out of range");
            if (std::find(mUsedMaterials.begin(), mUsedMaterials.end(), primitive.material) == mUsedMaterials.end())
                mUsedMaterials.push_back(primitive.material);
        }
        append(piece.mesh);
        return success();
    }

    static Piece buildPiece(const std::vector<float>& positions, const std::optional<std::vector<float>>& normals,
                            const std::optional<std::vector<float>>& uvs,
                            const std::optional<std::vector<float>>& tangents, const glm::mat4& world) {
        const glm::mat3 linear(world);
        const float det = glm::determinant(linear);
        // The cofactor matrix is det * inverse-transpose: it maps normals
        // correctly even for a singular transform. Its sign flips under a
        // mirror, where the winding is flipped instead.
        glm::mat3 normalMatrix(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                               glm::cross(linear[0], linear[1]));
        if (det < 0.0f) normalMatrix = -normalMatrix;
        const float tangentSign = det < 0.0f ? -1.0f : 1.0f;

        Piece piece;
        const size_t count = positions.size() / 3;
        piece.mesh.vertices.resize(count);
        piece.badNormal.assign(count, !normals.has_value());
        piece.badTangent.assign(count, !tangents.has_value());
        for (size_t i = 0; i < count; ++i) {
            Vertex& v = piece.mesh.vertices[i];
            v.position =
                glm::vec3(world * glm::vec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0f));
            if (uvs) v.uv = glm::vec2((*uvs)[2 * i], (*uvs)[2 * i + 1]);
            if (normals) {
                glm::vec3 n = normalMatrix * glm::vec3((*normals)[3 * i], (*normals)[3 * i + 1], (*normals)[3 * i + 2]);
                v.normal = normalizeOr(n, glm::vec3(0.0f));
                piece.badNormal[i] = glm::dot(v.normal, v.normal) == 0.0f;
            }
            if (tangents) {
                glm::vec3 t = linear * glm::vec3((*tangents)[4 * i], (*tangents)[4 * i + 1], (*tangents)[4 * i + 2]);
                float w = (*tangents)[4 * i + 3] < 0.0f ? -tangentSign : tangentSign;
                v.tangent = glm::vec4(normalizeOr(t, glm::vec3(0.0f)), w);
                piece.badTangent[i] = glm::dot(glm::vec3(v.tangent), glm::vec3(v.tangent)) == 0.0f;
            }
        }
        return piece;
    }

    // Generates what the file lacks, and replaces only the vertices whose
    // own normal or tangent was unusable.
    static void repairFrames(Piece& piece) {
        MeshData& mesh = piece.mesh;
        auto anyBad = [](const std::vector<bool>& flags) {
            return std::find(flags.begin(), flags.end(), true) != flags.end();
        };
        if (anyBad(piece.badNormal)) {
            MeshData generated = mesh;
            generateNormals(generated);
            for (size_t i = 0; i < mesh.vertices.size(); ++i)
                if (piece.badNormal[i]) {
                    mesh.vertices[i].normal = generated.vertices[i].normal;
                    piece.badTangent[i] = true;
                }
        }
        for (size_t i = 0; i < mesh.vertices.size(); ++i) {
            if (piece.badTangent[i]) continue;
            // Orthogonalise the file's tangent against the (transformed) normal.
            Vertex& v = mesh.vertices[i];
            glm::vec3 t(v.tangent);
            t = normalizeOr(t - v.normal * glm::dot(v.normal, t), glm::vec3(0.0f));
            if (glm::dot(t, t) == 0.0f)
                piece.badTangent[i] = true;
            else
                v.tangent = glm::vec4(t, v.tangent.w);
        }
        if (anyBad(piece.badTangent)) {
            MeshData generated = mesh;
            generateTangents(generated);
            for (size_t i = 0; i < mesh.vertices.size(); ++i)
                if (piece.badTangent[i]) mesh.vertices[i].tangent = generated.vertices[i].tangent;
        }
    }

    void append(const MeshData& piece) {
        MeshData& merged = mModel.mesh;
        const uint32_t offset = static_cast<uint32_t>(merged.vertices.size());
        merged.vertices.insert(merged.vertices.end(), piece.vertices.begin(), piece.vertices.end());
        merged.indices.reserve(merged.indices.size() + piece.indices.size());
        for (uint32_t index : piece.indices) merged.indices.push_back(index + offset);
    }

    // The maps come from the first material in use with a base colour
    // texture, else the first in use with any texture.
    Status loadMaps() {
        const tinygltf::Material* chosen = nullptr;
        int chosenIndex = -1;
        for (int pass = 0; pass < 2 && !chosen; ++pass) {
            for (int index : mUsedMaterials) {
                const tinygltf::Material& material = mGltf.materials[static_cast<size_t>(index)];
                bool hasBase = material.pbrMetallicRoughness.baseColorTexture.index >= 0;
                bool hasAny = hasBase || material.normalTexture.index >= 0 ||
                              material.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0;
                if (pass == 0 ? hasBase : hasAny) {
                    chosen = &material;
                    chosenIndex = index;
                    break;
                }
            }
        }
        if (!chosen) return success();
        if (mUsedMaterials.size() > 1)
            log::warn(mPath + ": " + std::to_string(mUsedMaterials.size()) +
                      " materials in use; maps come from material " + std::to_string(chosenIndex) +
                      quoted(chosen->name));

        struct Map {
            const char* role;
            int texture;
            int texCoord;
            ColourSpace colourSpace;
            Image* out;
        };
        const tinygltf::PbrMetallicRoughness& pbr = chosen->pbrMetallicRoughness;
        for (const Map& map :
             {Map{"baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, ColourSpace::Srgb,
                  &mModel.albedoMap},
              Map{"normalTexture", chosen->normalTexture.index, chosen->normalTexture.texCoord, ColourSpace::Linear,
                  &mModel.normalMap},
              Map{"metallicRoughnessTexture", pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                  ColourSpace::Linear, &mModel.metallicRoughnessMap}}) {
            if (map.texture < 0) continue;
            const std::string where = "material " + std::to_string(chosenIndex) + " " + map.role;
            if (map.texCoord != 0)
                log::warn(mPath + ": " + where + " uses TEXCOORD_" + std::to_string(map.texCoord) +
                          "; only TEXCOORD_0 is loaded");
            if (static_cast<size_t>(map.texture) >= mGltf.textures.size())
                return fail(where + ": texture " + std::to_string(map.texture) + " is out of range");
            int source = mGltf.textures[static_cast<size_t>(map.texture)].source;
            if (source < 0 || static_cast<size_t>(source) >= mGltf.images.size())
                return fail(where + ": texture " + std::to_string(map.texture) + " has no image this loader can read");
            Result<Image> image = decodeImage(source, map.colourSpace);
            if (!image) return image.error();
            *map.out = std::move(image.value());
        }
        return success();
    }

    Result<Image> decodeImage(int index, ColourSpace colourSpace) const {
        const tinygltf::Image& image = mGltf.images[static_cast<size_t>(index)];
        const std::string label =
            "image " + std::to_string(index) + quoted(image.name.empty() ? image.uri : image.name);
        Result<Image> decoded = makeError(label, "has no data");
        if (image.bufferView >= 0) {
            if (static_cast<size_t>(image.bufferView) >= mGltf.bufferViews.size())
                return fail(label + ": bufferView " + std::to_string(image.bufferView) + " is out of range");
            const tinygltf::BufferView& view = mGltf.bufferViews[static_cast<size_t>(image.bufferView)];
            if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= mGltf.buffers.size())
                return fail(label + ": buffer " + std::to_string(view.buffer) + " is out of range");
            const std::vector<unsigned char>& buffer = mGltf.buffers[static_cast<size_t>(view.buffer)].data;
            if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
                return fail(label + ": bufferView " + std::to_string(image.bufferView) + " is outside its buffer");
            decoded = loadImageFromMemory(buffer.data() + view.byteOffset, view.byteLength, label, colourSpace);
        } else if (!image.image.empty()) {
            decoded = loadImageFromMemory(image.image.data(), image.image.size(), label, colourSpace);
        } else if (!image.uri.empty()) {
            fs::path file = mBaseDir / percentDecode(image.uri);
            std::error_code error;
            if (!fs::exists(file, error)) return fail(label + " not found (looked for " + file.string() + ")");
            decoded = loadImage(file.string(), colourSpace);
            if (!decoded) return fail(label + ": " + decoded.error().message());
        }
        if (!decoded) return fail(decoded.error().message());
        return decoded;
    }

    const tinygltf::Model& mGltf;
    std::string mPath;
    fs::path mBaseDir;
    Model mModel;
    std::vector<int> mUsedMaterials;
};

Result<Model> loadGltfUnguarded(const std::string& path) {
    Result<std::vector<unsigned char>> file = readWholeFile(path);
    if (!file) return file.error();
    std::vector<unsigned char>& bytes = file.value();

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepEncodedImage, nullptr);
    loader.SetFsCallbacks(tinygltf::FsCallbacks{fileExistsCallback, expandFilePathCallback, readWholeFileCallback,
                                                writeWholeFileCallback, nullptr});
    const std::string baseDir = fs::absolute(path).parent_path().string();
    tinygltf::Model gltf;
    std::string err, warn, json;
    std::optional<GlbLayout> glb;
    if (bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic) {
        Result<GlbLayout> layout = checkGlb(bytes, path);
        if (!layout) return layout.error();
        glb = layout.value();
        json.assign(reinterpret_cast<const char*>(bytes.data()) + glb->jsonOffset, glb->jsonLength);
    } else {
        json.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }
    if (jsonNestingDepth(json.data(), json.size()) > kMaxJsonNesting)
        return makeError(path, "JSON nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
    const bool loaded =
        glb ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), static_cast<unsigned int>(glb->length),
                                          baseDir)
            : loader.LoadASCIIFromString(&gltf, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                         baseDir);
    if (!warn.empty()) log::warn(path + ": " + oneLine(warn));
    if (!loaded) return makeError(path, describeLoadError(err, json));
    return GltfConverter(gltf, path).convert();
}

}  // namespace

Result<Model> loadGltf(const std::string& path) {
    // tinygltf and the allocations it drives may throw (bad_alloc on a hostile
    // file); a loader reports that as an error rather than ending the program.
    try {
        return loadGltfUnguarded(path);
    } catch (const std::exception& exception) {
        return makeError(path, std::string("failed to load: ") + oneLine(exception.what()));
    }
}

}  // namespace dermis
