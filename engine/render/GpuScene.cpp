#include "render/GpuScene.h"
#include "render/SceneLoading.h"

#include "mesh/MeshTopology.h"

#include "gl/TexturePool.h"
#include "lean/LeanBake.h"
#include "plan/SceneGeometry.h"
#include "gpu/UniformBlocks.h"

#include <algorithm>
#include <map>
#include <cmath>
#include <cstddef>

namespace dermis {
namespace {

GpuMesh uploadMesh(const MeshData& mesh, const std::vector<uint32_t>& indices, const std::vector<glm::vec4>& colours,
                   const std::string& owner) {
    GpuMesh gpu;
    const std::vector<glm::vec4> white(mesh.vertices.size(), glm::vec4(1.0f));
    const std::vector<glm::vec4>& perVertex = colours.size() == mesh.vertices.size() ? colours : white;
    gpu.vertexColours = std::any_of(perVertex.begin(), perVertex.end(), [](const glm::vec4& c) { return glm::vec3(c) != glm::vec3(1.0f); });
    gpu.colourBuffer = gl::createBuffer(owner + ": vertex colours");
    glNamedBufferStorage(gpu.colourBuffer.get(), static_cast<GLsizeiptr>(perVertex.size() * sizeof(glm::vec4)),
                         perVertex.data(), 0);
    gpu.vertexBuffer = gl::createBuffer(owner + ": vertices");
    glNamedBufferStorage(gpu.vertexBuffer.get(), static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
                         mesh.vertices.data(), 0);
    gpu.indexBuffer = gl::createBuffer(owner + ": indices (every level of detail)");
    glNamedBufferStorage(gpu.indexBuffer.get(), static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)), indices.data(),
                         0);
    gpu.vertexArray = gl::createVertexArray(owner);
    const GLuint vao = gpu.vertexArray.get();
    glVertexArrayVertexBuffer(vao, 0, gpu.vertexBuffer.get(), 0, sizeof(Vertex));
    glVertexArrayVertexBuffer(vao, 1, gpu.colourBuffer.get(), 0, sizeof(glm::vec4));
    glEnableVertexArrayAttrib(vao, kColourLocation);
    glVertexArrayAttribFormat(vao, kColourLocation, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, kColourLocation, 1);
    glVertexArrayElementBuffer(vao, gpu.indexBuffer.get());
    struct Attribute {
        GLuint location;
        GLint components;
        size_t offset;
    };
    const Attribute attributes[] = {{0, 3, offsetof(Vertex, position)},
                                    {1, 3, offsetof(Vertex, normal)},
                                    {2, 4, offsetof(Vertex, tangent)},
                                    {3, 2, offsetof(Vertex, uv)}};
    for (const Attribute& a : attributes) {
        glEnableVertexArrayAttrib(vao, a.location);
        glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE, static_cast<GLuint>(a.offset));
        glVertexArrayAttribBinding(vao, a.location, 0);
    }
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
    gpu.objectBounds = mesh.bounds();
    return gpu;
}

static_assert(sizeof(Vertex) == DERMIS_VERTEX_FLOATS * sizeof(float), "shaders/skinning.comp writes Vertex as floats");

template <typename T>
gl::Buffer uploadBuffer(const std::vector<T>& data, const std::string& label, GLbitfield flags = 0) {
    gl::Buffer buffer = gl::createBuffer(label);
    const std::vector<T> one(1);  // GL buffers cannot be empty
    const std::vector<T>& contents = data.empty() ? one : data;
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(contents.size() * sizeof(T)), contents.data(), flags);
    return buffer;
}

struct SkinSourceVertex {
    Vertex vertex;
    glm::vec3 dPdu;
    glm::vec3 dPdv;
};
static_assert(sizeof(SkinSourceVertex) == DERMIS_SKIN_SOURCE_FLOATS * sizeof(float), "shaders/skinning.comp's source layout");

struct SkinInfluenceGpu {
    glm::uvec4 joints;  // xy: two 16-bit palette indices each
    glm::vec4 weights;
};

