#include "import/GltfLoader.h"

#include "core/Log.h"
#include "mesh/FlatNormals.h"
#include "mesh/Tangents.h"
#include "scene/JsonReader.h"

// The one translation unit that compiles tinygltf. Images are not decoded by
// tinygltf: its loader callback only keeps the encoded bytes of data URIs, and
// the maps a material needs are decoded afterwards through OpenImageIO, from
// buffer views this file has bounds-checked or from files beside the glTF.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>
// tiny_gltf.h guards its declarations only: the headers below include it again.
#undef TINYGLTF_IMPLEMENTATION

#include "import/GltfAccessors.h"
#include "import/GltfDraco.h"
#include "import/GltfMeshopt.h"
#include "import/GltfTextureTransform.h"
#include "import/GltfRig.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

namespace dermis {
namespace {

// glTF 2.0 §5.26: a sampler's wrapS / wrapT, whose values are OpenGL's enums.
std::optional<TextureWrap> textureWrapOf(int glTFValue) {
    switch (glTFValue) {
        case 10497: return TextureWrap::Repeat;
        case 33071: return TextureWrap::ClampToEdge;
        case 33648: return TextureWrap::MirroredRepeat;
        default: return std::nullopt;
    }
}

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
    const fs::file_status status = fs::status(path, error);
    // A symlink loop is not a missing file: say what the system says.
    if (error && error != std::errc::no_such_file_or_directory) return makeError(path, "cannot open: " + error.message());
    if (!fs::exists(status)) return makeError(path, "file not found");
    if (!fs::is_regular_file(status)) return makeError(path, "not a regular file");
    uintmax_t size = fs::file_size(path, error);
    if (error) return makeError(path, "cannot read size: " + error.message());
    if (size > kMaxFileBytes) return makeError(path, "file is larger than 2 GiB");
    if (size == 0) return makeError(path, "the file is empty (0 bytes)");
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

// The GLB with its JSON chunk replaced by `json` (padded with spaces, as GLB requires)
// and the rest as it was; `layout` is updated to the new bytes.
std::vector<unsigned char> replaceGlbJson(const std::vector<unsigned char>& bytes, const GlbLayout& old,
                                          std::string json, GlbLayout* layout) {
    while (json.size() % 4) json += ' ';
    const size_t rest = old.jsonOffset + old.jsonLength;
    std::vector<unsigned char> out(bytes.begin(), bytes.begin() + long(old.jsonOffset));
    out.insert(out.end(), json.begin(), json.end());
    out.insert(out.end(), bytes.begin() + long(rest), bytes.begin() + long(old.length));
    auto writeU32 = [&out](size_t at, size_t value) {
        for (int i = 0; i < 4; ++i) out[at + size_t(i)] = static_cast<unsigned char>(uint32_t(value) >> (8 * i));
    };
    writeU32(8, out.size());
    writeU32(12, json.size());
    layout->length = out.size();
    layout->jsonLength = json.size();
    return out;
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

glm::vec3 normalizeOr(const glm::vec3& v, const glm::vec3& fallback) {
    float lengthSq = glm::dot(v, v);
    if (!(lengthSq > 1e-30f) || !std::isfinite(lengthSq)) return fallback;
    return v / std::sqrt(lengthSq);
}

// A primitive's triangle list before it joins the merged mesh.
struct Piece {
    MeshData mesh;
    std::vector<bool> badNormal;  // missing, zero or not finite after transform
    std::vector<bool> badTangent;
};

class GltfConverter {
public:
    GltfConverter(const tinygltf::Model& gltf, std::string path)
        : mGltf(gltf),
          mPath(std::move(path)),
          mBaseDir(fs::absolute(mPath).parent_path()),
          mAccessors(gltf, mPath) {}

    Result<Model> convert() {
        if (Status status = checkAsset(); !status) return status.error();
        if (Status status = checkExtensions(); !status) return status.error();
        if (GltfRigBuilder::wanted(mGltf)) {
            mRig.emplace(mGltf, mAccessors, mPath);
            if (Status status = mRig->readHierarchy(); !status) return status.error();
        }
        if (Status status = addScene(); !status) return status.error();
        if (mModel.mesh.triangleCount() == 0) return fail("no triangles in the scene");
        if (mRig) mModel.rig = mRig->finish(mModel.mesh);
        if (Status status = loadMaterials(); !status) return status.error();
        if (mModel.mesh.name.empty()) mModel.mesh.name = fs::path(mPath).stem().string();
        return std::move(mModel);
    }

private:
    Error fail(const std::string& what) const { return makeError(mPath, what); }

    // glTF 2.0 §3.2: asset.version is the major.minor the file follows and
    // asset.minVersion the least a loader must support; this one reads 2.0.
    // §5.1: the default scene, when given, is one of the file's scenes.
    Status checkAsset() const {
        const std::string& version = mGltf.asset.version;
        if (version.rfind("2.", 0) != 0)
            return fail("glTF " + (version.empty() ? std::string("of no asset.version") : version) +
                        " is not supported: Dermis reads glTF 2.0 (convert the file, e.g. with Blender)");
        const std::string& minVersion = mGltf.asset.minVersion;
        if (!minVersion.empty() && minVersion != "2.0")
            return fail("asset.minVersion " + minVersion + ": Dermis reads glTF 2.0");
        if (mGltf.defaultScene >= static_cast<int>(mGltf.scenes.size()))
            return fail("scene " + std::to_string(mGltf.defaultScene) + " is out of range (the file has " +
                        std::to_string(mGltf.scenes.size()) + " scenes)");
        return success();
    }

    // Required extensions it cannot honour are refused or named; optional
    // ones it ignores are named in one warning.
    Status checkExtensions() {
        auto isSupported = [&](const std::string& e) {
            return std::find(std::begin(kSupportedGltfExtensions), std::end(kSupportedGltfExtensions), e) !=
                   std::end(kSupportedGltfExtensions);
        };
        // glTF 2.0 §3.12: a loader refuses a file whose extensionsRequired it does not support.
        for (const std::string& extension : mGltf.extensionsRequired) {
            if (!isSupported(extension))
                return fail("requires " + extension + ", which Dermis does not support (docs/gltf.md lists what it reads)");
        }
        std::string ignored;
        for (const std::string& extension : mGltf.extensionsUsed) {
            const bool required = std::find(mGltf.extensionsRequired.begin(), mGltf.extensionsRequired.end(), extension) !=
                                  mGltf.extensionsRequired.end();
            if (!required && !isSupported(extension)) ignored += (ignored.empty() ? "" : ", ") + extension;
        }
        if (!ignored.empty()) log::warn(mPath + ": uses " + ignored + ", which this loader ignores");
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
        Result<NodeTransform> transform = readNodeTransform(node, index, mPath);
        if (!transform) return transform.error();
        return transform->matrix();
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
                if (Status checked = checkTransformScale(glm::mat3(world), mPath,
                                                         "node " + std::to_string(index) +
                                                             (node.name.empty() ? "" : " '" + node.name + "'"));
                    !checked)
                    return checked;
                if (static_cast<size_t>(node.mesh) >= mGltf.meshes.size())
                    return fail("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) +
                                " is out of range");
                if (Status status = addMesh(index, node.mesh, world); !status) return status;
            }
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
                stack.emplace_back(*child, world);
        }
        return success();
    }

