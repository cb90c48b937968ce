#include "import/GltfDraco.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <memory>
#include <vector>

namespace dermis {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// Appends `bytes` to `buffer` (4-byte aligned) as a new buffer view; returns its index.
int appendView(tinygltf::Model& gltf, int buffer, const void* bytes, size_t size) {
    std::vector<unsigned char>& data = gltf.buffers[size_t(buffer)].data;
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = buffer;
    view.byteOffset = data.size();
    view.byteLength = size;
    data.insert(data.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
    gltf.bufferViews.push_back(view);
    return int(gltf.bufferViews.size() - 1);
}

// Each point's value of `attribute` as `components` values of type T, appended to `buffer` as a
// new view (its index in *view); false if Draco cannot convert a value.
template <class T>
bool appendConverted(tinygltf::Model& gltf, int buffer, const draco::PointAttribute& attribute, size_t points,
                     int components, int* view) {
    std::vector<T> values(points * size_t(components));
    for (size_t p = 0; p < points; ++p) {
        if (!attribute.ConvertValue<T>(attribute.mapped_index(draco::PointIndex(uint32_t(p))), int8_t(components),
                                       &values[p * size_t(components)]))
            return false;
    }
    *view = appendView(gltf, buffer, values.data(), values.size() * sizeof(T));
    return true;
}

Status decodePrimitive(tinygltf::Model& gltf, tinygltf::Primitive& primitive, const tinygltf::Value& extension,
                       const std::string& where, const std::string& path) {
    auto fail = [&](const std::string& what) { return makeError(path, where + ": " + kExtension + " " + what); };
    if (!extension.IsObject() || !extension.Has("bufferView") || !extension.Get("bufferView").IsInt())
        return fail("has no bufferView");
    const int viewIndex = extension.Get("bufferView").Get<int>();
    if (viewIndex < 0 || size_t(viewIndex) >= gltf.bufferViews.size())
        return fail("bufferView " + std::to_string(viewIndex) + " is out of range");
    const tinygltf::BufferView& view = gltf.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= gltf.buffers.size()) return fail("bufferView's buffer is out of range");
    const std::vector<unsigned char>& source = gltf.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > source.size() || view.byteLength > source.size() - view.byteOffset)
        return fail("bufferView " + std::to_string(viewIndex) + " is outside its buffer");

    draco::DecoderBuffer compressed;
    compressed.Init(reinterpret_cast<const char*>(source.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&compressed);
    if (!decoded.ok()) return fail("data does not decode: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    const size_t points = mesh->num_points();

    // The decoded data lives in a new buffer of its own.
    gltf.buffers.emplace_back();
    const int buffer = int(gltf.buffers.size() - 1);

    if (!extension.Has("attributes") || !extension.Get("attributes").IsObject()) return fail("has no attributes");
    const tinygltf::Value& ids = extension.Get("attributes");
    for (auto& [name, accessorIndex] : primitive.attributes) {
        if (!ids.Has(name)) continue;  // not compressed: read from its own accessor as usual
        const tinygltf::Value& id = ids.Get(name);
        if (!id.IsInt()) return fail("attribute " + name + " has no integer id");
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(uint32_t(id.Get<int>()));
        if (!attribute) return fail("attribute " + name + " (id " + std::to_string(id.Get<int>()) + ") is not in the data");
        if (accessorIndex < 0 || size_t(accessorIndex) >= gltf.accessors.size())
            return fail("attribute " + name + ": accessor " + std::to_string(accessorIndex) + " is out of range");
        tinygltf::Accessor& accessor = gltf.accessors[size_t(accessorIndex)];
        const int components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
        if (components <= 0 || components > 16) return fail("attribute " + name + " has an invalid accessor type");
        // Integer attributes that are not normalised (JOINTS_n) keep their component type; the
        // rest become floats (ConvertValue scales normalised integers as glTF does).
        const bool keepUnsigned = !accessor.normalized && (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                           accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        bool converted = false;
        if (keepUnsigned) {
            converted = appendConverted<uint16_t>(gltf, buffer, *attribute, points, components, &accessor.bufferView);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            converted = appendConverted<float>(gltf, buffer, *attribute, points, components, &accessor.bufferView);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
            accessor.normalized = false;
        }
        if (!converted) return fail("attribute " + name + " does not convert to " + std::to_string(components) + " values");
        accessor.byteOffset = 0;
        accessor.count = points;
        accessor.sparse.isSparse = false;
    }

    std::vector<uint32_t> indices;
    indices.reserve(size_t(mesh->num_faces()) * 3);
    for (uint32_t f = 0; f < mesh->num_faces(); ++f) {
        const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
        for (int k = 0; k < 3; ++k) indices.push_back(face[k].value());
    }
    tinygltf::Accessor indexAccessor;
    indexAccessor.bufferView = appendView(gltf, buffer, indices.data(), indices.size() * sizeof(uint32_t));
    indexAccessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indexAccessor.type = TINYGLTF_TYPE_SCALAR;
    indexAccessor.count = indices.size();
    gltf.accessors.push_back(indexAccessor);
    primitive.indices = int(gltf.accessors.size() - 1);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    return success();
}

}  // namespace

bool detachDracoIndices(nlohmann::json& document) {
    bool changed = false;
    if (!document.is_object() || !document.contains("meshes") || !document["meshes"].is_array()) return false;
    for (nlohmann::json& mesh : document["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (nlohmann::json& primitive : mesh["primitives"]) {
            if (!primitive.is_object() || !primitive.contains("extensions") || !primitive["extensions"].is_object())
                continue;
            if (!primitive["extensions"].contains(kExtension) || !primitive.contains("indices")) continue;
            primitive.erase("indices");
            changed = true;
        }
    }
    return changed;
}

Status decodeDracoPrimitives(tinygltf::Model& gltf, const std::string& path) {
    for (size_t m = 0; m < gltf.meshes.size(); ++m) {
        for (size_t p = 0; p < gltf.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = gltf.meshes[m].primitives[p];
            const auto found = primitive.extensions.find(kExtension);
            if (found == primitive.extensions.end()) continue;
            const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            if (Status status = decodePrimitive(gltf, primitive, found->second, where, path); !status) return status;
        }
    }
    return success();
}

}  // namespace dermis