GpuRig uploadRig(const Rig& rig, const MeshData& mesh, const std::string& owner) {
    GpuRig gpu;
    if (rig.empty()) return gpu;
    const size_t count = mesh.vertices.size();
    MeshData bind = mesh;
    setVertexFrames(bind, rig.bind);
    const UvLayout derivatives = analyseUvDerivatives(bind);
    std::vector<SkinSourceVertex> source(count);
    std::vector<SkinInfluenceGpu> influences(count);
    for (size_t v = 0; v < count; ++v) {
        source[v] = {bind.vertices[v], derivatives.dPdu[v], derivatives.dPdv[v]};
        const glm::u16vec4 j = rig.influences[v].joints;
        influences[v] = {glm::uvec4(uint32_t(j.x) | uint32_t(j.y) << 16, uint32_t(j.z) | uint32_t(j.w) << 16, 0u, 0u),
                         rig.influences[v].weights};
    }
    std::vector<float> deltas(rig.morphTargets.size() * count * DERMIS_MORPH_DELTA_FLOATS, 0.0f);
    for (size_t s = 0; s < rig.morphTargets.size(); ++s) {
        const MorphTarget& target = rig.morphTargets[s];
        const std::vector<glm::vec3>* attributes[3] = {&target.positions, &target.normals, &target.tangents};
        for (size_t a = 0; a < 3; ++a) {
            for (size_t v = 0; v < attributes[a]->size() && v < count; ++v)
                for (int c = 0; c < 3; ++c)
                    deltas[(s * count + v) * DERMIS_MORPH_DELTA_FLOATS + a * 3 + static_cast<size_t>(c)] = (*attributes[a])[v][c];
        }
    }
    gpu.source = uploadBuffer(source, owner + ": skinning bind pose");
    gpu.influences = uploadBuffer(influences, owner + ": skinning influences");
    gpu.morphDeltas = uploadBuffer(deltas, owner + ": morph deltas");
    gpu.palette = uploadBuffer(std::vector<glm::mat4>(rig.palette.size(), glm::mat4(1.0f)), owner + ": joint palette",
                               GL_DYNAMIC_STORAGE_BIT);
    gpu.morphWeights = uploadBuffer(std::vector<float>(rig.morphSlots.size(), 0.0f), owner + ": morph weights",
                                    GL_DYNAMIC_STORAGE_BIT);
    gpu.derivatives = uploadBuffer(std::vector<float>(count * DERMIS_SKIN_DERIVATIVE_FLOATS, 0.0f), owner + ": skinned dP/du, dP/dv");
    gpu.vertexCount = static_cast<GLsizei>(count);
    gpu.paletteEntries = static_cast<GLsizei>(rig.palette.size());
    gpu.morphSlots = static_cast<GLsizei>(rig.morphSlots.size());
    return gpu;
}

// The file's wrap modes on a texture of its maps (glTF 2.0 sampler.wrapS/T;
// the values are OpenGL's enums).
GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Repeat: return GL_REPEAT;
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

void applyWrap(const gl::Texture& texture, const TextureWraps& wrap) {
    if (!texture.isValid()) return;
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, glWrap(wrap.s));
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, glWrap(wrap.t));
}

void applyWrap(const GpuNormalMaps& maps, const TextureWraps& wrap) {
    for (const gl::Texture* texture : {&maps.normalMap, &maps.leanMap1, &maps.leanMap2}) applyWrap(*texture, wrap);
}

// Trilinear filtering and wrapping, as glTF samplers default to.
gl::Texture createMipmappedTexture(GLsizei levels, GLenum internalFormat, int width, int height, const std::string& label) {
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D, label);
    glTextureStorage2D(texture.get(), levels, internalFormat, width, height);
    glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return texture;
}

// Images are stored top row first; GL's first row is the bottom one, and glTF
// UVs have v = 0 at the top, so uploading top-first makes texture(uv) match
// glTF's convention directly. In bands of rows: the driver converts the
// floats to the texture's format through a temporary as large as what it is
// given (Mesa does), and a band's temporary is small.
constexpr int kUploadBandRows = 64;
void uploadLevel(const gl::Texture& texture, int level, const Image& image, int firstRow = 0) {
    for (int row = 0; row < image.height; row += kUploadBandRows) {
        const int rows = std::min(kUploadBandRows, image.height - row);
        glTextureSubImage2D(texture.get(), level, 0, firstRow + row, image.width, rows, GL_RGBA, GL_FLOAT,
                            &image.texels[static_cast<size_t>(row) * static_cast<size_t>(image.width)]);
    }
}

}  // namespace

