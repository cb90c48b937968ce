#pragma once
// Reading glTF accessors (glTF 2.0 §3.6.2) with every bound checked before a
// byte is read: the accessor, its buffer view and its buffer, the stride, and
// the component types each use allows. Errors name the file, the primitive
// or animation (`where`) and the accessor.

#include "core/Result.h"

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

struct AccessorView {
    const unsigned char* data = nullptr;  // null for a sparse accessor without a bufferView (zeros)
    size_t count = 0;
    size_t stride = 0;
    size_t componentSize = 0;
    int components = 0;
};


class GltfAccessors {
public:
    GltfAccessors(const tinygltf::Model& gltf, std::string path) : mGltf(gltf), mPath(std::move(path)) {}

    Error fail(const std::string& what) const { return makeError(mPath, what); }
    Result<AccessorView> view(int index, const std::string& where) const;
    // Every element as floats (normalised integers are scaled); `type` is a
    // TINYGLTF_TYPE_*; values that are not finite are refused. A sparse accessor
    // (glTF 2.0 §3.6.2.3) is its base (its bufferView, or zeros) with the listed
    // elements replaced.
    Result<std::vector<float>> readFloats(int index, int type, const std::string& where) const;
    // Triangle indices, each checked against the vertex count.
    Result<std::vector<uint32_t>> readIndices(int index, size_t vertexCount, const std::string& where) const;

private:
    // The first byte of bufferView `index` (in range), the view checked against its buffer.
    Result<const unsigned char*> bufferViewStart(int index) const;
    // `bytes` bytes at `byteOffset` into bufferView `index`, checked against the view and its buffer.
    Result<const unsigned char*> viewBytes(int index, size_t byteOffset, size_t bytes, const std::string& name) const;
    Status applySparse(int index, std::vector<float>& values, const std::string& name) const;

    const tinygltf::Model& mGltf;
    std::string mPath;
};

const char* gltfTypeName(int type);

}  // namespace dermis