    Status addMesh(int nodeIndex, int meshIndex, const glm::mat4& world) {
        const tinygltf::Mesh& mesh = mGltf.meshes[static_cast<size_t>(meshIndex)];
        if (mModel.mesh.name.empty()) mModel.mesh.name = mesh.name;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where = "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p);
            if (Status status = addPrimitive(where, mesh.primitives[p], nodeIndex, world); !status) return status;
        }
        return success();
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

    // With a rig, the vertices stay as the file gives them (the rig poses them);
    // without, the node's world transform is applied here.
    Status addPrimitive(const std::string& where, const tinygltf::Primitive& primitive, int node, const glm::mat4& nodeWorld) {
        const glm::mat4 world = mRig ? glm::mat4(1.0f) : nodeWorld;
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

        Result<AccessorView> positionView = mAccessors.view(positionAccessor, where);
        if (!positionView) return positionView.error();
        const size_t vertexCount = positionView->count;
        if (vertexCount == 0) return success();
        if (vertexCount > kMaxVertices - mModel.mesh.vertices.size())
            return fail("the scene has more than " + std::to_string(kMaxVertices) + " vertices");

        Result<std::vector<float>> positions = mAccessors.readFloats(positionAccessor, TINYGLTF_TYPE_VEC3, where);
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
            Result<std::vector<float>> values = mAccessors.readFloats(accessor, optional.type, where + " " + optional.name);
            if (!values) return values.error();
            if (mGltf.accessors[static_cast<size_t>(accessor)].count != vertexCount)
                return fail(where + ": " + optional.name + " has " +
                            std::to_string(mGltf.accessors[static_cast<size_t>(accessor)].count) +
                            " elements, POSITION has " + std::to_string(vertexCount));
            *optional.out = std::move(values.value());
        }