Result<GpuMaterial> uploadMaterial(const ModelMaterial& material) {
    GpuMaterial gpu;
    gpu.name = material.name;
    gpu.baseColourFactor = material.baseColourFactor;
    gpu.roughnessFactor = material.roughnessFactor;
    gpu.scatter = material.profile.empty() ? -1.0f : material.scatter;
    gpu.thicknessMm = material.thicknessMm;
    const TextureWraps repeat;  // the scene's own grey maps
    const struct {
        const Image* image;
        gl::Texture* texture;
        const TextureWraps* wrap;
        const char* name;
    } maps[] = {{&material.albedoMap, &gpu.albedoMap, &material.albedoWrap, "albedo"},
                {&material.metallicRoughnessMap, &gpu.metallicRoughnessMap, &material.metallicRoughnessWrap, "metallic-roughness"},
                {&material.roughnessMap, &gpu.roughnessMap, &repeat, "roughness"},
                {&material.specularMap, &gpu.specularMap, &repeat, "specular"},
                {&material.scatterMap, &gpu.scatterMap, &material.scatterWrap, "scatter"},
                {&material.thicknessMap, &gpu.thicknessMap, &material.thicknessWrap, "thickness"}};
    const std::string owner = material.name.empty() ? "material (unnamed)" : "material '" + material.name + "'";
    for (const auto& map : maps) {
        if (map.image->empty()) continue;
        *map.texture = uploadImage(*map.image, owner + ": " + map.name + " map");
        applyWrap(*map.texture, *map.wrap);
    }
    // The normal map goes up with the LEAN maps baked from it.
    if (!material.normalMap.empty()) {
        auto normals = uploadNormalMaps(material.normalMap, owner);
        if (!normals.ok()) return normals.error();
        applyWrap(*normals, material.normalWrap);
        gpu.normalMap = std::move(normals->normalMap);
        gpu.leanMap1 = std::move(normals->leanMap1);
        gpu.leanMap2 = std::move(normals->leanMap2);
    }
    return gpu;
}

Result<GpuNormalMaps> uploadNormalMaps(const Image& normals, const std::string& owner) {
    GpuNormalMaps gpu;
    gpu.normalMap = uploadImage(normals, owner + ": normal map");
    const GLsizei levels = static_cast<GLsizei>(leanMipLevelCount(normals.width, normals.height));
    gpu.leanMap1 = createMipmappedTexture(levels, GL_RGBA16F, normals.width, normals.height,
                                          owner + ": LEAN map 1 (B, M.xx, M.yy)");
    gpu.leanMap2 = createMipmappedTexture(levels, GL_RG16F, normals.width, normals.height, owner + ": LEAN map 2 (M.xy)");
    // Each band and level goes to the GPU as it is made (lean/LeanBake.h).
    const Status baked = bakeLeanLevels(normals, 0.0f, [&](int level, int firstRow, const Image& lean1, const Image& lean2) {
        uploadLevel(gpu.leanMap1, level, lean1, firstRow);
        uploadLevel(gpu.leanMap2, level, lean2, firstRow);
    });
    if (!baked.ok()) return baked.error();
    return gpu;
}

void GpuSubmesh::draw() const {
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<uintptr_t>(firstIndex) * sizeof(uint32_t)));
}

const std::vector<GpuSubmesh>& GpuCharacter::submeshesAt(int lod) const {
    if (lod <= 0 || lods.empty()) return submeshes;
    return lods[size_t(std::min(lod, int(lods.size())) - 1)].submeshes;
}

const GpuNormalMaps* GpuCharacter::lodNormalMapsAt(int lod, size_t material) const {
    if (lod <= 0 || lods.empty()) return nullptr;
    const GpuLod& level = lods[size_t(std::min(lod, int(lods.size())) - 1)];
    if (!level.normalMaps || material >= level.normalMaps->size()) return nullptr;
    const GpuNormalMaps& maps = (*level.normalMaps)[material];
    return maps.normalMap.isValid() ? &maps : nullptr;
}

GpuSubmesh GpuCharacter::wholeMeshAt(int lod) const {
    if (lod <= 0 || lods.empty()) return {0, mesh.indexCount, 0};
    return lods[size_t(std::min(lod, int(lods.size())) - 1)].whole;
}

bool GpuCharacter::hasLeanMaps() const {
    return std::any_of(materials->begin(), materials->end(), [](const GpuMaterial& m) { return m.leanMap1.isValid(); });
}

