#include "TestContent.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
// As engine/import/GltfLoader.cpp compiles tinygltf: no image codecs.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "core/Image.h"
#include "procedural/Procedural.h"
#include "procedural/ProceduralHeadShape.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace dermis::test {
namespace {

constexpr float kPi = 3.14159265358979f;

// Appends a tightly packed accessor over a new buffer view of buffer 0.
template <typename T>
int addAccessor(tinygltf::Model& model, const std::vector<T>& values, int componentType, int type, size_t count,
                bool minMax = false) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    if (minMax) {  // POSITION accessors must carry their bounds
        const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type));
        accessor.minValues.assign(static_cast<size_t>(components), 1e30);
        accessor.maxValues.assign(static_cast<size_t>(components), -1e30);
        for (size_t i = 0; i < values.size(); ++i) {
            const size_t c = i % static_cast<size_t>(components);
            accessor.minValues[c] = std::min(accessor.minValues[c], double(values[i]));
            accessor.maxValues[c] = std::max(accessor.maxValues[c], double(values[i]));
        }
    }
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

tinygltf::Model newModel() {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Dermis tests (tests/support/TestContent.cpp)";
    model.buffers.resize(1);
    return model;
}

bool writeModel(tinygltf::Model& model, const std::string& path, std::string* error) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, false, true, true, false)) {
        if (error) *error = "tinygltf could not write " + path;
        return false;
    }
    return true;
}

// Adds `mesh` as the model's only mesh, on one node of the default scene, and writes the file.
bool writeOneMeshModel(tinygltf::Model& model, const tinygltf::Mesh& mesh, const std::string& path, std::string* error) {
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = mesh.name;
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {static_cast<int>(model.nodes.size() - 1)};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return writeModel(model, path, error);
}

}  // namespace

bool writeBendingCylinder(const std::string& path, std::string* error, float uvScale) {
    using C = BendingCylinder;
    tinygltf::Model model = newModel();

    std::vector<float> positions, normals, uvs, weights, bulge;
    std::vector<uint16_t> joints;
    std::vector<uint32_t> indices;
    const int columns = C::kSegments + 1;
    for (int ring = 0; ring < C::kRings; ++ring) {
        const float v = float(ring) / float(C::kRings - 1);
        const float y = v * C::kLengthM;
        const float bend = smoothstep(C::kJointYM - C::kBlendM, C::kJointYM + C::kBlendM, y);
        const float bulgeM = C::kBulgeM * std::max(0.0f, 1.0f - std::abs(y - C::kJointYM) / C::kBulgeHalfWidthM);
        for (int column = 0; column < columns; ++column) {
            const float u = float(column) / float(C::kSegments);
            const float angle = 2.0f * kPi * u;
            const glm::vec3 radial(std::cos(angle), 0.0f, -std::sin(angle));
            positions.insert(positions.end(), {C::kRadiusM * radial.x, y, C::kRadiusM * radial.z});
            normals.insert(normals.end(), {radial.x, radial.y, radial.z});
            uvs.insert(uvs.end(), {uvScale * u, uvScale * (1.0f - v)});
            joints.insert(joints.end(), {0, 1, 0, 0});
            weights.insert(weights.end(), {1.0f - bend, bend, 0.0f, 0.0f});
            bulge.insert(bulge.end(), {bulgeM * radial.x, 0.0f, bulgeM * radial.z});
        }
    }
    for (int ring = 0; ring + 1 < C::kRings; ++ring) {
        for (int column = 0; column < C::kSegments; ++column) {
            const auto a = static_cast<uint32_t>(ring * columns + column), b = a + 1, c = a + columns, d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    }
    const size_t vertexCount = positions.size() / 3;

    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] =
        addAccessor(model, positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertexCount, true);
    primitive.attributes["NORMAL"] = addAccessor(model, normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertexCount);
    primitive.attributes["TEXCOORD_0"] = addAccessor(model, uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, vertexCount);
    primitive.attributes["JOINTS_0"] =
        addAccessor(model, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, vertexCount);
    primitive.attributes["WEIGHTS_0"] = addAccessor(model, weights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, vertexCount);
    primitive.indices = addAccessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
    primitive.targets.push_back(
        {{"POSITION", addAccessor(model, bulge, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertexCount, true)}});
    tinygltf::Mesh mesh;
    mesh.name = "cylinder";
    mesh.primitives.push_back(primitive);
    mesh.weights = {0.0};
    model.meshes.push_back(mesh);

    // Nodes: 0 the skinned mesh, 1 "root", 2 "bend".
    tinygltf::Node meshNode;
    meshNode.name = "cylinder";
    meshNode.mesh = 0;
    meshNode.skin = 0;
    meshNode.translation = {5.0, 5.0, 5.0};  // ignored: the mesh is skinned
    tinygltf::Node root;
    root.name = "root";
    root.children = {2};
    tinygltf::Node bend;
    bend.name = "bend";
    bend.translation = {0.0, double(C::kJointYM), 0.0};
    model.nodes = {meshNode, root, bend};
    tinygltf::Scene scene;
    scene.nodes = {0, 1};
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    tinygltf::Skin skin;
    skin.name = "two bones";
    skin.joints = {1, 2};
    skin.skeleton = 1;
    const std::vector<float> inverseBind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -C::kJointYM, 0, 1};
    skin.inverseBindMatrices = addAccessor(model, inverseBind, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, 2);
    model.skins.push_back(skin);

    tinygltf::Animation animation;
    animation.name = "bend";
    const std::vector<float> times = {0.0f, 1.0f, 2.0f};
    const int input = addAccessor(model, times, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, 3, true);
    const glm::quat bent = glm::angleAxis(glm::radians(C::kBendDeg), glm::vec3(0.0f, 0.0f, 1.0f));
    const std::vector<float> rotations = {0, 0, 0, 1, bent.x, bent.y, bent.z, bent.w, 0, 0, 0, 1};
    const std::vector<float> morphWeights = {0.0f, 1.0f, 0.0f};
    tinygltf::AnimationSampler rotationSampler;
    rotationSampler.input = input;
    rotationSampler.output = addAccessor(model, rotations, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 3);
    rotationSampler.interpolation = "LINEAR";
    tinygltf::AnimationSampler weightSampler = rotationSampler;
    weightSampler.output = addAccessor(model, morphWeights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, 3);
    animation.samplers = {rotationSampler, weightSampler};
    tinygltf::AnimationChannel rotate;
    rotate.sampler = 0;
    rotate.target_node = 2;
    rotate.target_path = "rotation";
    tinygltf::AnimationChannel morph;
    morph.sampler = 1;
    morph.target_node = 0;
    morph.target_path = "weights";
    animation.channels = {rotate, morph};
    model.animations.push_back(animation);

    return writeModel(model, path, error);
}