        if (uvs) {
            Result<UvTransform> transform = uvTransformOf(primitive.material);
            if (!transform) return transform.error();
            if (!transform->identity) {
                for (size_t i = 0; i + 1 < uvs->size(); i += 2) {
                    const glm::vec2 uv = transform->apply(glm::vec2((*uvs)[i], (*uvs)[i + 1]));
                    (*uvs)[i] = uv.x;
                    (*uvs)[i + 1] = uv.y;
                }
            }
        }

        Result<std::vector<glm::vec4>> colours = readColours(attribute("COLOR_0"), vertexCount, where);
        if (!colours) return colours.error();

        std::vector<uint32_t> indices;
        if (primitive.indices >= 0) {
            Result<std::vector<uint32_t>> read = mAccessors.readIndices(primitive.indices, vertexCount, where);
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
        if (mRig ? mRig->mirroredAtRest(node) : glm::determinant(glm::mat3(world)) < 0.0f)
            for (size_t i = 0; i + 2 < piece.mesh.indices.size(); i += 3)
                std::swap(piece.mesh.indices[i + 1], piece.mesh.indices[i + 2]);
        // Without NORMAL the primitive is drawn flat (mesh/FlatNormals.h): each
        // triangle its own vertices, each the copy of the file's vertex named here.
        std::vector<uint32_t> fileVertexOf;
        if (!normals) {
            UnweldedMesh flat = unweldWithFaceNormals(piece.mesh);
            if (flat.mesh.vertices.size() > kMaxVertices - mModel.mesh.vertices.size())
                return fail("the scene has more than " + std::to_string(kMaxVertices) +
                            " vertices once the primitives without normals have a vertex per triangle corner");
            std::vector<bool> badTangent;
            for (uint32_t source : flat.sourceVertex) badTangent.push_back(piece.badTangent[source]);
            piece.badTangent = std::move(badTangent);
            piece.badNormal = std::move(flat.degenerate);
            piece.mesh = std::move(flat.mesh);
            fileVertexOf = std::move(flat.sourceVertex);
        }
        repairFrames(piece);

        if (primitive.material >= 0 && static_cast<size_t>(primitive.material) >= mGltf.materials.size())
            return fail(where + ": material " + std::to_string(primitive.material) + " is out of range");
        addSubmesh(primitive.material, piece.mesh.indices.size());
        const size_t firstVertex = mModel.mesh.vertices.size();
        append(piece.mesh);
        if (!fileVertexOf.empty() && !colours->empty()) {
            std::vector<glm::vec4> copied;
            copied.reserve(fileVertexOf.size());
            for (uint32_t source : fileVertexOf) copied.push_back((*colours)[source]);
            *colours = std::move(copied);
        }
        addColours(*colours, firstVertex);
        if (!mRig) return success();
        if (Status status = mRig->addPrimitive(node, primitive, firstVertex, vertexCount, where); !status) return status;
        if (!fileVertexOf.empty()) return mRig->copyVertices(firstVertex, fileVertexOf);
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

    // COLOR_0 (glTF 2.0 §3.7.2.1): VEC3 or VEC4, float or normalised
    // integers; a primitive without it is white.
    Result<std::vector<glm::vec4>> readColours(int accessor, size_t vertexCount, const std::string& where) const {
        if (accessor < 0) return std::vector<glm::vec4>();
        if (static_cast<size_t>(accessor) >= mGltf.accessors.size())
            return fail(where + ": COLOR_0 accessor " + std::to_string(accessor) + " is out of range");
        const tinygltf::Accessor& info = mGltf.accessors[static_cast<size_t>(accessor)];
        if (info.type != TINYGLTF_TYPE_VEC3 && info.type != TINYGLTF_TYPE_VEC4)
            return fail(where + ": COLOR_0 must be VEC3 or VEC4, accessor " + std::to_string(accessor) + " is not");
        if (info.count != vertexCount)
            return fail(where + ": COLOR_0 has " + std::to_string(info.count) + " elements, POSITION has " +
                        std::to_string(vertexCount));
        const bool integer = info.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             info.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        if (integer && !info.normalized)  // read as they are, colours would reach 255 or 65535
            return fail(where + ": COLOR_0 accessor " + std::to_string(accessor) +
                        " holds unsigned integers but is not normalized (glTF 2.0 §3.7.2.1)");
        Result<std::vector<float>> values = mAccessors.readFloats(accessor, info.type, where + " COLOR_0");
        if (!values) return values.error();
        const size_t components = info.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
        std::vector<glm::vec4> colours(vertexCount, glm::vec4(1.0f));
        for (size_t v = 0; v < vertexCount; ++v)
            for (size_t c = 0; c < components; ++c) colours[v][static_cast<int>(c)] = (*values)[v * components + c];
        return colours;
    }

    // Colours stay empty (all white) until a primitive brings some.
    void addColours(const std::vector<glm::vec4>& colours, size_t firstVertex) {
        std::vector<glm::vec4>& all = mModel.colours;
        const size_t count = mModel.mesh.vertices.size();
        if (colours.empty() && all.empty()) return;
        all.resize(count, glm::vec4(1.0f));
        std::copy(colours.begin(), colours.end(), all.begin() + static_cast<std::ptrdiff_t>(firstVertex));
    }

    // The primitive's triangles join the last submesh when it has the same
    // material; glTF material -1 is the default material.
    void addSubmesh(int gltfMaterial, size_t indexCount) {
        auto used = std::find(mUsedMaterials.begin(), mUsedMaterials.end(), gltfMaterial);
        if (used == mUsedMaterials.end()) used = mUsedMaterials.insert(mUsedMaterials.end(), gltfMaterial);
        const int material = static_cast<int>(used - mUsedMaterials.begin());
        std::vector<Submesh>& submeshes = mModel.submeshes;
        if (!submeshes.empty() && submeshes.back().material == material) {
            submeshes.back().indexCount += static_cast<uint32_t>(indexCount);
            return;
        }
        submeshes.push_back({static_cast<uint32_t>(mModel.mesh.indices.size()), static_cast<uint32_t>(indexCount), material});
    }

    void append(const MeshData& piece) {
        MeshData& merged = mModel.mesh;
        const uint32_t offset = static_cast<uint32_t>(merged.vertices.size());
        merged.vertices.insert(merged.vertices.end(), piece.vertices.begin(), piece.vertices.end());
        merged.indices.reserve(merged.indices.size() + piece.indices.size());
        for (uint32_t index : piece.indices) merged.indices.push_back(index + offset);
    }

    // KHR_texture_transform of a material, read (and warned about) once.
    Result<UvTransform> uvTransformOf(int material) {
        auto it = mUvTransforms.find(material);
        if (it != mUvTransforms.end()) return it->second;
        Result<UvTransform> transform = materialUvTransform(mGltf, material, mPath);
        if (!transform) return transform.error();
        mUvTransforms.emplace(material, *transform);
        return transform;
    }

    // Model::materials[i] is the glTF material mUsedMaterials[i] (-1: glTF's default material).
    Status loadMaterials() {
        mModel.materials.clear();
        for (int index : mUsedMaterials) {
            ModelMaterial material;
            if (index >= 0) {
                if (Status status = loadMaterial(index, material); !status) return status;
            }
            mModel.materials.push_back(std::move(material));
        }
        if (mModel.materials.empty()) mModel.materials.emplace_back();
        return success();
    }

    Status loadMaterial(int index, ModelMaterial& out) {
        const tinygltf::Material& material = mGltf.materials[static_cast<size_t>(index)];
        const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
        out.name = material.name;
        for (size_t c = 0; c < 4 && c < pbr.baseColorFactor.size(); ++c) {
            const double factor = pbr.baseColorFactor[c];
            if (!(factor >= 0.0 && factor <= 1.0))  // glTF 2.0 §5.22.1: each in [0, 1]; NaN too
                return fail("material " + std::to_string(index) + quoted(material.name) + ": baseColorFactor[" +
                            std::to_string(c) + "] " + formatNumberForMessage(factor) + " is outside [0, 1]");
            out.baseColourFactor[static_cast<int>(c)] = static_cast<float>(factor);
        }
        out.roughnessFactor = static_cast<float>(pbr.roughnessFactor);
        out.alphaMode = material.alphaMode.empty() ? "OPAQUE" : material.alphaMode;
        struct Map {
            const char* role;
            int texture;
            int texCoord;
            ColourSpace colourSpace;
            Image* out;
            TextureWraps* wrap;
        };
        std::vector<Map> maps = {
            Map{"baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, ColourSpace::Srgb,
                &out.albedoMap, &out.albedoWrap},
            Map{"normalTexture", material.normalTexture.index, material.normalTexture.texCoord, ColourSpace::Linear,
                &out.normalMap, &out.normalWrap},
            Map{"metallicRoughnessTexture", pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                ColourSpace::Linear, &out.metallicRoughnessMap, &out.metallicRoughnessWrap}};
        // The surface beneath: KHR_materials_diffuse_transmission (factor, texture A),
        // KHR_materials_volume (thickness, texture G), KHR_materials_transmission (factor).
        auto extension = [&](const char* name) -> const tinygltf::Value* {
            auto found = material.extensions.find(name);
            return found == material.extensions.end() || !found->second.IsObject() ? nullptr : &found->second;
        };
        auto number = [](const tinygltf::Value& object, const char* key, float fallback) {
            return object.Has(key) && object.Get(key).IsNumber() ? static_cast<float>(object.Get(key).GetNumberAsDouble())
                                                                 : fallback;
        };
        auto textureOf = [&](const tinygltf::Value& object, const char* key, const char* role, Image* image, TextureWraps* wrap) {
            if (!object.Has(key) || !object.Get(key).IsObject()) return;
            const tinygltf::Value& info = object.Get(key);
            const int texture = info.Has("index") && info.Get("index").IsInt() ? info.Get("index").GetNumberAsInt() : -1;
            const int texCoord = info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
            maps.push_back(Map{role, texture, texCoord, ColourSpace::Linear, image, wrap});
        };
        if (const tinygltf::Value* diffuse = extension("KHR_materials_diffuse_transmission")) {
            out.diffuseTransmission = std::clamp(number(*diffuse, "diffuseTransmissionFactor", 0.0f), 0.0f, 1.0f);
            textureOf(*diffuse, "diffuseTransmissionTexture", "diffuseTransmissionTexture", &out.diffuseTransmissionMap,
                      &out.scatterWrap);
        }
        if (const tinygltf::Value* volume = extension("KHR_materials_volume")) {
            out.thicknessFactor = std::max(number(*volume, "thicknessFactor", 0.0f), 0.0f);
            textureOf(*volume, "thicknessTexture", "thicknessTexture", &out.thicknessMap, &out.thicknessWrap);
        }
        if (const tinygltf::Value* transmission = extension("KHR_materials_transmission"))
            out.transmission = std::clamp(number(*transmission, "transmissionFactor", 0.0f), 0.0f, 1.0f);
        for (const Map& map : maps) {
            if (map.texture < 0) continue;
            const std::string where = "material " + std::to_string(index) + quoted(material.name) + " " + map.role;
            if (map.texCoord != 0)
                log::warn(mPath + ": " + where + " uses TEXCOORD_" + std::to_string(map.texCoord) +
                          "; only TEXCOORD_0 is loaded");
            if (static_cast<size_t>(map.texture) >= mGltf.textures.size())
                return fail(where + ": texture " + std::to_string(map.texture) + " is out of range");
            const tinygltf::Texture& texture = mGltf.textures[static_cast<size_t>(map.texture)];
            if (texture.sampler >= 0) {
                if (static_cast<size_t>(texture.sampler) >= mGltf.samplers.size())
                    return fail(where + ": texture " + std::to_string(map.texture) + "'s sampler " +
                                std::to_string(texture.sampler) + " is out of range");
                const tinygltf::Sampler& sampler = mGltf.samplers[static_cast<size_t>(texture.sampler)];
                TextureWrap* axes[] = {&map.wrap->s, &map.wrap->t};
                const int values[] = {sampler.wrapS, sampler.wrapT};
                for (int axis = 0; axis < 2; ++axis) {
                    auto wrap = textureWrapOf(values[axis]);
                    if (!wrap)
                        return fail("sampler " + std::to_string(texture.sampler) + ": " + (axis == 0 ? "wrapS " : "wrapT ") +
                                    std::to_string(values[axis]) + " is not 33071, 33648 or 10497 (glTF 2.0 §5.26)");
                    *axes[axis] = *wrap;
                }
            }
            const int source = texture.source;
            // KTX2 (KHR_texture_basisu): no Debian package decodes it. Without a PNG or JPEG
            // fallback in `source`, the map is skipped with one warning and the material's
            // factors stand; the rest of the file loads.
            const bool basisOnly = source < 0 && texture.extensions.count("KHR_texture_basisu") != 0;
            if (basisOnly || (source >= 0 && static_cast<size_t>(source) < mGltf.images.size() &&
                              isKtx2(mGltf.images[static_cast<size_t>(source)]))) {
                log::warn(mPath + ": " + where + ": texture " + std::to_string(map.texture) +
                          " is KTX2 (KHR_texture_basisu), which Dermis cannot decode; drawn with the material's "
                          "factors. Re-export with PNG or JPEG textures (gltfpack without -tc)");
                continue;
            }
            if (source < 0 || static_cast<size_t>(source) >= mGltf.images.size())
                return fail(where + ": texture " + std::to_string(map.texture) + " has no image this loader can read");
            auto decoded = mDecoded.find({source, map.colourSpace});
            if (decoded == mDecoded.end()) {
                Result<Image> image = decodeImage(source, map.colourSpace);
                if (!image) return image.error();
                decoded = mDecoded.emplace(std::make_pair(source, map.colourSpace), std::move(image.value())).first;
            }
            *map.out = decoded->second;
        }
        // The extensions' grey values, moved to R where the scattering code reads them.
        for (auto [image, channel] : {std::pair{&out.diffuseTransmissionMap, 3}, std::pair{&out.thicknessMap, 1}}) {
            for (glm::vec4& texel : image->texels) texel = glm::vec4(glm::vec3(texel[channel]), 1.0f);
        }
        return success();
    }

    static bool isKtx2(const tinygltf::Image& image) {
        const std::string& uri = image.uri;
        return image.mimeType == "image/ktx2" || (uri.size() >= 5 && uri.compare(uri.size() - 5, 5, ".ktx2") == 0);
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
    GltfAccessors mAccessors;
    Model mModel;
    std::vector<int> mUsedMaterials;  // glTF material indices in first-use order, -1 the default material
    std::map<std::pair<int, ColourSpace>, Image> mDecoded;  // images shared by several materials decode once
    std::optional<GltfRigBuilder> mRig;  // when the file moves vertices
    std::map<int, UvTransform> mUvTransforms;  // by glTF material index
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
        // A .glb that is not JSON either: name the missing magic rather than a JSON parse error.
        const size_t first = json.find_first_not_of(" \t\r\n");
        std::string extension = fs::path(path).extension().string();
        for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (extension == ".glb" && (first == std::string::npos || json[first] != '{'))
            return makeError(path, "not a binary glTF: the file does not start with the magic 'glTF' (" +
                                       std::to_string(bytes.size()) + " bytes)");
    }
    if (jsonNestingDepth(json.data(), json.size()) > kMaxJsonNesting)
        return makeError(path, "JSON nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
    // What tinygltf would refuse in compressed files is set aside in the JSON first.
    MeshoptFallbacks fallbacks;
    if (json.find("EXT_meshopt_compression") != std::string::npos ||
        json.find("KHR_draco_mesh_compression") != std::string::npos) {
        nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
        if (!document.is_discarded()) {
            if (Status status = setAsideMeshoptFallbacks(document, fallbacks, path); !status) return status.error();
            const bool detached = detachDracoIndices(document);
            if (!fallbacks.empty() || detached) {
                json = document.dump();
                if (glb) bytes = replaceGlbJson(bytes, *glb, json, &glb.value());
            }
        }
    }
    const bool loaded =
        glb ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), static_cast<unsigned int>(glb->length),
                                          baseDir)
            : loader.LoadASCIIFromString(&gltf, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                         baseDir);
    if (!warn.empty()) log::warn(path + ": " + oneLine(warn));
    if (!loaded) return makeError(path, describeLoadError(err, json));
    if (Status decoded = decodeMeshoptViews(gltf, fallbacks, path); !decoded) return decoded.error();
    if (Status decoded = decodeDracoPrimitives(gltf, path); !decoded) return decoded.error();
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