gl::Texture uploadImage(const Image& image, const std::string& label) {
    const int levels = gl::fullMipLevelCount(uint32_t(image.width), uint32_t(image.height));
    // Colour as sRGB 8-bit. Data maps stay half floats even from an 8-bit
    // file: filtered as RGBA8, llvmpipe interpolates in 8-bit steps, and the
    // scan's texture-space irradiance error (SSS off on both sides, 320x180)
    // rose from 2.21% to 4.31% against the reference (docs/testing.md "Memory").
    const GLenum format = image.colourSpace == ColourSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA16F;
    gl::Texture texture = createMipmappedTexture(levels, format, image.width, image.height, label);
    uploadLevel(texture, 0, image);
    glGenerateTextureMipmap(texture.get());
    return texture;
}

Result<GpuScene> GpuScene::create(const Scene& scene) {
    auto models = loadSharedSceneModels(scene);
    if (!models.ok()) return models.error();
    return create(scene, *models);
}

Result<GpuScene> GpuScene::create(const Scene& scene, const std::vector<Model>& models) {
    return create(scene, shareModels(models));
}

namespace {

// What characters that share a model share on the GPU side, made once per model.
struct SharedUpload {
    std::shared_ptr<std::vector<GpuMaterial>> materials;
    std::vector<uint32_t> indices;  // the full mesh's, then each level's
    std::vector<GpuSubmesh> submeshes;
    std::vector<GpuLod> lods;
    bool closedOutward = false;
};

Result<SharedUpload> makeSharedUpload(const Model& model) {
    SharedUpload shared;
    shared.materials = std::make_shared<std::vector<GpuMaterial>>();
    for (const ModelMaterial& material : model.materials) {
        auto one = uploadMaterial(material);
        if (!one.ok()) return one.error();
        one->index = shared.materials->size();
        shared.materials->push_back(std::move(*one));
    }
    shared.indices = model.mesh.indices;
    for (const Submesh& submesh : model.drawRanges())
        shared.submeshes.push_back({static_cast<GLsizei>(submesh.firstIndex), static_cast<GLsizei>(submesh.indexCount),
                                    static_cast<size_t>(submesh.material)});
    for (const LodLevel& level : model.lods) {
        const auto first = static_cast<GLsizei>(shared.indices.size());
        GpuLod lod;
        lod.whole = {first, static_cast<GLsizei>(level.indices.size()), 0};
        for (const Submesh& range : level.ranges) {
            lod.submeshes.push_back({first + static_cast<GLsizei>(range.firstIndex), static_cast<GLsizei>(range.indexCount),
                                     static_cast<size_t>(range.material)});
        }
        shared.indices.insert(shared.indices.end(), level.indices.begin(), level.indices.end());
        lod.normalMaps = std::make_shared<std::vector<GpuNormalMaps>>();
        for (size_t m = 0; m < level.normalMaps.size(); ++m) {
            GpuNormalMaps maps;
            if (!level.normalMaps[m].empty()) {
                auto uploaded = uploadNormalMaps(level.normalMaps[m], "level " + std::to_string(shared.lods.size() + 1) +
                                                                          " of material " + std::to_string(m));
                if (!uploaded.ok()) return uploaded.error();
                maps = std::move(*uploaded);
                if (m < model.materials.size()) applyWrap(maps, model.materials[m].normalWrap);
            }
            lod.normalMaps->push_back(std::move(maps));
        }
        shared.lods.push_back(std::move(lod));
    }
    shared.closedOutward = isClosedOutward(model.mesh);
    return shared;
}

}  // namespace

Result<GpuScene> GpuScene::create(const Scene& scene, const SceneModels& models) {
    GpuScene gpuScene;
    std::map<const Model*, SharedUpload> uploads;
    for (size_t c = 0; c < scene.characters.size() && c < models.size(); ++c) {
        const Character& character = scene.characters[c];
        const Model& model = *models[c];
        auto found = uploads.find(&model);
        if (found == uploads.end()) {
            auto made = makeSharedUpload(model);
            if (!made.ok()) return makeError(character.name, made.error().what);
            found = uploads.emplace(&model, std::move(*made)).first;
        }
        const SharedUpload& shared = found->second;
        GpuCharacter gpu;
        gpu.name = character.name;
        // Its own buffers: the skinning pass writes an animated character's vertices.
        gpu.mesh = uploadMesh(model.mesh, shared.indices, model.colours, "character '" + character.name + "'");
        gpu.closedOutward = shared.closedOutward;
        gpu.rig = uploadRig(model.rig, model.mesh, "character '" + character.name + "'");
        gpu.materials = shared.materials;
        gpu.submeshes = shared.submeshes;
        gpu.lods = shared.lods;
        gpuScene.mCharacters.push_back(std::move(gpu));
    }
    return gpuScene;
}

}  // namespace dermis