bool writeMultiMaterialStrip(const std::string& path, std::string* error) {
    using S = MultiMaterialStrip;
    tinygltf::Model model = newModel();
    tinygltf::Mesh mesh;
    mesh.name = "strip";
    for (int p = 0; p < S::kPrimitives; ++p) {
        std::vector<float> positions, normals, uvs, floatColours;
        std::vector<uint8_t> byteColours;
        std::vector<uint16_t> shortColours;
        std::vector<uint32_t> indices;
        // A grid whose columns include either side of the step (kStepBandM
        // apart), so that one UV chart changes colour inside that narrow band;
        // inner rows and columns keep vertices away from the chart's border.
        const float left = S::leftXM(p);
        const float step = left + 0.5f * S::kWidthM;
        const float xs[] = {left, left + 0.25f * S::kWidthM, step - 0.5f * S::kStepBandM, step + 0.5f * S::kStepBandM,
                            left + 0.75f * S::kWidthM, left + S::kWidthM};
        constexpr uint32_t kColumns = 6;
        constexpr uint32_t kRows = 9;
        for (uint32_t row = 0; row < kRows; ++row) {
            const float t = float(row) / float(kRows - 1);
            const float z = (2.0f * t - 1.0f) * S::kHalfDepthM;
            for (uint32_t column = 0; column < kColumns; ++column) {
                const float x = xs[column];
                positions.insert(positions.end(), {x, 0.0f, z});
                normals.insert(normals.end(), {0.0f, 1.0f, 0.0f});
                const float u = (float(p) + (x - left) / S::kWidthM) / float(S::kPrimitives);
                uvs.insert(uvs.end(), {u * 0.98f + 0.01f, 0.01f + 0.98f * t});
                const glm::vec3 colour = S::kColours[p][x < step ? 0 : 1];
                for (int c = 0; c < 3; ++c) {
                    floatColours.push_back(colour[c]);
                    byteColours.push_back(static_cast<uint8_t>(std::lround(colour[c] * 255.0f)));
                    shortColours.push_back(static_cast<uint16_t>(std::lround(colour[c] * 65535.0f)));
                }
                floatColours.push_back(1.0f);
            }
        }
        for (uint32_t row = 0; row + 1 < kRows; ++row) {
            for (uint32_t column = 0; column + 1 < kColumns; ++column) {
                const uint32_t a = row * kColumns + column, b = a + 1, c = a + kColumns, d = c + 1;
                indices.insert(indices.end(), {a, c, b, b, c, d});  // counter-clockwise seen from +Y
            }
        }
        const size_t count = positions.size() / 3;
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = p;
        primitive.attributes["POSITION"] =
            addAccessor(model, positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count, true);
        primitive.attributes["NORMAL"] = addAccessor(model, normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
        primitive.attributes["TEXCOORD_0"] = addAccessor(model, uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
        int colours = -1;
        if (p == 0) {
            colours = addAccessor(model, floatColours, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, count);
        } else if (p == 1) {
            colours = addAccessor(model, byteColours, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC3, count);
        } else {
            colours = addAccessor(model, shortColours, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC3, count);
        }
        model.accessors[static_cast<size_t>(colours)].normalized = p != 0;
        primitive.attributes["COLOR_0"] = colours;
        primitive.indices = addAccessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
        mesh.primitives.push_back(primitive);

        tinygltf::Material material;
        material.name = S::kNames[p];
        const glm::vec4 factor = S::kFactors[p];
        material.pbrMetallicRoughness.baseColorFactor = {factor.r, factor.g, factor.b, factor.a};
        model.materials.push_back(material);
    }
    return writeOneMeshModel(model, mesh, path, error);
}

int Avatar::materialAt(const glm::vec3& c) {
    // The visible eyeball: a band of the closed lid's sphere in front of the eye.
    const glm::vec3 eye(std::fabs(c.x), c.y, c.z);
    const glm::vec3 toEye = eye - head::kEyeM;
    if (glm::length(toEye) < 0.0135f && toEye.z > 0.005f && std::fabs(toEye.y) < 0.0045f) return 2;
    if (c.y < -0.15f) return 3;  // the collar round the neck's foot
    // Hair: the crown and the back of the cranium, its line lower towards the
    // back (height over the cranium's centre, in its half-height, against z).
    const float height = (c.y - 0.024f) / 0.100f;
    const float line = 0.33f - 0.95f * std::clamp((0.06f - c.z) / 0.10f, 0.0f, 1.0f);
    if (height > line && std::fabs(c.x) < 0.072f) return 1;
    return 0;
}

bool writeAvatar(const std::string& path, std::string* error, bool withMaps) {
    auto head = makeProceduralModel("head");
    if (!head) {
        if (error) *error = head.error().message();
        return false;
    }
    const MeshData& mesh = head->mesh;
    tinygltf::Model model = newModel();
    std::vector<float> positions, normals, uvs, tangents;
    for (const Vertex& v : mesh.vertices) {
        positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
        normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
        uvs.insert(uvs.end(), {v.uv.x, v.uv.y});
        tangents.insert(tangents.end(), {v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w});
    }
    const size_t count = mesh.vertices.size();
    const int position = addAccessor(model, positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count, true);
    const int normal = addAccessor(model, normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    const int uv = addAccessor(model, uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
    const int tangent = addAccessor(model, tangents, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, count);
    std::vector<std::vector<uint32_t>> indices(Avatar::kMaterials);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 centroid = (mesh.vertices[mesh.indices[t]].position + mesh.vertices[mesh.indices[t + 1]].position +
                                    mesh.vertices[mesh.indices[t + 2]].position) / 3.0f;
        auto& list = indices[static_cast<size_t>(Avatar::materialAt(centroid))];
        list.insert(list.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    }
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "avatar";
    for (int m = 0; m < Avatar::kMaterials; ++m) {
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = m;
        primitive.attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}, {"TANGENT", tangent}};
        const auto& list = indices[static_cast<size_t>(m)];
        primitive.indices = addAccessor(model, list, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, list.size());
        gltfMesh.primitives.push_back(primitive);
        tinygltf::Material material;
        material.name = Avatar::kNames[m];
        glm::vec3 factor = Avatar::kFactors[m];
        if (m == 0 && withMaps) factor = glm::vec3(1.0f);
        material.pbrMetallicRoughness.baseColorFactor = {factor.r, factor.g, factor.b, 1.0};
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        model.materials.push_back(material);
    }
    if (withMaps) {
        const std::filesystem::path dir = std::filesystem::path(path).parent_path();
        const std::pair<const char*, const Image*> maps[] = {{"avatar_albedo.png", &head->materials[0].albedoMap},
                                                             {"avatar_normal.png", &head->materials[0].normalMap}};
        for (const auto& [name, image] : maps) {
            if (Status saved = saveImage((dir / name).string(), *image); !saved) {
                if (error) *error = saved.error().message();
                return false;
            }
            tinygltf::Image gltfImage;
            gltfImage.uri = name;
            model.images.push_back(gltfImage);
            tinygltf::Texture texture;
            texture.source = static_cast<int>(model.images.size() - 1);
            model.textures.push_back(texture);
        }
        model.materials[0].pbrMetallicRoughness.baseColorTexture.index = 0;
        model.materials[0].normalTexture.index = 1;
    }
    return writeOneMeshModel(model, gltfMesh, path, error);
}

}  // namespace dermis::test
