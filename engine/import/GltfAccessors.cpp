#include "import/GltfAccessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace dermis {

const char* gltfTypeName(int type) {
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

namespace {

// A sparse accessor without a bufferView names its element count alone; a hostile
// file must not make that an allocation of any size (the largest meshes Dermis draws
// have a few million vertices).
constexpr size_t kMaxSparseBaseElements = size_t(1) << 26;

// An unsigned 8-, 16- or 32-bit integer (an index).
uint32_t readUnsigned(const unsigned char* p, size_t size) {
    if (size == 1) return p[0];
    if (size == 2) {
        uint16_t short16;
        std::memcpy(&short16, p, sizeof short16);
        return short16;
    }
    uint32_t value;
    std::memcpy(&value, p, sizeof value);
    return value;
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

}  // namespace

Result<AccessorView> GltfAccessors::view(int index, const std::string& where) const {
    const std::string name = where + ": accessor " + std::to_string(index);
    if (index < 0 || static_cast<size_t>(index) >= mGltf.accessors.size())
        return fail(name + " is out of range (" + std::to_string(mGltf.accessors.size()) + " accessors)");
    const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
    int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
    int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    if (componentSize <= 0 || components <= 0) return fail(name + " has an invalid type or component type");
    AccessorView view;
    view.count = accessor.count;
    view.componentSize = static_cast<size_t>(componentSize);
    view.components = components;
    if (accessor.count == 0) return view;
    if (accessor.sparse.isSparse && accessor.bufferView < 0) {
        // Zeros with the sparse elements on top; bounded like a view would be.
        if (accessor.count > kMaxSparseBaseElements)
            return fail(name + " is sparse over " + std::to_string(accessor.count) + " elements, more than " +
                        std::to_string(kMaxSparseBaseElements));
        return view;
    }
    if (accessor.bufferView < 0 || static_cast<size_t>(accessor.bufferView) >= mGltf.bufferViews.size())
        return fail(name + " has no valid bufferView");
    Result<const unsigned char*> start = bufferViewStart(accessor.bufferView);
    if (!start) return start.error();
    const tinygltf::BufferView& bufferView = mGltf.bufferViews[static_cast<size_t>(accessor.bufferView)];
    const std::string viewName = "bufferView " + std::to_string(accessor.bufferView);
    const size_t elementSize = view.componentSize * static_cast<size_t>(components);
    view.stride = bufferView.byteStride == 0 ? elementSize : bufferView.byteStride;
    if (view.stride < elementSize)
        return fail(viewName + ": byteStride " + std::to_string(view.stride) + " is smaller than the " +
                    std::to_string(elementSize) + "-byte elements of accessor " + std::to_string(index));
    // Checked before anything is allocated: count is bounded by the view.
    if (bufferView.byteLength < elementSize || accessor.byteOffset > bufferView.byteLength - elementSize ||
        accessor.count - 1 > (bufferView.byteLength - elementSize - accessor.byteOffset) / view.stride)
        return fail(name + " (" + std::to_string(accessor.count) + " elements) runs past the end of " + viewName);
    view.data = *start + accessor.byteOffset;
    return view;
}

Result<const unsigned char*> GltfAccessors::bufferViewStart(int index) const {
    const tinygltf::BufferView& bufferView = mGltf.bufferViews[static_cast<size_t>(index)];
    const std::string viewName = "bufferView " + std::to_string(index);
    if (bufferView.buffer < 0 || static_cast<size_t>(bufferView.buffer) >= mGltf.buffers.size())
        return fail(viewName + ": buffer " + std::to_string(bufferView.buffer) + " is out of range");
    const std::vector<unsigned char>& buffer = mGltf.buffers[static_cast<size_t>(bufferView.buffer)].data;
    if (bufferView.byteOffset > buffer.size() || bufferView.byteLength > buffer.size() - bufferView.byteOffset)
        return fail(viewName + " (" + std::to_string(bufferView.byteLength) + " bytes at " +
                    std::to_string(bufferView.byteOffset) + ") is outside its buffer of " +
                    std::to_string(buffer.size()) + " bytes");
    return buffer.data() + bufferView.byteOffset;
}

Result<std::vector<float>> GltfAccessors::readFloats(int index, int type, const std::string& where) const {
    Result<AccessorView> view = this->view(index, where);
    if (!view) return view.error();
    const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
    const std::string name = where + ": accessor " + std::to_string(index);
    if (accessor.type != type)
        return fail(name + " is " + gltfTypeName(accessor.type) + ", expected " + gltfTypeName(type));
    std::vector<float> values(view->count * static_cast<size_t>(view->components));
    for (size_t i = 0; view->data && i < view->count; ++i) {
        for (int c = 0; c < view->components; ++c) {
            float value =
                decodeComponent(view->data + i * view->stride + static_cast<size_t>(c) * view->componentSize,
                                accessor.componentType, accessor.normalized);
            if (!std::isfinite(value)) return fail(name + " holds a value that is not finite");
            values[i * static_cast<size_t>(view->components) + static_cast<size_t>(c)] = value;
        }
    }
    if (accessor.sparse.isSparse) {
        if (Status status = applySparse(index, values, name); !status) return status.error();
    }
    return values;
}

Result<const unsigned char*> GltfAccessors::viewBytes(int index, size_t byteOffset, size_t bytes,
                                                      const std::string& name) const {
    if (index < 0 || static_cast<size_t>(index) >= mGltf.bufferViews.size())
        return fail(name + ": bufferView " + std::to_string(index) + " is out of range");
    Result<const unsigned char*> start = bufferViewStart(index);
    if (!start) return start.error();
    const tinygltf::BufferView& bufferView = mGltf.bufferViews[static_cast<size_t>(index)];
    if (byteOffset > bufferView.byteLength || bytes > bufferView.byteLength - byteOffset)
        return fail(name + " (" + std::to_string(bytes) + " bytes at " + std::to_string(byteOffset) +
                    ") runs past the end of bufferView " + std::to_string(index));
    return *start + byteOffset;
}

Status GltfAccessors::applySparse(int index, std::vector<float>& values, const std::string& name) const {
    const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
    const auto& sparse = accessor.sparse;
    const std::string sparseName = name + " sparse";
    if (sparse.count < 1 || static_cast<size_t>(sparse.count) > accessor.count)
        return fail(sparseName + " count " + std::to_string(sparse.count) + " is not in [1, " +
                    std::to_string(accessor.count) + "]");
    const size_t count = static_cast<size_t>(sparse.count);
    const int indexSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(sparse.indices.componentType));
    if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        return fail(sparseName + " indices must be unsigned 8-, 16- or 32-bit integers");
    const size_t components = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type)));
    const size_t componentSize =
        static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType)));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        return fail(sparseName + " has a negative byteOffset");
    Result<const unsigned char*> indices = viewBytes(sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                                                     count * size_t(indexSize), sparseName + " indices");
    if (!indices) return indices.error();
    Result<const unsigned char*> replacements = viewBytes(
        sparse.values.bufferView, size_t(sparse.values.byteOffset), count * components * componentSize, sparseName + " values");
    if (!replacements) return replacements.error();
    for (size_t i = 0; i < count; ++i) {
        const uint32_t element = readUnsigned(*indices + i * size_t(indexSize), size_t(indexSize));
        if (element >= accessor.count)
            return fail(sparseName + ": index " + std::to_string(element) + " at " + std::to_string(i) +
                        " is out of range for " + std::to_string(accessor.count) + " elements");
        for (size_t c = 0; c < components; ++c) {
            const float value = decodeComponent(*replacements + (i * components + c) * componentSize,
                                                accessor.componentType, accessor.normalized);
            if (!std::isfinite(value)) return fail(sparseName + " holds a value that is not finite");
            values[size_t(element) * components + c] = value;
        }
    }
    return success();
}

Result<std::vector<uint32_t>> GltfAccessors::readIndices(int index, size_t vertexCount, const std::string& where) const {
    Result<AccessorView> view = this->view(index, where);
    if (!view) return view.error();
    const tinygltf::Accessor& accessor = mGltf.accessors[static_cast<size_t>(index)];
    const std::string name = where + ": index accessor " + std::to_string(index);
    if (accessor.type != TINYGLTF_TYPE_SCALAR) return fail(name + " is not SCALAR");
    // Sparse indices are valid glTF, but no exporter writes them.
    if (accessor.sparse.isSparse) return fail(name + " is sparse, which is not supported for indices");
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        return fail(name + " must hold unsigned 8-, 16- or 32-bit integers");
    std::vector<uint32_t> indices(view->count);
    for (size_t i = 0; i < view->count; ++i) {
        const uint32_t value = readUnsigned(view->data + i * view->stride, view->componentSize);
        if (value >= vertexCount)
            return fail(name + ": index " + std::to_string(value) + " at " + std::to_string(i) +
                        " is out of range for " + std::to_string(vertexCount) + " vertices");
        indices[i] = value;
    }
    return indices;
}

}  // namespace dermis
